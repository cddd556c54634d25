// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_FidelityCheck_h
#define labelmesher_FidelityCheck_h

/**
 * @file FidelityCheck.h
 * Requirement 2 of section 3.1.3, both one-sided distances, exactly (never by
 * sampling voxel centres):
 *
 *  - h(M, I): every interface face a merge creates lies within h2 of the
 *    image boundary between its own two labels (the outside of the image and
 *    of the box counting as 0): DistanceBound's branch and bound against the
 *    image faces of that pair near it. Faces the merge does not move were
 *    within the bound before and are unchanged.
 *  - h(I, M): every image face stays within h1 of the mesh boundary of each
 *    of its labels (ImageBoundaryAnchors).
 *
 * Per-pair h(M, I) and per-side h(I, M) imply the per-material and overall
 * bounds the checks measure.
 */

#include "Decimation/ImageBoundaryAnchors.h"

#include <vector>

namespace labelmesher
{

class FidelityCheck
{
public:
  FidelityCheck(const ImageBoundary& boundary, const ImageBoundaryAnchors& anchors, double meshToImage);

  /// Both distances hold after the merge; Updates then holds the new h(I, M)
  /// certificates to commit with it.
  bool Accepts(const EditableMesh& mesh, const EdgeCollapse& merge);
  /// Every face of `faces` is within h2 of its pair's image boundary (used
  /// on the input mesh too).
  bool FaceWithinBound(const EditableMesh& mesh, const InterfaceFace& face);

  std::vector<ImageBoundaryAnchors::Update> Updates;

private:
  const ImageBoundary& Boundary;
  const ImageBoundaryAnchors& Anchors;
  double H;
  std::vector<ConvexPiece> Pieces;
};

/// The labels an interface face separates as the image sees them: the box's
/// outside and the background are both 0. Returns false when both are 0.
bool ImagePair(const InterfaceFace& face, std::int32_t& low, std::int32_t& high);

} // namespace labelmesher

#endif
