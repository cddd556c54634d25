// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ImageBoundary_h
#define labelmesher_ImageBoundary_h

/**
 * @file ImageBoundary.h
 * The image boundary B of section 2.1 as a list of voxel faces (pixel edges in
 * 2D) between different labels, outside the image counting as 0, with the
 * labels on either side and a uniform grid to find those near a box. The
 * decimator's fidelity check measures merged faces against the faces of their
 * own pair, and keeps every face (per side) near the mesh.
 */

#include "Criteria/DistanceBound.h"
#include "Support/LabelImage.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

/// The axis-aligned box of `piece`, grown by `margin` on every side.
void BoxAround(const ConvexPiece& piece, double margin, Point3& lo, Point3& hi);

class ImageBoundary
{
public:
  explicit ImageBoundary(const LabelImage& image);

  /// The face between voxel Voxel and its neighbour one step along Axis;
  /// Low < High are the labels on its two sides.
  struct Face
  {
    std::array<std::int32_t, 3> Voxel;
    std::int32_t Axis;
    std::int32_t Low, High;
  };
  const std::vector<Face>& Faces() const { return FaceList; }
  /// Index-space geometry: a unit square (3D) or segment (2D).
  ConvexPiece Piece(std::size_t face) const;

  /// Appends the pieces of the faces between labels low < high that meet the
  /// index-space box [lo, hi].
  void Pieces(const Point3& lo, const Point3& hi, std::int32_t low, std::int32_t high,
    std::vector<ConvexPiece>& out) const;

private:
  int Dimension;
  std::vector<Face> FaceList;
  // Uniform grid of Bin^d voxels over [-1, n] per axis; faces by their centre.
  static constexpr int Bin = 4;
  std::array<int, 3> Bins{ 1, 1, 1 };
  std::vector<std::uint32_t> BinStart; // CSR over FaceOrder
  std::vector<std::uint32_t> FaceOrder;
  int BinOf(double coordinate, int axis) const;
};

} // namespace labelmesher

#endif
