// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BoundaryShapes_h
#define labelmesher_BoundaryShapes_h

/**
 * @file BoundaryShapes.h
 * Internal to the checks (not installed, not part of the public API): the
 * image boundary and the mesh boundary (MeshChecks.h) as lists of convex
 * pieces, overall and per material, for the Hausdorff distance check.
 */

#include "Checks/ConvexShape.h"
#include "Checks/MeshChecks.h"
#include "Support/LabelImage.h"
#include "Mesh/SimplexMesh.h"

#include <cstdint>
#include <map>
#include <vector>

namespace labelmesher
{
namespace checks_detail
{

struct BoundaryPieces
{
  std::vector<Shape> Image; ///< voxel faces (pixel edges) between different labels
  std::vector<Shape> Mesh;  ///< mesh boundary triangles (segments)
};

struct Boundaries
{
  /// Each voxel face (mesh facet) once.
  BoundaryPieces Overall;
  /// Per non-zero label: the pieces on the boundary of that material, a subset of Overall.
  std::map<std::int32_t, BoundaryPieces> PerMaterial;
};

Boundaries ExtractBoundaries(const LabelImage& image, const SimplexMesh& mesh);
Boundaries ExtractBoundaries(const LabelImage& image, const std::vector<BoundaryFacet>& facets);

/// A material whose boundaries are the overall ones (a single material): its
/// pieces are a subset of the overall ones, so equal counts mean equal sets,
/// and its distances need not be computed again.
inline bool SameAsOverall(const Boundaries& b, const BoundaryPieces& material)
{
  return material.Image.size() == b.Overall.Image.size() && material.Mesh.size() == b.Overall.Mesh.size();
}

} // namespace checks_detail
} // namespace labelmesher

#endif
