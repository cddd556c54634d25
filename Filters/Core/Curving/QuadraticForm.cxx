// SPDX-License-Identifier: GPL-2.0-or-later
// Cubic Bézier triangles that are exactly quadratic ones (degree elevation).
#include "Curving/QuadraticForm.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
namespace
{

/// VTK_BEZIER_TRIANGLE degree 3: corners of edge e are e and (e + 1) % 3, its inner points
/// 3 + 2e (nearer the first corner) and 4 + 2e; the interior point is 9.
constexpr int kInterior = 9;

double Distance(const Point2& p, const Point2& q) { return std::hypot(p[0] - q[0], p[1] - q[1]); }

} // namespace

std::array<Point2, 2> ElevateQuadratic(const Point2& a, const Point2& q, const Point2& b)
{
  return { Point2{ (a[0] + 2.0 * q[0]) / 3.0, (a[1] + 2.0 * q[1]) / 3.0 },
    Point2{ (2.0 * q[0] + b[0]) / 3.0, (2.0 * q[1] + b[1]) / 3.0 } };
}

Point2 NearestQuadraticControl(const Point2& a, const Point2& c1, const Point2& c2, const Point2& b)
{
  return { (3.0 * (c1[0] + c2[0]) - a[0] - b[0]) / 4.0, (3.0 * (c1[1] + c2[1]) - a[1] - b[1]) / 4.0 };
}

Point2 CubicMidpoint(const Point2& a, const Point2& c1, const Point2& c2, const Point2& b)
{
  return { (a[0] + 3.0 * (c1[0] + c2[0]) + b[0]) / 8.0, (a[1] + 3.0 * (c1[1] + c2[1]) + b[1]) / 8.0 };
}

void MakeQuadraticForm(CurvedMesh& mesh)
{
  std::vector<Point2>& p = mesh.ControlPoints;
  for (const auto& [edge, ids] : mesh.EdgeControlPoints)
  {
    const Point2 &a = p[edge.first], &b = p[edge.second];
    const Point2 q = NearestQuadraticControl(a, p[ids[0]], p[ids[1]], b);
    const std::array<Point2, 2> inner = ElevateQuadratic(a, q, b);
    p[ids[0]] = inner[0];
    p[ids[1]] = inner[1];
  }
  for (const auto& ids : mesh.Cells)
  {
    Point2 interior{ 0.0, 0.0 };
    for (int e = 0; e < 3; ++e)
    {
      const Point2 q =
        NearestQuadraticControl(p[ids[e]], p[ids[3 + 2 * e]], p[ids[4 + 2 * e]], p[ids[(e + 1) % 3]]);
      interior[0] += q[0] / 3.0;
      interior[1] += q[1] / 3.0;
    }
    p[ids[kInterior]] = interior;
  }
}

double DistanceFromQuadraticForm(const CubicTriangle& triangle)
{
  const auto& p = triangle.ControlPoints;
  double largest = 0.0;
  Point2 interior{ 0.0, 0.0 };
  for (int e = 0; e < 3; ++e)
  {
    const Point2 &a = p[e], &b = p[(e + 1) % 3];
    const Point2 q = NearestQuadraticControl(a, p[3 + 2 * e], p[4 + 2 * e], b);
    const std::array<Point2, 2> inner = ElevateQuadratic(a, q, b);
    largest = std::max({ largest, Distance(inner[0], p[3 + 2 * e]), Distance(inner[1], p[4 + 2 * e]) });
    interior[0] += q[0] / 3.0;
    interior[1] += q[1] / 3.0;
  }
  return std::max(largest, Distance(interior, p[kInterior]));
}

} // namespace labelmesher
