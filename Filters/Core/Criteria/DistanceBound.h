// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_DistanceBound_h
#define labelmesher_DistanceBound_h

/**
 * @file DistanceBound.h
 * A rigorous test of one side of a Hausdorff bound: is every point of a convex
 * element (segment, triangle, square) within distance h of a union of convex
 * pieces? Used by the mesher's fidelity test (section 3.1.1, "Two-sided
 * Hausdorff distance") on the leaf's surface patch against the image boundary
 * inside the leaf, and the other way round.
 *
 * The distance to the union is 1-Lipschitz, and the distance to one convex
 * piece is convex, so its maximum over the element is at a vertex. Hence:
 * some vertex farther than h disproves; one piece within h of every vertex
 * proves; otherwise the element is subdivided. Elements lying in an
 * axis-aligned plane (line) that coplanar pieces cover exactly are at distance
 * 0 (the case h = 0 needs this). What cannot be decided within the subdivision
 * depth counts as a violation: the answer errs only towards refining.
 *
 * Kept apart on purpose from the Hausdorff measure of the checks
 * (Checks/MeshChecks.h), which re-measures the finished mesh: neither calls
 * the other and they share only the point distances of Support/Geometry.h,
 * so that a bug in one cannot hide in the other.
 */

#include "Mesh/SimplexMesh.h"

#include <vector>

namespace labelmesher
{

struct ConvexPiece
{
  int Count = 0; ///< 2: segment, 3: triangle, 4: parallelogram (points in order)
  Point3 Points[4];
};

bool WithinDistance(const ConvexPiece& element, const std::vector<ConvexPiece>& pieces, double h, int maxDepth = 8);

} // namespace labelmesher

#endif
