// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CubicTriangle_h
#define labelmesher_CubicTriangle_h

/**
 * @file CubicTriangle.h
 * A cubic Bézier triangle in the plane (dissertation section 2.5 and 4.2).
 *
 * Control points are stored in VTK's VTK_BEZIER_TRIANGLE order for degree 3,
 * so that a cell can be handed to VTK unchanged:
 *   0, 1, 2   corners (barycentric multi-indices 300, 030, 003)
 *   3, 4      edge 0→1  (210, 120)
 *   5, 6      edge 1→2  (021, 012)
 *   7, 8      edge 2→0  (102, 201)
 *   9         interior  (111)
 * Barycentric coordinates (u, v, w) weight corners 0, 1, 2; the reference
 * triangle is x̂ = v, ŷ = w (u = 1 - x̂ - ŷ), as in section 4.2.1.
 */

#include <array>

namespace labelmesher
{

using Point2 = std::array<double, 2>;

struct CubicTriangle
{
  std::array<Point2, 10> ControlPoints;
};

/// VTK index (0..9) of the control point with multi-index (i, j, k), i + j + k = 3.
int CubicControlPointIndex(int i, int j, int k);

/// The straight-sided triangle (a, b, c) as a cubic: edge points at 1/3, 2/3, interior at the centroid.
CubicTriangle StraightCubicTriangle(const Point2& a, const Point2& b, const Point2& c);

/// The point with barycentric coordinates (u, v, w), u + v + w = 1.
Point2 EvaluateCubicTriangle(const CubicTriangle& triangle, double u, double v, double w);

/// The cell's three corner angles (at control points 0, 1, 2), in degrees: at each corner, the
/// angle between its two edges' tangents there (towards their first inner control points); a
/// straight cell's interior angles. 0 when a tangent vanishes (a control point on its corner).
std::array<double, 3> CornerAngles(const CubicTriangle& triangle);
/// The smallest of them.
double SmallestCornerAngle(const CubicTriangle& triangle);

} // namespace labelmesher

#endif
