// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QuadraticCorners_h
#define labelmesher_QuadraticCorners_h

/**
 * @file QuadraticCorners.h
 * The corners of a quadratic tetrahedron keep the linear mesh's angle bound
 * (the 3D form of the 2D curver's corner angles, Curving/CornerHandles.h).
 * At corner k the cell's map is, to first order, the affine map of the
 * tangent trihedron spanned by the tangents of its three edges there (the
 * quadratic through a, mid-node m and b leaves a with tangent 4m - 3a - b).
 * The corner's angles are that trihedron's dihedral angles along its three
 * edges: for a straight cell exactly the tetrahedron's dihedral angles at the
 * edges through k, which the decimator bounded. So the bound a curved cell
 * must keep is the one the linear mesh holds, measured where the curving
 * bends it most sharply; and a corner whose three edges are straight is the
 * linear mesh's corner.
 *
 * Exact up to round-off (no sampling): the tangents are polynomial
 * coefficients, not differences of points.
 */

#include "Mesh/SimplexMesh.h"

#include <array>

namespace labelmesher
{

/// The three dihedral angles of corner k's tangent trihedron, degrees, along
/// the edges to the other corners in increasing order (k's edges in
/// kTetraEdges' numbering: see CornerEdges). 0 for a degenerate trihedron.
std::array<double, 3> CornerDihedralAngles(const std::array<Point3, 10>& nodes, int corner);

/// The smallest corner angle over the four corners.
double SmallestCornerAngle(const std::array<Point3, 10>& nodes);

/// The three edges (kTetraEdges' indices, 0-5) that meet at `corner`, in the
/// order of CornerDihedralAngles.
std::array<int, 3> CornerEdges(int corner);

} // namespace labelmesher

#endif
