// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_TriangleJacobian_h
#define labelmesher_TriangleJacobian_h

/**
 * @file TriangleJacobian.h
 * Validity of a quadratic triangle proved, never sampled: the 2D sibling of
 * TetraJacobian.h (section 4.2 of the dissertation, for degree 2). The map is
 * a quadratic Bézier triangle, each column of its Jacobian is linear in the
 * barycentric coordinates, so det J is a quadratic: six Bernstein
 * coefficients, computed here exactly (up to round-off) from the six nodes.
 * They bound det J over the closed triangle (the basis is a non-negative
 * partition of unity), so
 *   - all coefficients positive proves det J > 0 everywhere in the cell;
 *   - min coefficient / max coefficient bounds the scaled Jacobian
 *     min det J / max det J from below (1 for a straight triangle).
 * Where they are not conclusive the cell is subdivided (the reference
 * triangle into four, the map restricted to each piece being again a
 * quadratic triangle whose det J is the cell's times a quarter).
 *
 * Nodes in VTK_QUADRATIC_TRIANGLE's order: corners 0-2, then the mid-nodes of
 * edges 0-1, 1-2, 2-0; the triangle lies in a plane z = constant of index
 * space (a 2D image's), and det J is taken in (x, y): positive for a
 * counter-clockwise cell.
 */

#include "Mesh/SimplexMesh.h"

#include <array>

namespace labelmesher
{

/// The corners of each of a triangle's three edges, in VTK's order.
inline constexpr int kTriangleEdges[3][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 } };

/// The point of the quadratic triangle with six `nodes` at barycentric
/// coordinates l (l[k] the weight of corner k).
Point3 EvaluateQuadraticTriangle(const std::array<Point3, 6>& nodes, const std::array<double, 3>& l);

/// The Bernstein coefficients of det J, J = dx/d(l1, l2), in the order of the
/// multi-indices (2,0,0), (0,2,0), (0,0,2), (1,1,0), (0,1,1), (1,0,1): for a
/// straight cell every coefficient is twice its signed area.
std::array<double, 6> TriangleJacobianCoefficients(const std::array<Point3, 6>& nodes);

/// A lower bound of min det J / max det J, as CertifiedScaledJacobian
/// (TetraJacobian.h) for tetrahedra: the smallest coefficient over the
/// largest, over the pieces of up to `depth` levels of subdivision of the
/// pieces that hold it below `target`; 0 when the smallest is positive but
/// not beyond round-off; ≤ 0 when not proved valid.
double CertifiedTriangleScaledJacobian(const std::array<Point3, 6>& nodes, double target = 1.0, int depth = 0);

} // namespace labelmesher

#endif
