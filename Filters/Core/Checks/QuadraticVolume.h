// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QuadraticVolume_h
#define labelmesher_QuadraticVolume_h

/**
 * @file QuadraticVolume.h
 * The checks of MeshChecks.h for a quadratic tetrahedral mesh, and the voxel
 * accuracy of any tetrahedral mesh. Independent of the curver: the quadratic
 * map and its Jacobian are evaluated here from the nodes (Lagrange shape
 * functions), not from its Bernstein form.
 *
 * RefineQuadraticMesh replaces every cell by the n³ tetrahedra of its
 * Freudenthal (Kuhn) subdivision at step 1/n, through the points of the
 * quadratic map; the subdivision follows the corners' global order, so
 * neighbours induce the same triangles on their common face and share its
 * points: a conforming linear mesh whose boundaries are within
 * (2/3) max_e |a + b − 2 m_e| / n² of the quadratic cells' (RefinementTolerance).
 * MeshChecks.h then measures topology and conformity on it, and distances on
 * the boundary faces alone (CurvedBoundaryFacets).
 */

#include "Checks/MeshChecks.h"
#include "Quadratic/QuadraticMesh.h"

#include <array>
#include <cstddef>

namespace labelmesher
{

SimplexMesh RefineQuadraticMesh(const QuadraticMesh& mesh, int n);

/// The faces bounding a material (between cells of two materials, or of one
/// cell: the box), each curved one flattened into the m² triangles through its
/// points at step 1/m, m ≤ n the smallest that keeps it within
/// RefinementTolerance(mesh, n) (a face bent less than the most bent edge
/// needs fewer), each straight one as it is: the curved boundary to within
/// that tolerance, for MeasureHausdorff at a fine step without refining the
/// volume.
std::vector<BoundaryFacet> CurvedBoundaryFacets(const QuadraticMesh& mesh, int n);

/// How far RefineQuadraticMesh(mesh, n)'s boundaries may be from the curved ones, voxels.
double RefinementTolerance(const QuadraticMesh& mesh, int n);

/// min det J / max det J of a quadratic tetrahedron (VTK's node order) over the
/// barycentric lattice of step 1/n (the corners included): at least the true
/// ratio when the sampled minimum is positive; the smallest sampled det J is in
/// `smallest` (> 0 where valid).
double SampledScaledJacobian(const std::array<Point3, 10>& nodes, int n, double& smallest);

/// The smallest dihedral angle, degrees, of the tangent trihedra at the four
/// corners (the curver's corner angles, Quadratic/QuadraticCorners.h), measured
/// independently of it: each tangent from points of the map along the edge
/// (2 D(t) − D(2t) with D(t) = (x(t) − x(0)) / t, exact for a quadratic
/// curve), each angle between the normals of the trihedron's faces.
double MeasuredCornerAngle(const std::array<Point3, 10>& nodes);

struct VoxelAccuracy
{
  std::size_t Voxels = 0;        ///< voxels of the image
  /// Voxels whose centre lies in a cell of another material, or in no cell
  /// while their label is not 0 (a centre on a shared face counts for the
  /// cell found first).
  std::size_t Misclassified = 0;
};
/// Of a linear tetrahedral mesh in index space (voxel centres at integer points).
VoxelAccuracy MeasureVoxelAccuracy(const LabelImage& image, const SimplexMesh& mesh);
/// Of a quadratic one: its curved cells refined at step 1/n as RefineQuadraticMesh does, one
/// cell at a time (the refined mesh is never held), its straight cells as they are.
VoxelAccuracy MeasureVoxelAccuracy(const LabelImage& image, const QuadraticMesh& mesh, int n);

} // namespace labelmesher

#endif
