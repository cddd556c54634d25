// SPDX-License-Identifier: GPL-2.0-or-later
// Merges the cells that leaves emit into one SimplexMesh, keying vertices on the lattice.
#include "Fill/MeshAssembler.h"

#include <stdexcept>
#include <utility>

namespace labelmesher
{

MeshAssembler::MeshAssembler(int dimension)
{
  Mesh.Dimension = dimension;
}

std::int64_t MeshAssembler::Vertex(const LatticePoint& p)
{
  const std::uint64_t key = static_cast<std::uint64_t>(p[0]) | (static_cast<std::uint64_t>(p[1]) << 21) |
    (static_cast<std::uint64_t>(p[2]) << 42);
  auto [it, inserted] = Index.try_emplace(key, static_cast<std::int64_t>(Mesh.Points.size()));
  if (inserted)
    Mesh.Points.push_back({ (p[0] - 1) / 2.0, (p[1] - 1) / 2.0, Mesh.Dimension == 2 ? 0.0 : (p[2] - 1) / 2.0 });
  return it->second;
}

void MeshAssembler::AddCell(const std::array<LatticePoint, 4>& p, std::int32_t label)
{
  auto sub = [](const LatticePoint& a, const LatticePoint& b) {
    return LatticePoint{ a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  };
  std::int64_t ids[4];
  if (Mesh.Dimension == 2)
  {
    const LatticePoint u = sub(p[1], p[0]), v = sub(p[2], p[0]);
    const std::int64_t area = u[0] * v[1] - u[1] * v[0];
    if (area == 0)
      throw std::logic_error("degenerate triangle");
    ids[0] = Vertex(p[0]);
    ids[1] = Vertex(area > 0 ? p[1] : p[2]);
    ids[2] = Vertex(area > 0 ? p[2] : p[1]);
    Mesh.Connectivity.insert(Mesh.Connectivity.end(), ids, ids + 3);
  }
  else
  {
    const LatticePoint u = sub(p[1], p[0]), v = sub(p[2], p[0]), w = sub(p[3], p[0]);
    const std::int64_t volume = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
      u[2] * (v[0] * w[1] - v[1] * w[0]);
    if (volume == 0)
      throw std::logic_error("degenerate tetrahedron");
    ids[0] = Vertex(p[0]);
    ids[1] = Vertex(volume > 0 ? p[1] : p[2]);
    ids[2] = Vertex(volume > 0 ? p[2] : p[1]);
    ids[3] = Vertex(p[3]);
    Mesh.Connectivity.insert(Mesh.Connectivity.end(), ids, ids + 4);
  }
  Mesh.Materials.push_back(label);
}

SimplexMesh MeshAssembler::Release()
{
  Index.clear();
  return std::move(Mesh);
}

} // namespace labelmesher
