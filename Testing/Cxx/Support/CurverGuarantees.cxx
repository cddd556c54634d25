// SPDX-License-Identifier: GPL-2.0-or-later
// Mesher, decimator and curver on one image, and every guarantee of the curved mesh measured.
#include "CurverGuarantees.h"

#include "Checks/CurvedBoundary.h"
#include "Curving/CurvedMeshLocator.h"
#include "CurvingChecks.h"
#include "RandomLabelImages.h"

#include <sstream>

namespace labelmesher
{
namespace testing
{

Smoothness DrawSmoothness(std::uint64_t seed)
{
  SeededRandom draw(seed ^ 0x5851f42d4c957f2dull);
  return draw.Chance(0.5) ? Smoothness::C1 : Smoothness::C2;
}

std::vector<std::string> ViolatedCurverGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, Smoothness smoothness, CurverRun* run, double curverScaledJacobian,
  double curverCornerAngle, int curverOrder, int assertedOrder)
{
  if (assertedOrder == 0)
    assertedOrder = curverOrder;
  std::vector<std::string> violated;
  auto fail = [&violated](const std::string& what) { violated.push_back(what); };
  CurverRun local;
  CurverRun& out = run ? *run : local;
  const ImageOnMesh identity{ &image, { 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 } };
  CurvingParameters parameters;
  parameters.Smoothing.Continuity = smoothness;
  parameters.HasBorder = true;
  parameters.Border = { -0.5, image.Dimensions[0] - 0.5, -0.5, image.Dimensions[1] - 0.5 };
  parameters.Image = identity;
  parameters.Bounds.ImageToMesh = mesher.ImageToMeshDistance;
  parameters.Bounds.MeshToImage = mesher.MeshToImageDistance;
  parameters.MinimumScaledJacobian = curverScaledJacobian;
  parameters.MinimumCornerAngle = curverCornerAngle < 0.0 ? decimation.MinimumAngle : curverCornerAngle;
  parameters.Order = curverOrder;
  try
  {
    out.Linear = ForegroundMesh(DecimateMesh(image, MeshLabelImage(image, mesher).Mesh, decimation).Mesh);
    out.Result = CurveMesh(out.Linear, parameters);
  }
  catch (const std::exception& e)
  {
    return { std::string("mesher, decimator or curver threw: ") + e.what() };
  }
  const CurvingResult& result = out.Result;

  // Validity: proven for every cell, and the proof agrees with dense sampling.
  if (!result.Valid)
    fail(std::to_string(result.InvalidCells.size()) + " cells not proven valid");
  for (std::size_t c = 0; c < result.Mesh.Cells.size(); ++c)
  {
    const CubicTriangle cell = result.Mesh.Cell(c);
    if (ClassifyValidity(cell) == Validity::Valid && SampledMinimumJacobian(cell) <= 0.0)
    {
      fail("cell " + std::to_string(c) + " proven valid but det J <= 0 at a sample");
      break;
    }
  }
  // The scaled Jacobian: min det J / max det J at dense samples, which is at least the true ratio.
  for (std::size_t c = 0; c < result.Mesh.Cells.size(); ++c)
  {
    const double ratio = SampledJacobianRatio(result.Mesh.Cell(c));
    if (ratio < kCurvedScaledJacobian)
    {
      fail("cell " + std::to_string(c) + ": sampled min det J / max det J " + std::to_string(ratio) + " below " +
        std::to_string(kCurvedScaledJacobian));
      break;
    }
  }

  // Corner angles: the linear mesh's bound, between tangents measured from the cell's own map.
  for (std::size_t c = 0; c < result.Mesh.Cells.size(); ++c)
  {
    const double angle = SampledCornerAngle(result.Mesh.Cell(c));
    if (angle < decimation.MinimumAngle - kCornerAngleTolerance)
    {
      fail("cell " + std::to_string(c) + ": corner angle " + std::to_string(angle) + " degrees below " +
        std::to_string(decimation.MinimumAngle));
      break;
    }
  }

  // Quadratic triangles: each cell is one, and its six nodes give the same map.
  if (assertedOrder == 2)
  {
    for (std::size_t c = 0; c < result.Mesh.Cells.size(); ++c)
    {
      const CubicTriangle cell = result.Mesh.Cell(c);
      const double off = QuadraticNodesMismatch(cell);
      if (!(off <= 1e-9 * (1.0 + image.Dimensions[0] + image.Dimensions[1])))
      {
        fail("cell " + std::to_string(c) + " is not a quadratic triangle: its 6-node map is " + std::to_string(off) +
          " off at a sample");
        break;
      }
    }
  }

  // Continuity at every joint, as far as the pieces' scales promise it.
  const JointContinuity joints =
    MeasureJointContinuity(result.Linear, result.Mesh, parameters.Border, smoothness, result.Pieces,
      parameters.MinimumCornerAngle > 0.0);
  if (assertedOrder != 2 && (!(joints.FirstDerivativeMismatch < 1e-9) || !(joints.SecondDerivativeMismatch < 1e-9)))
  {
    std::ostringstream what;
    what << "joint continuity: first-derivative mismatch " << joints.FirstDerivativeMismatch << ", second "
         << joints.SecondDerivativeMismatch;
    fail(what.str());
  }
  if (joints.VertexMovement != 0.0)
    fail("a chain vertex moved by " + std::to_string(joints.VertexMovement));

  // Both distance bounds on the curves, per material; no crossings; topology.
  const CurvedMeshReport curved = MeasureCurvedMesh(image, result.Mesh, identity);
  auto checkDistances = [&](const std::string& where, const DistanceReport& d) {
    const double slack = curved.Resolution + 1e-9;
    if (d.ImageToMesh > mesher.ImageToMeshDistance + slack || d.MeshToImage > mesher.MeshToImageDistance + slack)
    {
      std::ostringstream what;
      what << where << ": curves at h(I,M) " << d.ImageToMesh << ", h(M,I) " << d.MeshToImage << " above the bounds "
           << mesher.ImageToMeshDistance << "/" << mesher.MeshToImageDistance;
      fail(what.str());
    }
  };
  checkDistances("overall", curved.Curves);
  for (const auto& [material, d] : curved.CurvesPerMaterial)
    checkDistances("material " + std::to_string(material), d);
  if (curved.Crossings != 0)
    fail(std::to_string(curved.Crossings) + " boundary segments of the curves cross or touch another");
  for (const auto& [material, comparison] : curved.Topology)
  {
    if (!comparison.Matches())
    {
      std::ostringstream what;
      what << "material " << material << ": curved mesh has " << comparison.Mesh.Components << " components, chi "
           << comparison.Mesh.EulerCharacteristic << "; image " << comparison.Image.Components << ", chi "
           << comparison.Image.EulerCharacteristic;
      fail(what.str());
    }
  }
  const std::array<double, 6> identityMap{ 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 };
  out.MisclassifiedLinear = MeasurePixelAccuracy(MakeStraightCurvedMesh(result.Linear), image, identityMap).Misclassified;
  out.MisclassifiedCurved = MeasurePixelAccuracy(result.Mesh, image, identityMap).Misclassified;
  return violated;
}

} // namespace testing
} // namespace labelmesher
