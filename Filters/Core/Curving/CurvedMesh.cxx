// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file CurvedMesh.cxx
 * The straight-sided cubic mesh a linear triangle mesh starts as (section 4.3:
 * "the two points which are located in the one third and two thirds ratio of
 * each edge ... together with the mesh vertices are the original positions of
 * the control points"). Ids: the mesh vertices first (same ids), then two per
 * edge in order of first use, then one interior point per cell.
 */

#include "Curving/CurvedMesh.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace labelmesher
{

namespace
{
Point2 Between(const Point2& a, const Point2& b, double t)
{
  return { a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) };
}
} // namespace

CubicTriangle CurvedMesh::Cell(std::size_t c) const
{
  CubicTriangle triangle;
  for (int k = 0; k < 10; ++k)
    triangle.ControlPoints[k] = ControlPoints[Cells[c][k]];
  return triangle;
}

std::array<std::int64_t, 2> CurvedMesh::EdgePoints(std::int64_t a, std::int64_t b) const
{
  const auto it = EdgeControlPoints.find({ std::min(a, b), std::max(a, b) });
  if (it == EdgeControlPoints.end())
    throw std::out_of_range("no mesh edge " + std::to_string(a) + "-" + std::to_string(b));
  const std::array<std::int64_t, 2>& ids = it->second;
  return a < b ? ids : std::array<std::int64_t, 2>{ ids[1], ids[0] };
}

CurvedMesh MakeStraightCurvedMesh(const SimplexMesh& mesh)
{
  if (mesh.Dimension != 2)
    throw std::invalid_argument("a curved mesh needs a 2D triangle mesh");
  CurvedMesh curved;
  curved.NumberOfVertices = static_cast<std::int64_t>(mesh.Points.size());
  curved.ControlPoints.reserve(mesh.Points.size() + 3 * mesh.NumberOfCells());
  for (const Point3& p : mesh.Points)
    curved.ControlPoints.push_back({ p[0], p[1] });
  curved.Materials = mesh.Materials;
  curved.Cells.resize(mesh.NumberOfCells());

  // VTK order: edge 0→1 at slots 3, 4, edge 1→2 at 5, 6, edge 2→0 at 7, 8,
  // each pair ordered from the edge's first corner to its second.
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* v = mesh.Cell(c);
    auto& ids = curved.Cells[c];
    for (int e = 0; e < 3; ++e)
    {
      const std::int64_t a = v[e], b = v[(e + 1) % 3];
      ids[e] = a;
      const std::pair<std::int64_t, std::int64_t> key{ std::min(a, b), std::max(a, b) };
      auto [it, inserted] = curved.EdgeControlPoints.try_emplace(key);
      if (inserted)
      {
        const Point2 p = curved.ControlPoints[key.first], q = curved.ControlPoints[key.second];
        const auto first = static_cast<std::int64_t>(curved.ControlPoints.size());
        curved.ControlPoints.push_back(Between(p, q, 1.0 / 3.0));
        curved.ControlPoints.push_back(Between(p, q, 2.0 / 3.0));
        it->second = { first, first + 1 };
      }
      const bool forward = a < b;
      ids[3 + 2 * e] = it->second[forward ? 0 : 1];
      ids[4 + 2 * e] = it->second[forward ? 1 : 0];
    }
  }
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    auto& ids = curved.Cells[c];
    const Point2 &a = curved.ControlPoints[ids[0]], &b = curved.ControlPoints[ids[1]],
                 &d = curved.ControlPoints[ids[2]];
    ids[9] = static_cast<std::int64_t>(curved.ControlPoints.size());
    curved.ControlPoints.push_back({ (a[0] + b[0] + d[0]) / 3.0, (a[1] + b[1] + d[1]) / 3.0 });
  }
  return curved;
}

} // namespace labelmesher
