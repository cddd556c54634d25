// SPDX-License-Identifier: GPL-2.0-or-later
// The 2D curvilinear mesher of chapter 4: smooth the interfaces, prove validity, untangle.
#include "Curving/BezierCurver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace labelmesher
{
namespace
{

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The curver needs counter-clockwise, non-degenerate triangles: the elastic
/// body and every Jacobian bound are defined relative to them.
void ValidateLinearMesh(const SimplexMesh& mesh)
{
  if (mesh.Dimension != 2)
  {
    throw std::invalid_argument("the curver needs a 2D triangle mesh");
  }
  if (mesh.NumberOfCells() == 0)
  {
    throw std::invalid_argument("the mesh has no triangles");
  }
  const auto points = static_cast<std::int64_t>(mesh.Points.size());
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* v = mesh.Cell(c);
    for (int k = 0; k < 3; ++k)
    {
      if (v[k] < 0 || v[k] >= points)
      {
        throw std::invalid_argument("triangle " + std::to_string(c) + " refers to a missing point");
      }
    }
    const Point3& a = mesh.Points[v[0]];
    const Point3& b = mesh.Points[v[1]];
    const Point3& d = mesh.Points[v[2]];
    const double area2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    if (!(area2 > 0.0))
    {
      throw std::invalid_argument("triangle " + std::to_string(c) +
        (area2 == 0.0 ? " is degenerate" : " is clockwise (inverted)"));
    }
  }
}

/// Section 4.1: one smooth Bézier path per interface chain; the inner control
/// points of its segments become the targets of the chain edges' control points.
std::vector<std::pair<std::int64_t, Point2>> SmoothInterfaces(const SimplexMesh& linear,
  const CurvedMesh& curved, const std::vector<InterfaceChain>& chains,
  const SmoothingOptions& options, std::size_t& curvedEdges)
{
  std::vector<std::pair<std::int64_t, Point2>> prescribed;
  curvedEdges = 0;
  for (const InterfaceChain& chain : chains)
  {
    std::vector<Point2> vertices;
    vertices.reserve(chain.Vertices.size());
    for (std::int64_t v : chain.Vertices)
    {
      vertices.push_back({ linear.Points[v][0], linear.Points[v][1] });
    }
    const auto segments = SmoothChain(vertices, chain.Closed, options);
    for (std::size_t s = 0; s < segments.size(); ++s)
    {
      const std::int64_t a = chain.Vertices[s];
      const std::int64_t b = chain.Vertices[(s + 1) % chain.Vertices.size()];
      const auto ids = curved.EdgePoints(a, b);
      prescribed.emplace_back(ids[0], segments[s][0]);
      prescribed.emplace_back(ids[1], segments[s][1]);
      ++curvedEdges;
    }
  }
  return prescribed;
}

/// A box no mesh vertex lies on: without a known image border every interface is curved.
Box2 BoxAroundMesh(const SimplexMesh& mesh)
{
  Box2 box = BoundingBox2(mesh);
  const double margin = 1.0 + std::max(box[1] - box[0], box[3] - box[2]);
  return { box[0] - margin, box[1] + margin, box[2] - margin, box[3] + margin };
}

/// Cells not proven valid when the control points sit at `positions` (the
/// mesh's cells, other positions): no copy of the mesh's cells and edge map.
std::size_t CountInvalidCells(const CurvedMesh& mesh, const std::vector<Point2>& positions)
{
  std::size_t invalid = 0;
  for (const auto& ids : mesh.Cells)
  {
    CubicTriangle cell;
    for (int k = 0; k < 10; ++k)
      cell.ControlPoints[k] = positions[static_cast<std::size_t>(ids[k])];
    invalid += ClassifyValidity(cell) != Validity::Valid ? 1 : 0;
  }
  return invalid;
}

} // namespace

CurvingResult CurveMesh(
  const SimplexMesh& linear, const CurvingParameters& parameters, const ProgressObserver& observer)
{
  ValidateLinearMesh(linear);
  if (!observer.Report("Smoothing boundaries", 0.0))
  {
    throw AbortRequested{};
  }
  CurvingResult result;
  auto start = Clock::now();
  const Box2 border = parameters.HasBorder ? parameters.Border : BoxAroundMesh(linear);
  result.Linear = linear;
  std::vector<InterfaceChain> chains = ExtractInterfaceChains(result.Linear, border);
  result.SplitEars = SplitBoundaryEars(result.Linear, chains, border);
  result.NumberOfChains = chains.size();
  for (const InterfaceChain& chain : chains)
  {
    result.NumberOfClosedChains += chain.Closed ? 1 : 0;
  }
  result.Mesh = MakeStraightCurvedMesh(result.Linear);
  const auto prescribed = SmoothInterfaces(
    result.Linear, result.Mesh, chains, parameters.Smoothing, result.NumberOfCurvedEdges);
  result.Timings.push_back({ "smooth boundaries", SecondsSince(start) });

  // How many cells curving the boundary alone would break (the dissertation's
  // "invalid elements" before the FE method, section 5.2.4).
  start = Clock::now();
  {
    std::vector<Point2> boundaryOnly = result.Mesh.ControlPoints;
    for (const auto& [id, target] : prescribed)
    {
      boundaryOnly[static_cast<std::size_t>(id)] = target;
    }
    result.InvalidBeforeUntangling = CountInvalidCells(result.Mesh, boundaryOnly);
  }
  result.Timings.push_back({ "validity before untangling", SecondsSince(start) });

  start = Clock::now();
  ProgressObserver untangling;
  untangling.Callback = [&observer](const std::string& stage, double fraction) {
    return observer.Report(stage, 0.05 + 0.85 * fraction);
  };
  const UntanglingResult untangled =
    UntangleControlNets(result.Mesh, prescribed, parameters.Untangling, untangling);
  result.UntanglingSteps = untangled.Steps;
  result.Timings.push_back({ "untangle", SecondsSince(start) });

  // Section 4.2: a proven bound for every cell. A cell is valid when either the
  // control net (Theorem 4.2.1) or the subdivided Jacobian proves det J > 0.
  start = Clock::now();
  if (!observer.Report("Bounding Jacobians", 0.9))
  {
    throw AbortRequested{};
  }
  result.CellBounds.reserve(result.Mesh.Cells.size());
  for (std::size_t c = 0; c < result.Mesh.Cells.size(); ++c)
  {
    const CubicTriangle cell = result.Mesh.Cell(c);
    result.CellBounds.push_back(BoundJacobian(cell));
    if (ClassifyValidity(cell) != Validity::Valid)
    {
      result.InvalidCells.push_back(c);
    }
  }
  result.Valid = result.InvalidCells.empty();
  result.Timings.push_back({ "bound Jacobians", SecondsSince(start) });
  observer.Report("Bounding Jacobians", 1.0);
  return result;
}

} // namespace labelmesher
