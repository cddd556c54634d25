// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BlockPlan_h
#define labelmesher_BlockPlan_h

/**
 * @file BlockPlan.h
 * Where things lie in the block-streamed pipeline (StreamedPipeline.h): the
 * octree's leaves in Morton order (p4est's: bits interleaved, x lowest) are
 * cut into blocks, runs of consecutive leaves, so that a block is a range of
 * Morton keys of voxels, [Start, End). A box of voxels meets only leaves whose
 * keys lie between the keys of its low and its high corner (the key grows
 * with every coordinate), which decides in O(1) whether a box lies in one
 * block or may cross into another.
 */

#include "Octree/LeafBox.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

/// Morton key of a voxel of the 2^depth octree (dimension 2: x and y only).
std::uint64_t VoxelKey(const std::array<int, 3>& voxel, int dimension, int depth);

/// A box of voxels [Low, High] (inclusive) and the Morton keys of its corners.
struct VoxelBox
{
  std::array<int, 3> Low{}, High{};
  std::uint64_t LowKey = 0, HighKey = 0;

  bool Meets(const LeafBox& leaf) const;
};

/// The voxels within `margin` (voxels) of the index-space box [lo, hi]: every
/// voxel whose closed cell comes that near, clipped to the 2^depth octree.
VoxelBox GrownVoxelBox(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double margin,
  int dimension, int depth);

/// A block's range of keys: [Start, End).
struct KeyRange
{
  std::uint64_t Start = 0, End = 0;
  /// Every voxel of `box` lies in the range (so every leaf the box meets is the block's).
  bool Holds(const VoxelBox& box) const { return Start <= box.LowKey && box.HighKey < End; }
  /// Some voxel of `box` may lie in the range.
  bool MayMeet(const VoxelBox& box) const { return box.LowKey < End && box.HighKey >= Start; }
};

/// The keys of leaves [first, last) of `leaves` (in Morton order): from the
/// key of leaf `first`'s first voxel to that of leaf `last` (or the end of the octree).
KeyRange LeafRunKeys(const std::vector<OctreeLeaf>& leaves, std::size_t first, std::size_t last, int dimension,
  int depth);

} // namespace labelmesher

#endif
