// SPDX-License-Identifier: GPL-2.0-or-later
// Edges numbered once, mid-nodes from their offsets, and the quadratic map of a cell.
#include "Quadratic/QuadraticMesh.h"

#include "Support/Geometry.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace labelmesher
{
using namespace geometry;

Point3 QuadraticMesh::MidNode(std::size_t edge) const
{
  const Point3& a = Linear.Points[static_cast<std::size_t>(Edges[edge][0])];
  const Point3& b = Linear.Points[static_cast<std::size_t>(Edges[edge][1])];
  Point3 m = Scale(Add(a, b), 0.5);
  if (Scales[edge] > 0.0)
    m = Add(m, Scale(Offset[edge], Scales[edge]));
  return m;
}

std::array<Point3, 10> QuadraticMesh::Nodes(std::size_t c) const
{
  std::array<Point3, 10> nodes;
  const std::int64_t* v = Linear.Cell(c);
  for (int k = 0; k < 4; ++k)
    nodes[k] = Linear.Points[static_cast<std::size_t>(v[k])];
  for (int e = 0; e < 6; ++e)
    nodes[4 + e] = MidNode(static_cast<std::size_t>(CellEdges[c * 6 + e]));
  return nodes;
}

bool QuadraticMesh::CellIsCurved(std::size_t c) const
{
  for (int e = 0; e < 6; ++e)
    if (Curved(static_cast<std::size_t>(CellEdges[c * 6 + e])))
      return true;
  return false;
}

QuadraticMesh MakeQuadraticMesh(SimplexMesh linear)
{
  QuadraticMesh mesh;
  mesh.Linear = std::move(linear);
  const std::size_t cells = mesh.Linear.NumberOfCells();
  mesh.CellEdges.resize(cells * 6);
  std::unordered_map<std::uint64_t, std::int64_t> edgeOf;
  edgeOf.reserve(cells * 2);
  const auto points = static_cast<std::uint64_t>(mesh.Linear.Points.size());
  for (std::size_t c = 0; c < cells; ++c)
  {
    const std::int64_t* v = mesh.Linear.Cell(c);
    for (int e = 0; e < 6; ++e)
    {
      std::int64_t a = v[kTetraEdges[e][0]], b = v[kTetraEdges[e][1]];
      if (a > b)
        std::swap(a, b);
      const std::uint64_t key = static_cast<std::uint64_t>(a) * points + static_cast<std::uint64_t>(b);
      const auto [it, added] = edgeOf.emplace(key, static_cast<std::int64_t>(mesh.Edges.size()));
      if (added)
        mesh.Edges.push_back({ a, b });
      mesh.CellEdges[c * 6 + e] = it->second;
    }
  }
  mesh.Offset.assign(mesh.Edges.size(), Point3{ 0.0, 0.0, 0.0 });
  mesh.Scales.assign(mesh.Edges.size(), 0.0);
  return mesh;
}

Point3 EvaluateQuadraticTetra(const std::array<Point3, 10>& nodes, const std::array<double, 4>& l)
{
  // Lagrange basis of degree 2: corners l(2l - 1), edge (i, j) 4 l_i l_j.
  Point3 x{ 0.0, 0.0, 0.0 };
  for (int k = 0; k < 4; ++k)
    x = Add(x, Scale(nodes[k], l[k] * (2.0 * l[k] - 1.0)));
  for (int e = 0; e < 6; ++e)
    x = Add(x, Scale(nodes[4 + e], 4.0 * l[kTetraEdges[e][0]] * l[kTetraEdges[e][1]]));
  return x;
}

} // namespace labelmesher
