// SPDX-License-Identifier: GPL-2.0-or-later
// Dihedral angles of the tangent trihedron at each corner of a quadratic tetrahedron.
#include "Quadratic/QuadraticCorners.h"

#include "Quadratic/QuadraticMesh.h"
#include "Support/Geometry.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
using namespace geometry;

std::array<int, 3> CornerEdges(int corner)
{
  std::array<int, 3> edges{ -1, -1, -1 };
  for (int other = 0, n = 0; other < 4; ++other)
    if (other != corner)
      for (int e = 0; e < 6; ++e)
        if ((kTetraEdges[e][0] == corner && kTetraEdges[e][1] == other) ||
          (kTetraEdges[e][1] == corner && kTetraEdges[e][0] == other))
          edges[static_cast<std::size_t>(n++)] = e;
  return edges;
}

std::array<double, 3> CornerDihedralAngles(const std::array<Point3, 10>& nodes, int corner)
{
  const Point3& a = nodes[static_cast<std::size_t>(corner)];
  std::array<Point3, 3> tangent;
  const std::array<int, 3> edges = CornerEdges(corner);
  for (int i = 0; i < 3; ++i)
  {
    const int e = edges[static_cast<std::size_t>(i)];
    const int other = kTetraEdges[e][0] == corner ? kTetraEdges[e][1] : kTetraEdges[e][0];
    // d/dt of (1-t)(1-2t) a + 4t(1-t) m + t(2t-1) b at t = 0.
    tangent[static_cast<std::size_t>(i)] =
      Sub(Sub(Scale(nodes[static_cast<std::size_t>(4 + e)], 4.0), Scale(a, 3.0)), nodes[static_cast<std::size_t>(other)]);
  }
  std::array<double, 3> angles{ 0.0, 0.0, 0.0 };
  for (int i = 0; i < 3; ++i)
  {
    const Point3& along = tangent[static_cast<std::size_t>(i)];
    const double length = Norm(along);
    if (length == 0.0)
      continue;
    const Point3 unit = Scale(along, 1.0 / length);
    // The other two tangents projected on the plane normal to this edge: the angle between them
    // is the dihedral angle between the trihedron's faces through the edge.
    const Point3& p = tangent[static_cast<std::size_t>((i + 1) % 3)];
    const Point3& q = tangent[static_cast<std::size_t>((i + 2) % 3)];
    const Point3 u = Sub(p, Scale(unit, Dot(p, unit)));
    const Point3 w = Sub(q, Scale(unit, Dot(q, unit)));
    // atan2(0, 0) = 0: a degenerate trihedron has a zero angle.
    angles[static_cast<std::size_t>(i)] = std::atan2(Norm(Cross(u, w)), Dot(u, w)) * 180.0 / 3.14159265358979323846;
  }
  return angles;
}

double SmallestCornerAngle(const std::array<Point3, 10>& nodes)
{
  double smallest = 180.0;
  for (int k = 0; k < 4; ++k)
    for (double angle : CornerDihedralAngles(nodes, k))
      smallest = std::min(smallest, angle);
  return smallest;
}

} // namespace labelmesher
