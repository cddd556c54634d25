// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MeshSelection_h
#define labelmesher_MeshSelection_h

/**
 * @file MeshSelection.h
 * Sub-meshes of a SimplexMesh: the cells of chosen materials, with the points
 * they use renumbered in order of first use (unused points dropped).
 */

#include "Mesh/SimplexMesh.h"

namespace labelmesher
{

/// The cells of non-zero material (or every cell when `includeBackground`),
/// with compacted points.
SimplexMesh SelectMaterials(const SimplexMesh& mesh, bool includeBackground = false);
/// The same, taking `mesh` over: when every cell is kept it is returned as it
/// is (no copy: the meshes of large images are the run's peak memory).
SimplexMesh SelectMaterials(SimplexMesh&& mesh, bool includeBackground = false);

} // namespace labelmesher

#endif
