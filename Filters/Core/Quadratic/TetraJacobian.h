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
 * The bound is conservative (no subdivision): a cell it cannot certify is
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

/// min / max of the coefficients when the smallest is positive; otherwise
/// that smallest coefficient divided by the largest absolute one (≤ 0: the
/// cell is not proved valid).
double CertifiedScaledJacobian(const std::array<Point3, 10>& nodes);

} // namespace labelmesher

#endif
