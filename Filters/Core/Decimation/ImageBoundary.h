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
 *
 * Of a slab of the image (LabelImage::Slab) it holds the faces whose two
 * voxels the slab holds (the outside counts as held), in the whole image's
 * order, and finds them as on the whole image in the slab's interior: a query
 * that reaches the slab's edge (SlabMargin) throws std::logic_error.
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

  /// How many slices a slab must hold beyond the cells a process meshes, on
  /// either side, so that every query within `distance` voxels of those cells
  /// (a fidelity test, a certificate, a face's neighbourhood) reads only faces
  /// of the slab's interior.
  static int SlabMargin(double distance);

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
  // Of a slab, only its bins along the last axis are stored, from FirstBin;
  // those in [WholeBins[0], WholeBins[1]] hold every face they would hold on
  // the whole image.
  static constexpr int Bin = 4;
  std::array<int, 3> Size{ 0, 0, 0 }; ///< the image's voxels per axis
  std::array<int, 3> Bins{ 1, 1, 1 };
  int FirstBin = 0, StoredBins = 1;
  std::array<int, 2> WholeBins{ 0, 0 };
  std::vector<std::uint32_t> BinStart; // CSR over FaceOrder
  std::vector<std::uint32_t> FaceOrder;
  int BinOf(double coordinate, int axis) const;
};

} // namespace labelmesher

#endif
