// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LabelPyramid_h
#define labelmesher_LabelPyramid_h

/**
 * @file LabelPyramid.h
 * Which labels an octree leaf holds, in O(1): a min-max-style pyramid whose
 * level-l entry summarises the 2^l-voxel block of the image as "one label",
 * "two labels" or "more". Leaves of the octree are exactly such blocks, so the
 * refinement test "at most two materials per leaf" (section 3.1.1) and the
 * uniform-leaf shortcut never visit voxels. Level 1 (blocks of 2^d voxels)
 * is not stored but read from the voxels when asked: it would be seven
 * eighths of the pyramid's memory, 1 byte per voxel (1 GiB at 1024^3), for
 * 8 reads a query.
 */

#include "Support/LabelImage.h"

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace labelmesher
{

struct LabelSummary
{
  static constexpr std::int32_t Many = std::numeric_limits<std::int32_t>::min();
  std::int32_t First = 0;  ///< smallest label, or Many when there are more than two labels
  std::int32_t Second = 0; ///< largest label (== First for a uniform block)

  bool IsUniform() const { return First != Many && First == Second; }
  bool HasMoreThanTwo() const { return First == Many; }
};

class LabelPyramid
{
public:
  /// Builds levels 1..depth over `image`; voxels outside the image count as 0.
  LabelPyramid(const LabelImage& image, int depth);

  /// Summary of the block of 2^level voxels a side whose first voxel is
  /// (i, j, k) (a multiple of 2^level).
  LabelSummary Block(int level, int i, int j, int k) const;

private:
  /// Level 1, from the 2^d voxels of the block whose first voxel is (i, j, k).
  LabelSummary VoxelBlock(int i, int j, int k) const;

  const LabelImage& Image;
  std::vector<std::vector<LabelSummary>> Levels; // Levels[l] for l >= 1
  std::vector<std::array<int, 3>> LevelDimensions;
};

} // namespace labelmesher

#endif
