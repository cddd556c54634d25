// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CurveFidelity_h
#define labelmesher_CurveFidelity_h

/**
 * @file CurveFidelity.h
 * The curver's own test of the two distance bounds and of crossings on the curves (the
 * linear mesh's bounds of section 3.1.1, kept by the curved mesh), and the
 * shortening of the pieces that break them.
 *
 * Every curved piece is replaced by its polyline within `Tolerance` voxels
 * (CurvePieces.h: the curve and the polyline are within that distance of each
 * other both ways), so a bound h holds on the curve when h − Tolerance holds
 * on the polyline, which Criteria/DistanceBound.h decides exactly:
 * - mesh to image: every polyline segment of a piece within h(M, I) − ε of the
 *   image boundary of each non-zero material on its sides;
 * - image to mesh: every pixel edge of material m's image boundary within
 *   h(I, M) of m's straight boundary edges, or within h(I, M) − ε of them and
 *   the polylines together. Pixel edges with only straight edges within reach
 *   are the linear mesh's, which the decimator already certified, and are
 *   skipped.
 * - crossings: a piece that may meet another boundary curve away from a
 *   shared vertex fails (CurveCrossings.h proves the others apart). On a mesh
 *   without background cells, curves facing each other across a gap can meet;
 *   where cells fill the box, valid cells cannot overlap.
 * Pieces that fail are shortened (scale halved, then straight) and the test
 * repeated; straight pieces are the linear mesh's, so the loop ends.
 * Everything is measured in index space: distances are in voxels.
 */

#include "Curving/CurvePieces.h"
#include "Curving/ImageOnMesh.h"

#include <cstddef>
#include <vector>

namespace labelmesher
{

struct CurveBounds
{
  double ImageToMesh = 0.0; ///< h(I, M) the curves must keep, voxels
  double MeshToImage = 0.0; ///< h(M, I), voxels
  double Tolerance = 1.0 / 256.0; ///< polyline-to-curve distance ε, voxels
};

struct FidelityOutcome
{
  std::size_t Rounds = 0;          ///< test rounds run
  std::size_t ShortenedPieces = 0; ///< distinct pieces shortened at least once
  /// Pieces still failing when they could not be shortened further (straight
  /// pieces the test cannot certify; expected 0).
  std::size_t Uncertified = 0;
};

/// Shortens `pieces` (of `linear`'s interface edges) until the bounds hold on
/// their curves. `linear` is the mesh in mesh coordinates with Materials.
FidelityOutcome KeepDistanceBounds(const SimplexMesh& linear, std::vector<CurvePiece>& pieces,
  const ImageOnMesh& image, const CurveBounds& bounds);

} // namespace labelmesher

#endif
