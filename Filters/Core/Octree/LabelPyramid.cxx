// SPDX-License-Identifier: GPL-2.0-or-later
// Builds the pyramid that tells in O(1) which labels an octree leaf holds.
#include "Octree/LabelPyramid.h"

#include <algorithm>

namespace labelmesher
{
namespace
{
LabelSummary Merge(LabelSummary s, std::int32_t label)
{
  if (s.HasMoreThanTwo() || label == s.First || label == s.Second)
    return s;
  if (s.First == s.Second)
  {
    s.First = std::min(s.First, label);
    s.Second = std::max(s.Second, label);
    return s;
  }
  return { LabelSummary::Many, LabelSummary::Many };
}

LabelSummary Merge(LabelSummary a, const LabelSummary& b)
{
  if (a.HasMoreThanTwo() || b.HasMoreThanTwo())
    return { LabelSummary::Many, LabelSummary::Many };
  return Merge(Merge(a, b.First), b.Second);
}
} // namespace

LabelPyramid::LabelPyramid(const LabelImage& image, int depth)
  : Image(image)
{
  Levels.resize(depth + 1);
  LevelDimensions.resize(depth + 1);
  LevelDimensions[0] = image.Dimensions;
  const bool flat = image.Dimension() == 2;
  for (int level = 1; level <= depth; ++level)
  {
    const auto& below = LevelDimensions[level - 1];
    std::array<int, 3> dims{ (below[0] + 1) / 2, (below[1] + 1) / 2, flat ? 1 : (below[2] + 1) / 2 };
    LevelDimensions[level] = dims;
    if (level == 1)
      continue; // summarised from the voxels when asked (VoxelBlock)
    std::vector<LabelSummary>& out = Levels[level];
    out.resize(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]);
    const int kMax = flat ? 1 : 2;
    for (int k = 0; k < dims[2]; ++k)
      for (int j = 0; j < dims[1]; ++j)
        for (int i = 0; i < dims[0]; ++i)
        {
          bool first = true;
          LabelSummary s;
          for (int dk = 0; dk < kMax; ++dk)
            for (int dj = 0; dj < 2; ++dj)
              for (int di = 0; di < 2; ++di)
              {
                const int ci = 2 * i + di, cj = 2 * j + dj, ck = flat ? 0 : 2 * k + dk;
                LabelSummary child;
                if (ci >= below[0] || cj >= below[1] || ck >= below[2])
                  child = { 0, 0 };
                else if (level == 2)
                  child = VoxelBlock(2 * ci, 2 * cj, 2 * ck);
                else
                  child = Levels[level - 1][(static_cast<std::size_t>(ck) * below[1] + cj) * below[0] + ci];
                s = first ? child : Merge(s, child);
                first = false;
              }
          out[(static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i] = s;
        }
  }
}

LabelSummary LabelPyramid::VoxelBlock(int i, int j, int k) const
{
  const int kMax = Image.Dimension() == 2 ? 1 : 2;
  const std::int32_t l = Image.At(i, j, k);
  LabelSummary s{ l, l };
  for (int dk = 0; dk < kMax; ++dk)
    for (int dj = 0; dj < 2; ++dj)
      for (int di = 0; di < 2; ++di)
        s = Merge(s, Image.At(i + di, j + dj, k + dk));
  return s;
}

LabelSummary LabelPyramid::Block(int level, int i, int j, int k) const
{
  if (level == 0)
  {
    const std::int32_t l = Image.At(i, j, k);
    return { l, l };
  }
  if (level == 1 && level < static_cast<int>(Levels.size()))
    return VoxelBlock(i, j, Image.Dimension() == 2 ? 0 : k);
  if (level >= static_cast<int>(Levels.size()))
    return { LabelSummary::Many, LabelSummary::Many };
  const auto& dims = LevelDimensions[level];
  const int bi = i >> level, bj = j >> level, bk = Image.Dimension() == 2 ? 0 : k >> level;
  if (bi >= dims[0] || bj >= dims[1] || bk >= dims[2])
    return { 0, 0 }; // wholly outside the image: background
  return Levels[level][(static_cast<std::size_t>(bk) * dims[1] + bj) * dims[0] + bi];
}

} // namespace labelmesher
