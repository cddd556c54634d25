// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LeafFaces_h
#define labelmesher_LeafFaces_h

/**
 * @file LeafFaces.h
 * The voxel faces (pixel edges in 2D) of a closed leaf that separate two
 * different labels: those between two of its voxels and those on its
 * boundary, between one of its voxels and an outside one. The fidelity test
 * measures them and the single manifold condition checks that those between
 * the leaf's two labels form one piece; both walk them here.
 */

#include "Support/LabelImage.h"
#include "Octree/LeafBox.h"

#include <array>
#include <cstdint>

namespace labelmesher
{

/// Calls visit(voxel, axis, step, here, there) once per face of the closed
/// leaf between different labels: `voxel` (leaf-relative) is the leaf's voxel
/// on one side, labelled `here`; its neighbour voxel + step along `axis`
/// (step = +1, or -1 on the leaf's low side) is labelled `there`.
template <typename Visit>
void ForEachBoundaryFaceInLeaf(const LabelImage& image, const LeafBox& leaf, Visit&& visit)
{
  const int s = leaf.Size, depth = leaf.Dimension == 2 ? 1 : s;
  for (int k = 0; k < depth; ++k)
    for (int j = 0; j < s; ++j)
      for (int i = 0; i < s; ++i)
      {
        const std::array<int, 3> local{ i, j, k };
        const int x = leaf.Origin[0] + i, y = leaf.Origin[1] + j, z = leaf.Origin[2] + k;
        const std::int32_t here = image.At(x, y, z);
        // The face at +1/2 along `axis`, and at -1/2 on the leaf's low side:
        // each face of the closed leaf once.
        for (int axis = 0; axis < leaf.Dimension; ++axis)
          for (int step = local[axis] == 0 ? -1 : 1; step <= 1; step += 2)
          {
            int n[3] = { x, y, z };
            n[axis] += step;
            const std::int32_t there = image.At(n[0], n[1], n[2]);
            if (there != here)
              visit(local, axis, step, here, there);
          }
      }
}

} // namespace labelmesher

#endif
