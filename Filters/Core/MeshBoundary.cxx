// SPDX-License-Identifier: GPL-2.0-or-later
#include "MeshBoundary.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace labelmesher
{
namespace
{
struct FaceKeyHash
{
  std::size_t operator()(const std::array<std::int64_t, 3>& k) const
  {
    std::size_t h = 1469598103934665603ull;
    for (std::int64_t v : k)
      h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
    return h;
  }
};
} // namespace

MaterialInterfaces ExtractMaterialInterfaces(const SimplexMesh& mesh)
{
  const int n = mesh.VerticesPerCell(); // face = cell minus one vertex
  struct Use
  {
    std::int64_t Owner;  ///< first cell seen with this face
    int Opposite;        ///< owner's vertex not on the face
    std::int64_t Other;  ///< second cell, or -1 (outside of the mesh)
  };
  // Only a face whose vertices all touch two materials (or the mesh's own
  // border) can separate materials: mark such vertices first, so that the
  // hash below holds the faces near interfaces, not every face of the mesh.
  constexpr std::int64_t kUnseen = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t kMixed = kUnseen + 1;
  std::vector<std::int64_t> vertexMaterial(mesh.Points.size(), kUnseen);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* cell = mesh.Cell(c);
    for (int i = 0; i < n; ++i)
    {
      std::int64_t& m = vertexMaterial[cell[i]];
      if (m == kUnseen)
        m = mesh.Materials[c];
      else if (m != mesh.Materials[c])
        m = kMixed;
    }
  }
  // Vertices on the border of the mesh: the ends of faces used once. Found on
  // the fly below: a face with an unmixed vertex is still hashed when that
  // vertex lies on the bounding box, where the mesh may end.
  Point3 lo = mesh.Points.empty() ? Point3{ 0, 0, 0 } : mesh.Points[0], hi = lo;
  for (const Point3& p : mesh.Points)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  auto candidate = [&](std::int64_t v) {
    if (vertexMaterial[v] == kMixed)
      return true;
    const Point3& p = mesh.Points[v];
    for (int a = 0; a < mesh.Dimension; ++a)
      if (p[a] == lo[a] || p[a] == hi[a])
        return true;
    return false;
  };

  std::unordered_map<std::array<std::int64_t, 3>, Use, FaceKeyHash> faces;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* cell = mesh.Cell(c);
    for (int o = 0; o < n; ++o)
    {
      bool possible = true;
      for (int i = 0; i < n && possible; ++i)
        possible = i == o || candidate(cell[i]);
      if (!possible)
        continue;
      std::array<std::int64_t, 3> key{ -1, -1, -1 };
      int k = 0;
      for (int i = 0; i < n; ++i)
        if (i != o)
          key[k++] = cell[i];
      // Sort the (two or three) ids: the key must not depend on vertex order.
      if (key[0] > key[1])
        std::swap(key[0], key[1]);
      if (k == 3 && key[1] > key[2])
        std::swap(key[1], key[2]);
      if (key[0] > key[1])
        std::swap(key[0], key[1]);
      auto [it, inserted] = faces.try_emplace(key, Use{ static_cast<std::int64_t>(c), o, -1 });
      if (inserted)
        continue;
      if (mesh.Materials[it->second.Owner] == mesh.Materials[c])
        faces.erase(it); // interior to one material: not part of the boundary
      else
        it->second.Other = static_cast<std::int64_t>(c);
    }
  }
  MaterialInterfaces out;
  out.Faces.Dimension = mesh.Dimension - 1;
  out.Faces.Points = mesh.Points;
  for (const auto& [key, use] : faces)
  {
    const std::int32_t inside = mesh.Materials[use.Owner];
    const std::int32_t outside = use.Other >= 0 ? mesh.Materials[use.Other] : 0;
    if (inside == outside)
      continue;
    // Orient the face outward from its owner cell: the owner's vertices in
    // order with the opposite one removed, flipped for odd positions.
    const std::int64_t* cell = mesh.Cell(use.Owner);
    std::int64_t f[3] = { -1, -1, -1 };
    int k = 0;
    for (int i = 0; i < n; ++i)
      if (i != use.Opposite)
        f[k++] = cell[i];
    const bool flip = mesh.Dimension == 3 ? (use.Opposite % 2 == 1) : (use.Opposite == 1);
    if (flip)
      std::swap(f[0], f[1]);
    out.Faces.Connectivity.insert(out.Faces.Connectivity.end(), f, f + k);
    out.Faces.Materials.push_back(inside);
    out.Sides.emplace_back(inside, outside);
  }
  return out;
}

} // namespace labelmesher
