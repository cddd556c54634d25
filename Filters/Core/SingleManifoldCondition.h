// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_SingleManifoldCondition_h
#define labelmesher_SingleManifoldCondition_h

/**
 * @file SingleManifoldCondition.h
 * The topological acceptance test of a proper boundary leaf (a leaf holding
 * exactly two labels): the single manifold condition of section 2.4, made
 * strong enough that the leaf's cone patch (section 3.1.1) is provably
 * homeomorphic to the image boundary inside it, cell by cell:
 *
 *  - every face of the leaf is *clean*: no image-boundary voxel face lies on
 *    the leaf's boundary (each voxel on a face has the label of its mirror
 *    voxel across it), so the image boundary meets the leaf's faces
 *    transversally and both leaves sharing a face see the same labels on it;
 *  - along every leaf edge the labels change at most once (this excludes the
 *    multiple crossings of Figure 9a);
 *  - on every face, the two labels form one simple arc across the face (or the
 *    face is uniform: this excludes the island of Figure 9b and the saddle);
 *  - inside the leaf, the voxel faces between the two labels form one
 *    topological disk: a 2-manifold with boundary (both labels face-connected
 *    around every voxel vertex, which excludes pinched edges and vertices),
 *    connected, with Euler characteristic 1. In 2D: one simple path.
 *
 * A leaf that fails is split; single voxels are uniform, so refinement ends.
 */

#include "LabelImage.h"
#include "LeafBox.h"

namespace labelmesher
{

bool SatisfiesSingleManifoldCondition(
  const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second);

} // namespace labelmesher

#endif
