// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LabelImage_h
#define labelmesher_LabelImage_h

/**
 * @file LabelImage.h
 * The label image as the mesher sees it: a dense grid of integer labels in
 * *index space*, with no VTK or ITK types.
 *
 * Geometry convention (VTK's): voxel (i, j, k) is centred at (i, j, k); its faces
 * lie at half-integer positions. The image boundary B (dissertation section 2.1)
 * is the union of voxel faces shared by voxels of different labels, including
 * faces between a foreground voxel and the outside of the image (the outside is
 * background, label 0). A 2D image has dims[2] == 1 and lives in the plane z = 0.
 *
 * Physical placement (origin, spacing, direction) is applied by the VTK adapter.
 */

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

struct LabelImage
{
  std::array<int, 3> Dimensions{ 0, 0, 0 }; ///< voxels along x, y, z (z == 1 in 2D)
  std::vector<std::int32_t> Labels;         ///< x fastest; 0 = background; never negative

  LabelImage() = default;
  LabelImage(int nx, int ny, int nz)
    : Dimensions{ nx, ny, nz }
    , Labels(static_cast<std::size_t>(nx) * ny * nz, 0)
  {
  }

  int Dimension() const { return Dimensions[2] == 1 ? 2 : 3; }
  std::size_t NumberOfVoxels() const { return Labels.size(); }
  bool Contains(int i, int j, int k) const
  {
    return i >= 0 && j >= 0 && k >= 0 && i < Dimensions[0] && j < Dimensions[1] &&
      k < Dimensions[2];
  }
  std::size_t Index(int i, int j, int k) const
  {
    return (static_cast<std::size_t>(k) * Dimensions[1] + j) * Dimensions[0] + i;
  }
  /// Label of voxel (i, j, k); voxels outside the image are background (0).
  std::int32_t At(int i, int j, int k) const { return Contains(i, j, k) ? Labels[Index(i, j, k)] : 0; }
  std::int32_t& operator()(int i, int j, int k) { return Labels[Index(i, j, k)]; }
};

} // namespace labelmesher

#endif
