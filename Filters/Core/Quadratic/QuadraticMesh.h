// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QuadraticMesh_h
#define labelmesher_QuadraticMesh_h

/**
 * @file QuadraticMesh.h
 * A linear tetrahedral mesh made quadratic: one mid-node per edge (ten nodes a
 * cell, VTK_QUADRATIC_TETRA's order: corners, then the edges 0-1, 1-2, 2-0,
 * 0-3, 1-3, 2-3). A straight edge has its mid-node at the midpoint; a curved
 * one at midpoint + Scale × Offset, the curve then passing through the
 * edge's corners and that node (a Lagrange node at t = 1/2 is the quadratic's
 * point there; the Bézier control point is 2 m − (a + b)/2).
 *
 * Index space, as SimplexMesh (distances in voxels).
 */

#include "Mesh/SimplexMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

/// The corners of each of a tetrahedron's six edges, in VTK's order.
inline constexpr int kTetraEdges[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };

struct QuadraticMesh
{
  SimplexMesh Linear;                              ///< tetrahedra, positively oriented
  std::vector<std::array<std::int64_t, 2>> Edges; ///< corner ids, smaller first
  std::vector<std::int64_t> CellEdges;            ///< 6 edge ids per cell, kTetraEdges' order
  std::vector<Point3> Offset;                     ///< per edge: the fitted mid-node's displacement
  std::vector<double> Scales;                     ///< per edge: of Offset in [0, 1]; 0: straight

  std::size_t NumberOfCells() const { return Linear.NumberOfCells(); }
  bool Curved(std::size_t edge) const { return Scales[edge] > 0.0; }
  Point3 MidNode(std::size_t edge) const;
  /// The ten nodes of cell c (corners, then mid-nodes), in VTK's order.
  std::array<Point3, 10> Nodes(std::size_t c) const;
  bool CellIsCurved(std::size_t c) const;
};

/// The linear mesh with its edges numbered, every edge straight.
QuadraticMesh MakeQuadraticMesh(SimplexMesh linear);

/// The point of the quadratic tetrahedron with ten `nodes` at barycentric
/// coordinates l (l[k] the weight of corner k).
Point3 EvaluateQuadraticTetra(const std::array<Point3, 10>& nodes, const std::array<double, 4>& l);

} // namespace labelmesher

#endif
