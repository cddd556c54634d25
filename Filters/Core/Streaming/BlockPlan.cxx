// SPDX-License-Identifier: GPL-2.0-or-later
// Morton keys of voxels, boxes and runs of leaves: which block a box lies in.
#include "Streaming/BlockPlan.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{

std::uint64_t VoxelKey(const std::array<int, 3>& voxel, int dimension, int depth)
{
  std::uint64_t key = 0;
  for (int bit = depth - 1; bit >= 0; --bit)
    for (int a = dimension - 1; a >= 0; --a)
      key = (key << 1) | ((static_cast<std::uint64_t>(voxel[a]) >> bit) & 1u);
  return key;
}

bool VoxelBox::Meets(const LeafBox& leaf) const
{
  for (int a = 0; a < leaf.Dimension; ++a)
    if (leaf.Origin[a] > High[a] || leaf.Origin[a] + leaf.Size - 1 < Low[a])
      return false;
  return true;
}

VoxelBox GrownVoxelBox(const std::array<double, 3>& lo, const std::array<double, 3>& hi, double margin,
  int dimension, int depth)
{
  // Voxel v covers [v - 1/2, v + 1/2]: it comes within the margin of the box
  // when v - 1/2 <= hi + margin and v + 1/2 >= lo - margin.
  VoxelBox box;
  const int last = (1 << depth) - 1;
  for (int a = 0; a < dimension; ++a)
  {
    box.Low[a] = std::clamp(static_cast<int>(std::ceil(lo[a] - margin - 0.5)), 0, last);
    box.High[a] = std::clamp(static_cast<int>(std::floor(hi[a] + margin + 0.5)), 0, last);
  }
  box.LowKey = VoxelKey(box.Low, dimension, depth);
  box.HighKey = VoxelKey(box.High, dimension, depth);
  return box;
}

KeyRange LeafRunKeys(const std::vector<OctreeLeaf>& leaves, std::size_t first, std::size_t last, int dimension,
  int depth)
{
  KeyRange range;
  range.Start = VoxelKey(leaves[first].Box.Origin, dimension, depth);
  range.End = last < leaves.size() ? VoxelKey(leaves[last].Box.Origin, dimension, depth)
                                   : std::uint64_t(1) << (dimension * depth);
  return range;
}

} // namespace labelmesher
