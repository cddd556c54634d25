// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LeafSurfacePatch_h
#define labelmesher_LeafSurfacePatch_h

/**
 * @file LeafSurfacePatch.h
 * The surface patch S_L of a proper boundary leaf (section 3.1.1, "Waterproof
 * surface mesh"): intersection vertices at the midpoints of leaf edges whose
 * ends carry different labels, one intersection edge per crossed face, and the
 * cone from the leaf centre over the resulting intersection polygon. Also the
 * image boundary B_L inside the leaf, and the fidelity test that compares them
 * (both one-sided Hausdorff bounds, evaluated exactly; see DistanceBound.h).
 *
 * Coordinates are index-space (voxel centres at integers).
 */

#include "Criteria/DistanceBound.h"
#include "Support/LabelImage.h"
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

/// The image boundary in the closed leaf: voxel faces (pixel edges in 2D)
/// between different labels inside it and on its boundary.
struct LeafImageBoundary
{
  std::vector<ConvexPiece> All;
  /// Those between the leaf's two labels: the part of the image boundary that
  /// the patch stands for.
  std::vector<ConvexPiece> Interface;
};
LeafImageBoundary ImageBoundaryInLeaf(const LabelImage& image, const LeafBox& leaf, std::int32_t first,
  std::int32_t second);

/// h(B_L, S_L) <= imageToMesh, with B_L every boundary face in the closed
/// leaf, and h(S_L, I_L) <= meshToImage, with I_L only the faces between the
/// leaf's two labels. The patch bounds both materials, so it must lie near
/// their common interface: near a third label's boundary (on the leaf's
/// faces) is not enough for the per-material bound.
bool SatisfiesFidelity(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second,
  double imageToMesh, double meshToImage);

} // namespace labelmesher

#endif
