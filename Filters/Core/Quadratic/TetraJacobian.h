// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_TetraJacobian_h
#define labelmesher_TetraJacobian_h

/**
 * @file TetraJacobian.h
 * Validity of a quadratic tetrahedron proved, never sampled (the 3D form of
 * dissertation section 4.2). Its map is a quadratic Bézier tetrahedron, so each
 * column of the Jacobian is linear in the barycentric coordinates and det J
 * is a cubic: a Bernstein polynomial with 20 coefficients, computed here
 * exactly (up to round-off) from the ten nodes. det J lies between the
 * smallest and the largest coefficient everywhere in the cell (the Bernstein
 * basis is a partition of unity and non-negative), so
 *   - all coefficients positive proves det J > 0 in the whole closed cell;
 *   - min coefficient / max coefficient is a lower bound of the cell's scaled
 *     Jacobian min det J / max det J (1 for a straight cell).
 * Where the coefficients are not conclusive, the cell is subdivided (red
 * refinement of its reference tetrahedron, the map restricted to each piece
 * being again a quadratic tetrahedron, whose det J is the cell's times the
 * piece's share of the volume): the bounds tighten towards the true extremes.
 * Still conservative: a cell the bound cannot certify within the depth is
 * treated as failing, and its curves are pulled back towards straight.
 */

#include "Mesh/SimplexMesh.h"

#include <array>

namespace labelmesher
{

/// The Bernstein coefficients of det J of the quadratic tetrahedron with ten
/// nodes in VTK's order (QuadraticMesh.h), with J = dx/d(l1, l2, l3): for a
/// straight cell every coefficient is six times its volume.
std::array<double, 20> JacobianCoefficients(const std::array<Point3, 10>& nodes);

/// A lower bound of min det J / max det J: the smallest coefficient over the
/// largest (over the pieces), when the smallest is positive beyond round-off
/// (1e-12 of the largest); 0 when it is positive but not beyond; otherwise
/// that smallest divided by the largest absolute one (≤ 0: not proved valid).
/// Pieces holding the bound below `target` are refined, up to `depth` levels
/// (8^depth pieces at most); 0 does not subdivide.
double CertifiedScaledJacobian(const std::array<Point3, 10>& nodes, double target = 1.0, int depth = 0);

} // namespace labelmesher

#endif
