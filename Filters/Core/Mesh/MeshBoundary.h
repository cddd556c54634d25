// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MeshBoundary_h
#define labelmesher_MeshBoundary_h

/**
 * @file MeshBoundary.h
 * The mesh boundary S: every cell face (edge in 2D) whose two sides carry
 * different materials, where the outside of the mesh counts as material 0.
 *
 * Precondition: the mesh fills its bounding box (as the mesher's mesh, with
 * background cells, does), so that faces used by one cell lie on that box;
 * only faces near interfaces or on the box are hashed, which keeps this pass
 * proportional to the boundary rather than to the volume.
 */

#include "Mesh/SimplexMesh.h"

#include <utility>
#include <vector>

namespace labelmesher
{

struct MaterialInterfaces
{
  SimplexMesh Faces; ///< triangles (3D) or segments (2D, Dimension == 1), sharing Points with the mesh
  /// Materials on either side of each face: first is the side the face's normal
  /// points away from (the cell it was taken from), second the other side.
  std::vector<std::pair<std::int32_t, std::int32_t>> Sides;
};

MaterialInterfaces ExtractMaterialInterfaces(const SimplexMesh& mesh);

} // namespace labelmesher

#endif
