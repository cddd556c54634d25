// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LeafFidelity_h
#define labelmesher_LeafFidelity_h

/**
 * @file LeafFidelity.h
 * The geometric acceptance test of a proper boundary leaf (section 3.1.1,
 * "Two-sided Hausdorff distance"): its surface patch S_L (Fill/LeafSurfacePatch.h)
 * against the image boundary B_L in the closed leaf, both one-sided bounds,
 * evaluated exactly by branch and bound (DistanceBound.h) instead of through
 * the dissertation's EDT fidelity zone, which samples distances at voxel
 * centres and can admit a patch up to sqrt(3)/2 voxel beyond h(M, I).
 *
 * Coordinates are index-space (voxel centres at integers).
 */

#include "Criteria/DistanceBound.h"
#include "Octree/LeafBox.h"
#include "Support/LabelImage.h"

#include <cstdint>
#include <vector>

namespace labelmesher
{

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
