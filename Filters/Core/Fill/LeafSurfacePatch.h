// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LeafSurfacePatch_h
#define labelmesher_LeafSurfacePatch_h

/**
 * @file LeafSurfacePatch.h
 * The surface patch S_L of a proper boundary leaf (section 3.1.1, "Waterproof
 * surface mesh"): intersection vertices at the midpoints of leaf edges whose
 * ends carry different labels, one intersection edge per crossed face, and the
 * cone from the leaf centre over the resulting intersection polygon, as the
 * convex pieces the fidelity test measures (Criteria/LeafFidelity.h). The
 * cells that realise it are made by the fill (LeafFill.h, FaceTriangulation.h).
 *
 * Coordinates are index-space (voxel centres at integers).
 */

#include "Criteria/DistanceBound.h"
#include "Octree/LatticeLabels.h"
#include "Octree/LeafBox.h"

#include <vector>

namespace labelmesher
{

/// The cone patch: triangles (3D) or segments (2D) from the leaf centre to the
/// intersection polygon through 0-corners and the midpoints of edges with ends
/// of different labels; empty unless that polygon is one simple closed loop
/// through every 0-corner (3D) or one pair of points (2D).
std::vector<ConvexPiece> ConeSurfacePatch(const LeafBox& leaf, const CornerSigns& signs);

} // namespace labelmesher

#endif
