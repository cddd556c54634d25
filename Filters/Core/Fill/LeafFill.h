// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LeafFill_h
#define labelmesher_LeafFill_h

/**
 * @file LeafFill.h
 * Filling one octree leaf with tetrahedra (triangles in 2D): Algorithm 3.
 *
 * - A uniform leaf with no extra point on its boundary takes the six-tetrahedra
 *   split around its main diagonal (two triangles in 2D).
 * - Any other leaf is coned from its centre over its triangulated faces
 *   (FaceTriangulation.h): in a proper boundary leaf the cone over the
 *   intersection polygon is the surface patch S_L, and every tetrahedron takes
 *   the label of its face triangle's side; in a uniform leaf all take the
 *   leaf's label. Materials therefore need no flood fill: each cell knows the
 *   side of the surface it lies on when it is made.
 */

#include "Support/LabelImage.h"
#include "Octree/LeafBox.h"
#include "Fill/MeshAssembler.h"

namespace labelmesher
{

void FillLeaf(const LabelImage& image, const OctreeLeaf& leaf, MeshAssembler& mesh);

} // namespace labelmesher

#endif
