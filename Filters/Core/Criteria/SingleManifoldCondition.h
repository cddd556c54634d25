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
 *  - labels are read at lattice points (LatticeLabels.h: 0 where the image
 *    boundary passes), the same from both leaves of a face;
 *  - every 0-corner of the leaf (a vertex of the intersection polygon) lies
 *    on the interface between the leaf's two labels: both are among the
 *    voxels around it (a corner of a third label's boundary would join two
 *    regions of a label there);
 *  - along every leaf edge the image boundary is empty, or one run of points
 *    between or at the ends (this excludes the multiple crossings of
 *    Figure 9a);
 *  - every face is not crossed (one label, its boundary points only at its
 *    0-corners and the edge runs hanging from them), or crossed once: no
 *    saddle, no two adjacent 0-corners, the boundary points one connected set
 *    between one 4-connected set of each label (this excludes the island of
 *    Figure 9b);
 *  - boundary points on an edge or face are connected only through lattice
 *    segments that lie in the image boundary themselves: neighbouring
 *    0-points can belong to separate pieces of the boundary (one of them
 *    touching the leaf from outside), and then the leaf holds two pieces;
 *  - the interface between the leaf's two labels in the closed leaf (inside
 *    it and on its faces) is one connected piece: a piece on a face, cut off
 *    from the rest by a third label, would be joined to it by the patch;
 *  - inside the leaf, the voxel faces between the two labels form one
 *    topological disk: a 2-manifold with boundary (both labels face-connected
 *    around every voxel vertex, which excludes pinched edges and vertices),
 *    connected, with Euler characteristic 1. In 2D: one simple path.
 *
 * A leaf that fails is split; single voxels are uniform, so refinement ends.
 */

#include "Support/LabelImage.h"
#include "Octree/LeafBox.h"

namespace labelmesher
{

bool SatisfiesSingleManifoldCondition(
  const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second);

} // namespace labelmesher

#endif
