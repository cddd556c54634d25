// SPDX-License-Identifier: GPL-2.0-or-later
// Distances, crossings and topology of curved 2D meshes, measured on certified polylines.
#include "Checks/CurvedBoundary.h"

#include "Curving/CurvePieces.h"
#include "Support/BoxBins.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace labelmesher
{
namespace
{

using EdgeKey = std::pair<std::int64_t, std::int64_t>;
struct EdgeKeyHash
{
  std::size_t operator()(const EdgeKey& k) const
  {
    return std::hash<std::int64_t>()(k.first) * 1000003u ^ std::hash<std::int64_t>()(k.second);
  }
};

double Cross(const Point3& o, const Point3& a, const Point3& b)
{
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

bool OnSegment(const Point3& p, const Point3& a, const Point3& b)
{
  return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
    p[1] <= std::max(a[1], b[1]);
}

/// Closed segments ab and cd meet (exact predicates on doubles: the
/// orientation signs are computed in floating point, which errs only on
/// near-degenerate pairs).
bool SegmentsMeet(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  const double d1 = Cross(c, d, a), d2 = Cross(c, d, b), d3 = Cross(a, b, c), d4 = Cross(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  return (d1 == 0 && OnSegment(a, c, d)) || (d2 == 0 && OnSegment(b, c, d)) || (d3 == 0 && OnSegment(c, a, b)) ||
    (d4 == 0 && OnSegment(d, a, b));
}

} // namespace

SimplexMesh CurvedBoundaryPolygons(const CurvedMesh& mesh, const ImageOnMesh& image, double tolerance)
{
  SimplexMesh out;
  out.Dimension = 2;
  auto add = [&out](const Point2& p) {
    out.Points.push_back({ p[0], p[1], 0.0 });
    return static_cast<std::int64_t>(out.Points.size() - 1);
  };
  for (std::int64_t v = 0; v < mesh.NumberOfVertices; ++v)
    add(image.ToIndex(mesh.ControlPoints[static_cast<std::size_t>(v)]));
  // Each edge's polyline once, ordered from its smaller vertex id.
  std::unordered_map<EdgeKey, std::vector<std::int64_t>, EdgeKeyHash> polylines;
  auto polyline = [&](std::int64_t a, std::int64_t b) {
    const EdgeKey key{ std::min(a, b), std::max(a, b) };
    auto it = polylines.find(key);
    if (it == polylines.end())
    {
      const auto ids = mesh.EdgePoints(key.first, key.second);
      std::array<Point2, 4> p{ mesh.ControlPoints[key.first], mesh.ControlPoints[ids[0]],
        mesh.ControlPoints[ids[1]], mesh.ControlPoints[key.second] };
      for (Point2& q : p)
        q = image.ToIndex(q);
      const std::vector<Point2> points = FlattenCubic(p, tolerance);
      std::vector<std::int64_t> chain{ key.first };
      for (std::size_t k = 1; k + 1 < points.size(); ++k)
        chain.push_back(add(points[k]));
      chain.push_back(key.second);
      it = polylines.emplace(key, std::move(chain)).first;
    }
    std::vector<std::int64_t> chain = it->second;
    if (a > b)
      std::reverse(chain.begin(), chain.end());
    return chain;
  };
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
  {
    const auto& cell = mesh.Cells[c];
    std::vector<std::int64_t> loop;
    for (int k = 0; k < 3; ++k)
    {
      const std::vector<std::int64_t> chain = polyline(cell[k], cell[(k + 1) % 3]);
      loop.insert(loop.end(), chain.begin(), chain.end() - 1);
    }
    Point2 centre{ 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 2; ++a)
        centre[a] += out.Points[static_cast<std::size_t>(cell[k])][a] / 3.0;
    const std::int64_t hub = out.Points.size();
    out.Points.push_back({ centre[0], centre[1], 0.0 });
    for (std::size_t k = 0; k < loop.size(); ++k)
    {
      out.Connectivity.insert(out.Connectivity.end(), { hub, loop[k], loop[(k + 1) % loop.size()] });
      out.Materials.push_back(mesh.Materials[c]);
    }
  }
  return out;
}

std::size_t CountBoundaryCrossings(const SimplexMesh& mesh)
{
  // Boundary segments: used by one cell, or by two of different materials.
  std::unordered_map<EdgeKey, std::pair<std::int32_t, int>, EdgeKeyHash> uses;
  std::unordered_map<EdgeKey, bool, EdgeKeyHash> differ;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* v = mesh.Cell(c);
    for (int k = 0; k < 3; ++k)
    {
      const EdgeKey key{ std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3]) };
      auto [it, inserted] = uses.emplace(key, std::make_pair(mesh.Materials[c], 1));
      if (!inserted)
      {
        ++it->second.second;
        differ[key] = differ[key] || it->second.first != mesh.Materials[c];
      }
    }
  }
  std::vector<EdgeKey> segments;
  for (const auto& [key, use] : uses)
    if (use.second == 1 || differ[key])
      segments.push_back(key);
  std::sort(segments.begin(), segments.end());
  // Segments in the uniform bins their boxes overlap: segments that meet share a bin.
  BoxBins bins(4.0);
  for (std::size_t s = 0; s < segments.size(); ++s)
  {
    const Point3& a = mesh.Points[segments[s].first];
    const Point3& b = mesh.Points[segments[s].second];
    bins.Insert(s, { std::min(a[0], b[0]), std::min(a[1], b[1]) }, { std::max(a[0], b[0]), std::max(a[1], b[1]) });
  }
  std::vector<char> crossing(segments.size(), 0);
  bins.ForEachBin([&](const std::vector<std::size_t>& members) {
    for (std::size_t i = 0; i < members.size(); ++i)
      for (std::size_t j = i + 1; j < members.size(); ++j)
      {
        const EdgeKey& s = segments[members[i]];
        const EdgeKey& t = segments[members[j]];
        const Point3 &a = mesh.Points[s.first], &b = mesh.Points[s.second];
        const Point3 &c = mesh.Points[t.first], &d = mesh.Points[t.second];
        bool meets;
        if (s.first == t.first || s.first == t.second || s.second == t.first || s.second == t.second)
        {
          // A shared end: they cross only by overlapping, the far end of one on the other.
          const std::int64_t shared = (s.first == t.first || s.first == t.second) ? s.first : s.second;
          const Point3& p = shared == s.first ? b : a;
          const Point3& q = (t.first == shared) ? d : c;
          const Point3& o = mesh.Points[shared];
          meets = (Cross(o, q, p) == 0 && OnSegment(p, o, q)) || (Cross(o, p, q) == 0 && OnSegment(q, o, p));
        }
        else
        {
          meets = SegmentsMeet(a, b, c, d);
        }
        if (meets)
          crossing[members[i]] = crossing[members[j]] = 1;
      }
  });
  return static_cast<std::size_t>(std::count(crossing.begin(), crossing.end(), 1));
}

CurvedMeshReport MeasureCurvedMesh(
  const LabelImage& labels, const CurvedMesh& mesh, const ImageOnMesh& image, double tolerance)
{
  CurvedMeshReport report;
  report.Tolerance = tolerance;
  constexpr double kMeasureTolerance = 1.0 / 1024.0; // MeasureHausdorff's default
  report.Resolution = tolerance + kMeasureTolerance;
  const SimplexMesh polygons = CurvedBoundaryPolygons(mesh, image, tolerance);
  report.Polylines = MeasureHausdorff(labels, polygons, kMeasureTolerance);
  auto widen = [tolerance](const DistanceReport& d) {
    return DistanceReport{ d.ImageToMesh + tolerance, d.MeshToImage + tolerance };
  };
  report.Curves = widen(report.Polylines.Overall);
  for (const auto& [material, d] : report.Polylines.PerMaterial)
    report.CurvesPerMaterial[material] = widen(d);
  report.Crossings = CountBoundaryCrossings(polygons);
  report.Topology = CompareTopology(labels, polygons);
  return report;
}

} // namespace labelmesher
