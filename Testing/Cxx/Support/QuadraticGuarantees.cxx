// SPDX-License-Identifier: GPL-2.0-or-later
// Mesher, decimator and quadratic curver on one image, and every guarantee of the curved mesh measured.
#include "QuadraticGuarantees.h"

#include "Checks/QuadraticVolume.h"
#include "Support/Geometry.h"

#include <algorithm>

#include <sstream>

namespace labelmesher
{
namespace testing
{

std::vector<std::string> ViolatedQuadraticGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, QuadraticRun* run, const QuadraticParameters* curver)
{
  QuadraticRun local;
  QuadraticRun& out = run ? *run : local;
  QuadraticParameters parameters = curver ? *curver : QuadraticParameters{};
  parameters.ImageToMeshDistance = mesher.ImageToMeshDistance;
  parameters.MeshToImageDistance = mesher.MeshToImageDistance;
  if (!curver)
    parameters.MinimumScaledJacobian = kQuadraticScaledJacobian;
  parameters.MinimumCornerAngle = decimation.MinimumAngle;
  out.CornerAngle = decimation.MinimumAngle;
  SimplexMesh linear;
  try
  {
    linear = DecimateMesh(image, MeshLabelImage(image, mesher).Mesh, decimation).Mesh;
    out.Result = CurveQuadratic(linear, image, parameters);
  }
  catch (const std::exception& e)
  {
    return { std::string("mesher, decimator or curver threw: ") + e.what() };
  }
  return ViolatedQuadraticMeshGuarantees(image, mesher, linear, out);
}

std::vector<std::string> ViolatedQuadraticMeshGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const SimplexMesh& linear, QuadraticRun& out)
{
  std::vector<std::string> violated;
  auto fail = [&violated](const std::string& what) { violated.push_back(what); };
  const QuadraticMesh& mesh = out.Result.Mesh;

  // Validity and quality: det J on a dense lattice of every curved cell.
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    if (!mesh.CellIsCurved(c))
      continue;
    double smallest = 0.0;
    const double ratio = SampledScaledJacobian(mesh.Nodes(c), 8, smallest);
    if (smallest <= 0.0)
    {
      fail("cell " + std::to_string(c) + ": det J " + std::to_string(smallest) + " <= 0 at a sample");
      break;
    }
    if (ratio < kQuadraticScaledJacobian)
    {
      fail("cell " + std::to_string(c) + ": sampled min det J / max det J " + std::to_string(ratio) + " below " +
        std::to_string(kQuadraticScaledJacobian));
      break;
    }
    if (ratio < out.Result.ScaledJacobian[c] - 1e-9)
    {
      fail("cell " + std::to_string(c) + ": certified scaled Jacobian " + std::to_string(out.Result.ScaledJacobian[c]) +
        " above the sampled " + std::to_string(ratio));
      break;
    }
  }

  // Corners: at least the asked angle, or the linear mesh's smallest dihedral angle if smaller
  // (the straight mesh is the curver's last resort).
  double linearSmallest = 180.0;
  for (std::size_t c = 0; c < linear.NumberOfCells(); ++c)
  {
    const std::int64_t* v = linear.Cell(c);
    linearSmallest = std::min(linearSmallest,
      geometry::MinimumDihedralAngle(linear.Points[static_cast<std::size_t>(v[0])], linear.Points[static_cast<std::size_t>(v[1])],
        linear.Points[static_cast<std::size_t>(v[2])], linear.Points[static_cast<std::size_t>(v[3])]));
  }
  const double cornerBound = std::min(out.CornerAngle, linearSmallest);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const double corner = MeasuredCornerAngle(mesh.Nodes(c));
    if (corner < cornerBound - 1e-6)
    {
      fail("cell " + std::to_string(c) + ": corner angle " + std::to_string(corner) + " below " +
        std::to_string(cornerBound) + " degrees");
      break;
    }
  }

  // Distances on the boundary faces flattened finely; topology and conformity on the refined cells.
  constexpr int kFacetSteps = 8, kRefinement = 2, kAccuracyRefinement = 4;
  const double allowance = RefinementTolerance(mesh, kFacetSteps) + 2.0 / 1024.0 + 1e-9;
  const HausdorffReport distances = MeasureHausdorff(image, CurvedBoundaryFacets(mesh, kFacetSteps));
  for (const auto& [material, d] : distances.PerMaterial)
  {
    if (d.ImageToMesh > mesher.ImageToMeshDistance + allowance || d.MeshToImage > mesher.MeshToImageDistance + allowance)
    {
      std::ostringstream line;
      line << "material " << material << ": h(I,M) " << d.ImageToMesh << ", h(M,I) " << d.MeshToImage
           << " beyond the bounds " << mesher.ImageToMeshDistance << "/" << mesher.MeshToImageDistance << " + "
           << allowance;
      fail(line.str());
    }
  }
  // Conformity is combinatorial here: every face shared by at most two cells, the boundary closed.
  // (The hanging-vertex test is geometric, and a piecewise-linear approximation of curved cells
  // may have one cell's node on another's sub-triangle where the curved cells only meet: not a
  // fault of the mesh, which cannot overlap when every cell is valid, QuadraticCurver.h.)
  const SimplexMesh refined = RefineQuadraticMesh(mesh, kRefinement);
  const ConformityReport conformity = MeasureConformity(refined);
  if (conformity.OverSharedFaces != 0 || conformity.NonManifoldBoundaryEdges != 0)
    fail("the refined quadratic mesh is not conforming: " + std::to_string(conformity.OverSharedFaces) +
      " faces of more than two cells, " + std::to_string(conformity.NonManifoldBoundaryEdges) +
      " non-manifold boundary edges");
  for (const auto& [material, t] : CompareTopology(image, refined))
    if (!t.Matches())
      fail("material " + std::to_string(material) + ": topology " + std::to_string(t.Mesh.Components) + " components, chi " +
        std::to_string(t.Mesh.EulerCharacteristic) + " where the image has " + std::to_string(t.Image.Components) +
        ", " + std::to_string(t.Image.EulerCharacteristic));

  out.MisclassifiedLinear = MeasureVoxelAccuracy(image, linear).Misclassified;
  out.MisclassifiedCurved = MeasureVoxelAccuracy(image, RefineQuadraticMesh(mesh, kAccuracyRefinement)).Misclassified;
  return violated;
}

} // namespace testing
} // namespace labelmesher
