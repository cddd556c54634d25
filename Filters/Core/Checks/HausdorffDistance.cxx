// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file HausdorffDistance.cxx
 * MeasureHausdorff / WithinHausdorff: the fidelity guarantee of the ORD mesh
 * (dissertation section 2.2 and 3.2): both one-sided Hausdorff distances
 * between the mesh boundary and the image boundary, overall and per material.
 *
 * Both boundaries are finite unions of convex pieces (ConvexShape.h): voxel
 * faces (axis-aligned squares; pixel edges in 2D) and mesh boundary facets
 * (triangles; segments in 2D), extracted once for all materials
 * (BoundaryShapes.h). Each one-sided distance is bounded by branch and bound
 * (DirectedDistance.h), with an exact zero for elements covered by coplanar
 * pieces (CoplanarCoverage.h) and the pieces in a uniform grid (ShapeGrid.h).
 *
 * MeasureHausdorff refines an element until its upper bound is within
 * `tolerance` of the largest lower bound found so far (or a depth/work limit
 * is hit: the result is then still an upper bound, only less tight).
 * WithinHausdorff answers true only when every element is certified, up to
 * 1e-9; an element left undecided at the depth/work limit counts as a failure.
 */

#include "Checks/MeshChecks.h"

#include "Checks/BoundaryShapes.h"
#include "Checks/DirectedDistance.h"

#include <limits>

namespace labelmesher
{

namespace
{
using checks_detail::BoundaryPieces;

DistanceReport MeasurePair(const BoundaryPieces& b, double tolerance)
{
  DistanceReport d;
  if (b.Image.empty() != b.Mesh.empty())
  {
    d.ImageToMesh = d.MeshToImage = std::numeric_limits<double>::infinity();
    return d;
  }
  d.ImageToMesh = checks_detail::MeasureDirected(b.Image, b.Mesh, tolerance);
  d.MeshToImage = checks_detail::MeasureDirected(b.Mesh, b.Image, tolerance);
  return d;
}

bool WithinPair(const BoundaryPieces& b, double imageToMesh, double meshToImage)
{
  if (b.Image.empty() != b.Mesh.empty())
    return false;
  return checks_detail::WithinDirected(b.Image, b.Mesh, imageToMesh) &&
    checks_detail::WithinDirected(b.Mesh, b.Image, meshToImage);
}

} // namespace

namespace
{
HausdorffReport MeasureBoundaries(const checks_detail::Boundaries& b, double tolerance)
{
  HausdorffReport report;
  report.Overall = MeasurePair(b.Overall, tolerance);
  for (const auto& entry : b.PerMaterial)
    report.PerMaterial[entry.first] =
      checks_detail::SameAsOverall(b, entry.second) ? report.Overall : MeasurePair(entry.second, tolerance);
  return report;
}
} // namespace

HausdorffReport MeasureHausdorff(const LabelImage& image, const SimplexMesh& mesh, double tolerance)
{
  return MeasureBoundaries(checks_detail::ExtractBoundaries(image, mesh), tolerance);
}

HausdorffReport MeasureHausdorff(const LabelImage& image, const std::vector<BoundaryFacet>& facets, double tolerance)
{
  return MeasureBoundaries(checks_detail::ExtractBoundaries(image, facets), tolerance);
}

bool WithinHausdorff(const LabelImage& image, const SimplexMesh& mesh, double imageToMesh, double meshToImage)
{
  const checks_detail::Boundaries b = checks_detail::ExtractBoundaries(image, mesh);
  if (!WithinPair(b.Overall, imageToMesh, meshToImage))
    return false;
  for (const auto& entry : b.PerMaterial)
    if (!checks_detail::SameAsOverall(b, entry.second) && !WithinPair(entry.second, imageToMesh, meshToImage))
      return false;
  return true;
}

} // namespace labelmesher
