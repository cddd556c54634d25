// SPDX-License-Identifier: GPL-2.0-or-later
// Splits the triangles with two edges on one smooth chain before curving (they would have det J = 0).
#include "Curving/BoundaryEars.h"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace labelmesher
{
namespace
{

using EdgeKey = std::uint64_t;

EdgeKey Key(std::int64_t a, std::int64_t b)
{
  if (a > b)
    std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) ^ static_cast<std::uint64_t>(b);
}

/// Chain edges, and the vertices where a chain passes smoothly (every vertex of
/// a closed chain, the inner vertices of an open one).
struct ChainGeometry
{
  std::unordered_set<EdgeKey> Edges;
  std::vector<bool> Smooth;
};

ChainGeometry DescribeChains(const std::vector<InterfaceChain>& chains, std::size_t points)
{
  ChainGeometry g;
  g.Smooth.assign(points, false);
  for (const InterfaceChain& chain : chains)
  {
    const std::size_t n = chain.Vertices.size();
    const std::size_t segments = chain.Closed ? n : n - 1;
    for (std::size_t s = 0; s < segments; ++s)
      g.Edges.insert(Key(chain.Vertices[s], chain.Vertices[(s + 1) % n]));
    for (std::size_t k = chain.Closed ? 0 : 1; k < (chain.Closed ? n : n - 1); ++k)
      g.Smooth[static_cast<std::size_t>(chain.Vertices[k])] = true;
  }
  return g;
}

/// The edge opposite the ear vertex of cell c, as (position in the cell of its
/// first vertex), or -1 when c is not an ear.
int EarEdge(const SimplexMesh& mesh, std::size_t c, const ChainGeometry& g)
{
  const std::int64_t* v = mesh.Cell(c);
  for (int k = 0; k < 3; ++k)
  {
    const std::int64_t apex = v[k];
    if (!g.Smooth[static_cast<std::size_t>(apex)])
      continue;
    if (g.Edges.count(Key(apex, v[(k + 1) % 3])) && g.Edges.count(Key(apex, v[(k + 2) % 3])))
      return (k + 1) % 3; // the edge v[k+1] -> v[k+2]
  }
  return -1;
}

} // namespace

std::vector<std::int64_t> EarVertices(const SimplexMesh& mesh, const std::vector<InterfaceChain>& chains)
{
  const ChainGeometry g = DescribeChains(chains, mesh.Points.size());
  std::vector<std::int64_t> apexes;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    // Every corner of the cell that is one (a lone triangle of a material, its three edges one
    // closed chain, has three), not only the first EarEdge finds.
    const std::int64_t* v = mesh.Cell(c);
    for (int k = 0; k < 3; ++k)
      if (g.Smooth[static_cast<std::size_t>(v[k])] && g.Edges.count(Key(v[k], v[(k + 1) % 3])) &&
        g.Edges.count(Key(v[k], v[(k + 2) % 3])))
        apexes.push_back(v[k]);
  }
  std::sort(apexes.begin(), apexes.end());
  apexes.erase(std::unique(apexes.begin(), apexes.end()), apexes.end());
  return apexes;
}

std::vector<InterfaceChain> BreakChainsAt(
  const std::vector<InterfaceChain>& chains, const std::vector<std::int64_t>& vertices)
{
  auto breaks = [&vertices](std::int64_t v) { return std::binary_search(vertices.begin(), vertices.end(), v); };
  std::vector<InterfaceChain> out;
  for (const InterfaceChain& chain : chains)
  {
    const std::size_t n = chain.Vertices.size();
    // Where the walk starts: a closed chain at its first break (then it ends there too).
    std::size_t start = 0;
    if (chain.Closed)
    {
      while (start < n && !breaks(chain.Vertices[start]))
        ++start;
      if (start == n)
      {
        out.push_back(chain); // no break on it
        continue;
      }
    }
    const std::size_t length = chain.Closed ? n + 1 : n; // vertices walked, the first again when closed
    InterfaceChain piece{ {}, false, chain.FirstMaterial, chain.SecondMaterial };
    for (std::size_t i = 0; i < length; ++i)
    {
      const std::int64_t v = chain.Vertices[(start + i) % n];
      piece.Vertices.push_back(v);
      const bool inner = i > 0 && i + 1 < length;
      if (inner && breaks(v))
      {
        out.push_back(piece);
        piece.Vertices = { v };
      }
    }
    out.push_back(piece);
  }
  return out;
}

std::size_t SplitBoundaryEars(
  SimplexMesh& mesh, std::vector<InterfaceChain>& chains, const Box2& border, int maximumRounds)
{
  std::size_t splits = 0;
  for (int round = 0; round < maximumRounds; ++round)
  {
    const ChainGeometry g = DescribeChains(chains, mesh.Points.size());
    // Edges to split this round; a cell takes part in one split at most, so
    // that every split sees the cells as they were at the start of the round.
    std::vector<bool> busy(mesh.NumberOfCells(), false);
    std::unordered_map<EdgeKey, std::vector<std::size_t>> cellsOfEdge;
    std::vector<std::pair<std::size_t, int>> ears;
    for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    {
      const int e = EarEdge(mesh, c, g);
      if (e >= 0)
        ears.emplace_back(c, e);
    }
    if (ears.empty())
      break;
    for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
      for (int k = 0; k < 3; ++k)
        cellsOfEdge[Key(mesh.Cell(c)[k], mesh.Cell(c)[(k + 1) % 3])].push_back(c);

    std::vector<std::array<std::int64_t, 3>> added;
    std::vector<std::int32_t> addedMaterials;
    for (const auto& [ear, e] : ears)
    {
      const std::int64_t p = mesh.Cell(ear)[e];
      const std::int64_t q = mesh.Cell(ear)[(e + 1) % 3];
      const auto& sharing = cellsOfEdge[Key(p, q)];
      if (std::any_of(sharing.begin(), sharing.end(), [&](std::size_t c) { return busy[c]; }))
        continue; // next round
      const Point3& a = mesh.Points[static_cast<std::size_t>(p)];
      const Point3& b = mesh.Points[static_cast<std::size_t>(q)];
      const auto m = static_cast<std::int64_t>(mesh.Points.size());
      mesh.Points.push_back({ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) });
      for (std::size_t c : sharing)
      {
        busy[c] = true;
        std::int64_t* v = mesh.Connectivity.data() + 3 * c;
        int i = 0;
        while (Key(v[i], v[(i + 1) % 3]) != Key(p, q))
          ++i;
        // [x_i, x_i+1, x_i+2] -> [x_i, m, x_i+2] and [m, x_i+1, x_i+2]: both keep the orientation.
        const std::array<std::int64_t, 3> second{ m, v[(i + 1) % 3], v[(i + 2) % 3] };
        v[(i + 1) % 3] = m;
        added.push_back(second);
        addedMaterials.push_back(mesh.Materials[c]);
      }
      ++splits;
    }
    for (std::size_t n = 0; n < added.size(); ++n)
    {
      mesh.Connectivity.insert(mesh.Connectivity.end(), added[n].begin(), added[n].end());
      mesh.Materials.push_back(addedMaterials[n]);
    }
    chains = ExtractInterfaceChains(mesh, border);
  }
  return splits;
}

} // namespace labelmesher
