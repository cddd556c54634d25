// SPDX-License-Identifier: GPL-2.0-or-later
// Requirement 2 of section 3.1.3: both one-sided distances of a merge, decided exactly.
#include "Decimation/FidelityCheck.h"

#include <algorithm>

namespace labelmesher
{

bool ImagePair(const InterfaceFace& face, std::int32_t& low, std::int32_t& high)
{
  const std::int32_t a = std::max(face.Low, 0), b = std::max(face.High, 0);
  low = std::min(a, b);
  high = std::max(a, b);
  return low != high;
}

FidelityCheck::FidelityCheck(const ImageBoundary& boundary, const ImageBoundaryAnchors& anchors, double meshToImage)
  : Boundary(boundary)
  , Anchors(anchors)
  , H(meshToImage)
{
}

bool FidelityCheck::FaceWithinBound(const EditableMesh& mesh, const InterfaceFace& face)
{
  std::int32_t low, high;
  if (!ImagePair(face, low, high))
    return true; // background against the box: not part of any material's boundary
  const ConvexPiece piece = MeshFacePiece(mesh, face.Vertices);
  Point3 lo, hi;
  BoxAround(piece, H + 1e-6, lo, hi);
  Pieces.clear();
  Boundary.Pieces(lo, hi, low, high, Pieces);
  return WithinDistance(piece, Pieces, H);
}

bool FidelityCheck::Accepts(const EditableMesh& mesh, const EdgeCollapse& merge)
{
  // Faces after the merge that did not exist before are the moved ones.
  for (const InterfaceFace& face : merge.After)
  {
    const bool existed = std::binary_search(merge.Before.begin(), merge.Before.end(), face);
    if (!existed && !FaceWithinBound(mesh, face))
      return false;
  }
  return Anchors.Recertify(mesh, merge, Updates);
}

} // namespace labelmesher
