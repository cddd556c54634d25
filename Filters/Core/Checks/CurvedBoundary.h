// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CurvedBoundary_h
#define labelmesher_CurvedBoundary_h

/**
 * @file CurvedBoundary.h
 * The checks of MeshChecks.h for a curved 2D mesh. Every cell edge is
 * replaced by a polyline within `tolerance` of its cubic both ways
 * (FlattenCubic), and every cell by the fan of its closed polyline from its
 * corners' centroid: a linear mesh with the curved mesh's boundaries (to
 * within the tolerance) and, since the fans share the edges' polylines, its
 * combinatorial topology. The fans themselves need not be valid triangles;
 * only their boundary edges and the cells' adjacency are measured. The
 * Hausdorff distances of the curves are then at most the polylines' plus the
 * tolerance, and interfaces cross where boundary polylines do.
 */

#include "Checks/MeshChecks.h"
#include "Curving/CurvedMesh.h"
#include "Curving/ImageOnMesh.h"

#include <cstddef>
#include <map>

namespace labelmesher
{

/// The fan mesh described above, in the image's index space.
SimplexMesh CurvedBoundaryPolygons(const CurvedMesh& mesh, const ImageOnMesh& image, double tolerance);

/// Boundary segments (as MeshChecks.h defines the mesh boundary) of a 2D
/// mesh that intersect another boundary segment other than at a shared end,
/// or overlap one with which they share an end: 0 when no interface crosses
/// or touches another or itself.
std::size_t CountBoundaryCrossings(const SimplexMesh& mesh);

struct CurvedMeshReport
{
  double Tolerance = 0.0;          ///< polyline-to-curve distance, voxels
  /// How far the Curves figures may exceed the true distances: the tolerance
  /// plus the Hausdorff measure's own 1/1024 (so a curve, or a straight edge,
  /// lying exactly at its bound may read up to bound + Resolution).
  double Resolution = 0.0;
  HausdorffReport Polylines;       ///< measured on the polylines
  DistanceReport Curves;           ///< upper bounds on the curves: polylines + tolerance, overall
  std::map<std::int32_t, DistanceReport> CurvesPerMaterial;
  std::size_t Crossings = 0;
  std::map<std::int32_t, TopologyComparison> Topology;
};

/// Distances, crossings and topology of a curved mesh against its image.
CurvedMeshReport MeasureCurvedMesh(const LabelImage& labels, const CurvedMesh& mesh, const ImageOnMesh& image,
  double tolerance = 1.0 / 1024.0);

} // namespace labelmesher

#endif
