// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QuadraticForm_h
#define labelmesher_QuadraticForm_h

/**
 * @file QuadraticForm.h
 * Quadratic triangles inside the cubic curver (CurvingParameters::Order 2).
 *
 * A quadratic Bézier curve a, q, b is exactly the cubic a, (a + 2q)/3,
 * (2q + b)/3, b (degree elevation), and a quadratic triangle with edge control
 * points q01, q12, q20 is exactly the cubic one with those edges and interior
 * point (q01 + q12 + q20)/3. The curver certifies cubic cells (validity and
 * scaled Jacobian by Bernstein bounds, corners, distances, crossings), so a
 * mesh whose every cell has this form carries the same proofs as 6-node
 * triangles, whose mid-nodes are the curves' points at t = 1/2,
 * (a + 2q + b)/4. The untangler moves interior control points freely; its
 * result is brought back to this form (the least-squares quadratic of each
 * edge) and certified again.
 */

#include "Curving/CurvedMesh.h"

#include <array>

namespace labelmesher
{

/// The inner control points of the cubic that is the quadratic a, q, b.
std::array<Point2, 2> ElevateQuadratic(const Point2& a, const Point2& q, const Point2& b);

/// The control point q of the quadratic whose elevation is nearest to the cubic a, c1, c2, b
/// (least squares over the two inner points: q = (3 c1 - a + 3 c2 - b) / 4; exact when the cubic
/// is an elevated quadratic).
Point2 NearestQuadraticControl(const Point2& a, const Point2& c1, const Point2& c2, const Point2& b);

/// Replaces every edge of `mesh` by the elevation of its nearest quadratic and every cell's
/// interior point by the elevated one. Vertices do not move; edges that are quadratic already
/// keep their shape (up to rounding).
void MakeQuadraticForm(CurvedMesh& mesh);

/// The point at t = 1/2 of the cubic a, c1, c2, b: a quadratic edge's Lagrange mid-node.
Point2 CubicMidpoint(const Point2& a, const Point2& c1, const Point2& c2, const Point2& b);

/// The largest distance between `triangle`'s edge and interior control points and those of
/// the elevation of its nearest quadratic triangle: 0 (up to rounding) when it is quadratic.
double DistanceFromQuadraticForm(const CubicTriangle& triangle);

} // namespace labelmesher

#endif
