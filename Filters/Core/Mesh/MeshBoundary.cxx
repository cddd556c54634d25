// SPDX-License-Identifier: GPL-2.0-or-later
// Extracts the mesh boundary: the faces whose two sides carry different materials.
#include "Mesh/MeshBoundary.h"

#include "Mesh/CellFacets.h"

#include "Support/ParallelChunks.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace labelmesher
{
namespace
{
/// One cell's use of a face: the face's sorted vertex ids (the third -1 in 2D),
/// the cell, and the cell's vertex not on the face.
struct FaceUse
{
  std::array<std::int64_t, 3> Key;
  std::int64_t Cell;
  int Opposite;
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
  // the fly below: a face with an unmixed vertex is still kept when that
  // vertex lies on the bounding box, where the mesh may end.
  Point3 lo = mesh.Points.empty() ? Point3{ 0, 0, 0 } : mesh.Points[0], hi = lo;
  for (const Point3& p : mesh.Points)
    for (int a = 0; a < 3; ++a)
      lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  std::vector<unsigned char> candidate(mesh.Points.size());
  for (std::size_t v = 0; v < candidate.size(); ++v)
  {
    bool onBox = false;
    for (int a = 0; a < mesh.Dimension; ++a)
      onBox = onBox || mesh.Points[v][a] == lo[a] || mesh.Points[v][a] == hi[a];
    candidate[v] = vertexMaterial[v] == kMixed || onBox;
  }

  // Every candidate face once per cell using it, sorted by its vertex ids:
  // a face used by two cells appears twice in a row. Sorting beats a hash map
  // of millions of faces (no node per face) and gives a deterministic order.
  // Runs of cells are scanned on all cores and concatenated in cell order.
  const std::size_t run = 65536;
  std::vector<std::vector<FaceUse>> runs((mesh.NumberOfCells() + run - 1) / run);
  ParallelChunks(mesh.NumberOfCells(), run, [&](unsigned, std::size_t begin, std::size_t end) {
    std::vector<FaceUse>& out = runs[begin / run];
    for (std::size_t c = begin; c < end; ++c)
    {
      const std::int64_t* cell = mesh.Cell(c);
      int candidates = 0;
      for (int i = 0; i < n; ++i)
        candidates += candidate[cell[i]];
      if (candidates < n - 1)
        continue;
      for (int o = 0; o < n; ++o)
      {
        if (candidates == n - 1 && candidate[cell[o]])
          continue; // the face without o has a vertex that is not a candidate
        out.push_back(FaceUse{ SortedFacetOpposite(cell, mesh.Dimension, o), static_cast<std::int64_t>(c), o });
      }
    }
  });
  std::vector<FaceUse> uses;
  std::size_t total = 0;
  for (const auto& r : runs)
    total += r.size();
  uses.reserve(total);
  for (auto& r : runs)
  {
    uses.insert(uses.end(), r.begin(), r.end());
    r = std::vector<FaceUse>();
  }
  ParallelSort(uses, [](const FaceUse& a, const FaceUse& b) {
    // Spelled out: std::array's operators go through memcmp, a tenth of the
    // whole mesher's time on digimouse.
    if (a.Key[0] != b.Key[0])
      return a.Key[0] < b.Key[0];
    if (a.Key[1] != b.Key[1])
      return a.Key[1] < b.Key[1];
    if (a.Key[2] != b.Key[2])
      return a.Key[2] < b.Key[2];
    return a.Cell < b.Cell;
  });
  std::vector<Use> faces;
  for (std::size_t u = 0; u < uses.size();)
  {
    std::size_t next = u + 1;
    while (next < uses.size() && uses[next].Key[0] == uses[u].Key[0] && uses[next].Key[1] == uses[u].Key[1] &&
      uses[next].Key[2] == uses[u].Key[2])
      ++next;
    const std::int64_t other = next - u >= 2 ? uses[u + 1].Cell : -1;
    if (other < 0 || mesh.Materials[uses[u].Cell] != mesh.Materials[other])
      faces.push_back(Use{ uses[u].Cell, uses[u].Opposite, other });
    u = next;
  }
  uses = std::vector<FaceUse>();
  MaterialInterfaces out;
  out.Faces.Dimension = mesh.Dimension - 1;
  out.Faces.Points = mesh.Points;
  for (const Use& use : faces)
  {
    const std::int32_t inside = mesh.Materials[use.Owner];
    const std::int32_t outside = use.Other >= 0 ? mesh.Materials[use.Other] : 0;
    if (inside == outside)
      continue;
    // Oriented outward from its owner cell.
    std::array<std::int64_t, 3> f = FacetOpposite(mesh.Cell(use.Owner), mesh.Dimension, use.Opposite);
    if (FacetFlips(mesh.Dimension, use.Opposite))
      std::swap(f[0], f[1]);
    out.Faces.Connectivity.insert(out.Faces.Connectivity.end(), f.begin(), f.begin() + mesh.Dimension);
    out.Faces.Materials.push_back(inside);
    out.Sides.emplace_back(inside, outside);
  }
  return out;
}

} // namespace labelmesher
