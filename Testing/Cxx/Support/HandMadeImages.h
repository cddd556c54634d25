// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_HandMadeImages_h
#define labelmesher_testing_HandMadeImages_h

/**
 * @file HandMadeImages.h
 * Small label images written out in a test: a 2D picture drawn as text, and
 * images given by a label function of the voxel index. Header only.
 */

#include "Support/LabelImage.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

/// A 2D image drawn as text: rows[0] is the top row (largest j), '.' is label
/// 0, a digit is that label. All rows must have the same length.
inline LabelImage Picture(const std::vector<std::string>& rows)
{
  const int ny = static_cast<int>(rows.size()), nx = static_cast<int>(rows[0].size());
  LabelImage image(nx, ny, 1);
  for (int j = 0; j < ny; ++j)
  {
    const std::string& row = rows[ny - 1 - j];
    for (int i = 0; i < nx && i < static_cast<int>(row.size()); ++i)
      image(i, j, 0) = row[i] == '.' ? 0 : row[i] - '0';
  }
  return image;
}

/// An n^3 image with label(i, j, k) at voxel (i, j, k).
inline LabelImage Volume(int n, const std::function<std::int32_t(int, int, int)>& label)
{
  LabelImage image(n, n, n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        image(i, j, k) = label(i, j, k);
  return image;
}

/// An n^3 image of label 1 at k >= planeK and 0 below, except the one voxel
/// (i, j, k), which has `label`: a plane with a dent, a bump or a lone voxel.
inline LabelImage PlaneWithOneVoxel(int n, int planeK, int vi, int vj, int vk, std::int32_t label)
{
  return Volume(n, [=](int i, int j, int k) { return i == vi && j == vj && k == vk ? label : (k >= planeK ? 1 : 0); });
}

/// An nx x ny 2D image with label(i, j) at pixel (i, j).
inline LabelImage Plane(int nx, int ny, const std::function<std::int32_t(int, int)>& label)
{
  LabelImage image(nx, ny, 1);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      image(i, j, 0) = label(i, j);
  return image;
}

} // namespace testing
} // namespace labelmesher

#endif
