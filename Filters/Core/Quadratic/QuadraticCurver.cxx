// SPDX-License-Identifier: GPL-2.0-or-later
// Fit, then certify and pull back until every cell and face holds.
#include "Quadratic/QuadraticCurver.h"

#include "Quadratic/InterfaceFaces.h"
#include "Quadratic/TetraJacobian.h"

#include <chrono>
#include <set>
#include <stdexcept>
#include <utility>

namespace labelmesher
{
namespace
{

double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Offset × 1/2, 1/4, then straight.
void PullBack(double& scale)
{
  scale = scale > 0.3 ? scale * 0.5 : 0.0;
}

std::array<double, 6> ImageBox(const LabelImage& image)
{
  // Voxel centres are at integers, so the sides are at -1/2 and n - 1/2.
  return { -0.5, image.Dimensions[0] - 0.5, -0.5, image.Dimensions[1] - 0.5, -0.5, image.Dimensions[2] - 0.5 };
}

} // namespace

QuadraticResult FitQuadraticMesh(SimplexMesh linear, const LabelImage& image, const QuadraticParameters& parameters)
{
  if (linear.Dimension != 3)
    throw std::invalid_argument("quadratic curving needs a tetrahedral mesh");
  QuadraticResult result;
  const auto start = std::chrono::steady_clock::now();
  result.Mesh = MakeQuadraticMesh(std::move(linear));
  const std::vector<MaterialFace> faces = FindInterfaceFaces(result.Mesh);
  const std::vector<char> curvable = CurvableEdges(result.Mesh, faces, ImageBox(image));
  result.FittedEdges = FitInterfaceMidNodes(result.Mesh, faces, curvable, image, parameters.Fit);
  result.FitSeconds = SecondsSince(start);
  return result;
}

QuadraticResult CurveQuadratic(SimplexMesh linear, const LabelImage& image, const QuadraticParameters& parameters)
{
  QuadraticResult result = FitQuadraticMesh(std::move(linear), image, parameters);
  CertifyQuadraticMesh(result, image, parameters);
  return result;
}

void CertifyQuadraticMesh(QuadraticResult& result, const LabelImage& image, const QuadraticParameters& parameters)
{
  if (!(parameters.MinimumScaledJacobian >= 0.0 && parameters.MinimumScaledJacobian < 1.0))
    throw std::invalid_argument("the minimum scaled Jacobian must be in [0, 1)");
  const auto start = std::chrono::steady_clock::now();
  QuadraticMesh& mesh = result.Mesh;
  const std::vector<MaterialFace> faces = FindInterfaceFaces(mesh);
  // Only interface sheets may bend: the box's faces stay flat (what the homeomorphism needs).
  const std::vector<char> curvable = CurvableEdges(mesh, faces, ImageBox(image));
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
    if (mesh.Curved(e) && !curvable[e])
    {
      mesh.Scales[e] = 0.0;
      ++result.StraightenedEdges;
    }
  const QuadraticBounds bounds{ parameters.ImageToMeshDistance, parameters.MeshToImageDistance, parameters.Tolerance };
  std::set<std::size_t> shortened, failedCells, failedFaces;
  result.ScaledJacobian.assign(mesh.NumberOfCells(), 1.0);
  for (;;)
  {
    ++result.Rounds;
    std::set<std::size_t> failing; // edges
    for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    {
      if (!mesh.CellIsCurved(c))
      {
        result.ScaledJacobian[c] = 1.0;
        continue;
      }
      result.ScaledJacobian[c] = CertifiedScaledJacobian(mesh.Nodes(c));
      const double ratio = result.ScaledJacobian[c];
      if (!parameters.CertifyValidity || (ratio > 0.0 && ratio >= parameters.MinimumScaledJacobian))
        continue;
      failedCells.insert(c);
      for (int e = 0; e < 6; ++e)
        failing.insert(static_cast<std::size_t>(mesh.CellEdges[c * 6 + e]));
    }
    if (parameters.CertifyDistances)
      for (std::size_t f : FacesBreakingDistances(mesh, faces, image, bounds))
      {
        failedFaces.insert(f);
        for (std::int64_t e : faces[f].Edges)
          failing.insert(static_cast<std::size_t>(e));
      }
    bool changed = false;
    for (std::size_t e : failing)
    {
      if (!mesh.Curved(e))
        continue;
      PullBack(mesh.Scales[e]);
      shortened.insert(e);
      result.StraightenedEdges += mesh.Scales[e] == 0.0 ? 1 : 0;
      changed = true;
    }
    if (!changed)
      break;
  }
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
    result.CurvedEdges += mesh.Curved(e) ? 1 : 0;
  result.ShortenedEdges = shortened.size();
  result.CellsFailedQuality = failedCells.size();
  result.FacesFailedDistance = failedFaces.size();
  result.CertifySeconds = SecondsSince(start);
}

} // namespace labelmesher
