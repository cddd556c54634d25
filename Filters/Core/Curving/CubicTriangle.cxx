// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file CubicTriangle.cxx
 * Cubic Bézier triangles in VTK_BEZIER_TRIANGLE point order (dissertation
 * section 2.5): T(u, v, w) = sum over i + j + k = 3 of 3!/(i! j! k!) u^i v^j w^k P_ijk.
 */

#include "Curving/CubicTriangle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace labelmesher
{

int CubicControlPointIndex(int i, int j, int k)
{
  // Indexed by (j, k); VTK numbers the corners, then edges 0→1, 1→2, 2→0
  // (each from its first corner), then the interior point.
  static constexpr int Index[4][4] = { { 0, 8, 7, 2 }, { 3, 9, 6, -1 }, { 4, 5, -1, -1 }, { 1, -1, -1, -1 } };
  if (i < 0 || j < 0 || k < 0 || i + j + k != 3)
    throw std::invalid_argument("CubicControlPointIndex: multi-index must satisfy i + j + k = 3");
  return Index[j][k];
}

CubicTriangle StraightCubicTriangle(const Point2& a, const Point2& b, const Point2& c)
{
  // The affine map is its own cubic Bézier form: P_ijk = (i a + j b + k c) / 3.
  CubicTriangle triangle;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j)
    {
      const int k = 3 - i - j;
      Point2& p = triangle.ControlPoints[CubicControlPointIndex(i, j, k)];
      for (int d = 0; d < 2; ++d)
        p[d] = (i * a[d] + j * b[d] + k * c[d]) / 3.0;
    }
  return triangle;
}

Point2 EvaluateCubicTriangle(const CubicTriangle& triangle, double u, double v, double w)
{
  const double pu[4] = { 1.0, u, u * u, u * u * u };
  const double pv[4] = { 1.0, v, v * v, v * v * v };
  const double pw[4] = { 1.0, w, w * w, w * w * w };
  static constexpr double Factorial[4] = { 1.0, 1.0, 2.0, 6.0 };
  Point2 result{ 0.0, 0.0 };
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j)
    {
      const int k = 3 - i - j;
      const double basis = 6.0 / (Factorial[i] * Factorial[j] * Factorial[k]) * pu[i] * pv[j] * pw[k];
      const Point2& p = triangle.ControlPoints[CubicControlPointIndex(i, j, k)];
      result[0] += basis * p[0];
      result[1] += basis * p[1];
    }
  return result;
}

std::array<double, 3> CornerAngles(const CubicTriangle& triangle)
{
  // Corner, then the inner control points of its two edges next to it (VTK order).
  static constexpr int Corner[3][3] = { { 0, 3, 8 }, { 1, 5, 4 }, { 2, 7, 6 } };
  std::array<double, 3> angles{};
  for (int k = 0; k < 3; ++k)
  {
    const Point2& p = triangle.ControlPoints[Corner[k][0]];
    const Point2& a = triangle.ControlPoints[Corner[k][1]];
    const Point2& b = triangle.ControlPoints[Corner[k][2]];
    const double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
    if (std::hypot(ax, ay) == 0.0 || std::hypot(bx, by) == 0.0)
    {
      angles[k] = 0.0;
      continue;
    }
    // atan2 of |cross| and dot: accurate near 0 and 180 degrees, unlike acos.
    angles[k] = std::atan2(std::abs(ax * by - ay * bx), ax * bx + ay * by) * 180.0 / 3.14159265358979323846;
  }
  return angles;
}

double SmallestCornerAngle(const CubicTriangle& triangle)
{
  const std::array<double, 3> angles = CornerAngles(triangle);
  return std::min({ angles[0], angles[1], angles[2] });
}

} // namespace labelmesher
