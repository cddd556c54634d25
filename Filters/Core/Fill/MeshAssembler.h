// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MeshAssembler_h
#define labelmesher_MeshAssembler_h

/**
 * @file MeshAssembler.h
 * Collects the cells that leaves emit into one SimplexMesh. Vertices are keyed
 * by their doubled-lattice coordinates (LeafBox.h), so a point that several
 * leaves produce becomes one vertex: the mesh is conforming exactly when the
 * leaves triangulate every shared face the same way. Cells are oriented
 * positively here, from exact integer determinants.
 */

#include "Mesh/SimplexMesh.h"

#include <array>
#include <cstdint>
#include <unordered_map>

namespace labelmesher
{

using LatticePoint = std::array<std::int64_t, 3>;

class MeshAssembler
{
public:
  explicit MeshAssembler(int dimension);

  std::int64_t Vertex(const LatticePoint& p);
  /// A tetrahedron (3D) or triangle (2D, p[3] ignored) of material `label`.
  void AddCell(const std::array<LatticePoint, 4>& p, std::int32_t label);

  std::size_t NumberOfCells() const { return Mesh.Materials.size(); }
  SimplexMesh Release();

private:
  SimplexMesh Mesh;
  std::unordered_map<std::uint64_t, std::int64_t> Index;
};

} // namespace labelmesher

#endif
