// SPDX-License-Identifier: GPL-2.0-or-later
// The chains of edges a 2D mesh's material interfaces are made of (section 4.1).
#include "Curving/InterfaceChains.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>

namespace labelmesher
{
namespace
{
using EdgeKey = std::array<std::int64_t, 2>;

struct EdgeKeyHash
{
  std::size_t operator()(const EdgeKey& k) const
  {
    std::size_t h = 1469598103934665603ull;
    for (std::int64_t v : k)
      h = (h ^ static_cast<std::size_t>(v)) * 1099511628211ull;
    return h;
  }
};

/// The cells on either side of edge Key[0] → Key[1] (Key[0] < Key[1]), -1 for none.
struct EdgeCells
{
  EdgeKey Key;
  std::int64_t Left = -1;
  std::int64_t Right = -1;
};

/// An interface edge directed so that First is on its left.
struct InterfaceEdge
{
  std::int64_t From;
  std::int64_t To;
  std::int32_t First;
  std::int32_t Second;
};

/// Which sides of the border box a point lies on (bits: xmin, xmax, ymin, ymax).
class BorderSides
{
public:
  explicit BorderSides(const Box2& box)
    : Box(box)
    , Tolerance(1e-9 * std::max(box[1] - box[0], box[3] - box[2]))
  {
  }

  unsigned operator()(const Point3& p) const
  {
    unsigned sides = 0;
    for (int a = 0; a < 2; ++a)
    {
      if (std::abs(p[a] - Box[2 * a]) <= Tolerance)
        sides |= 1u << (2 * a);
      if (std::abs(p[a] - Box[2 * a + 1]) <= Tolerance)
        sides |= 1u << (2 * a + 1);
    }
    return sides;
  }

private:
  Box2 Box;
  double Tolerance;
};

// Per-vertex slot for the one incoming (or outgoing) interface edge.
constexpr std::int64_t kNoEdge = -1;
constexpr std::int64_t kManyEdges = -2;

void Attach(std::int64_t& slot, std::int64_t edge)
{
  slot = slot == kNoEdge ? edge : kManyEdges;
}

} // namespace

Box2 BoundingBox2(const SimplexMesh& mesh)
{
  if (mesh.Points.empty())
    return { 0.0, 0.0, 0.0, 0.0 };
  Box2 box{ mesh.Points[0][0], mesh.Points[0][0], mesh.Points[0][1], mesh.Points[0][1] };
  for (const Point3& p : mesh.Points)
  {
    box[0] = std::min(box[0], p[0]);
    box[1] = std::max(box[1], p[0]);
    box[2] = std::min(box[2], p[1]);
    box[3] = std::max(box[3], p[1]);
  }
  return box;
}

std::vector<InterfaceChain> ExtractInterfaceChains(const SimplexMesh& mesh, const Box2& border)
{
  if (mesh.Dimension != 2)
    throw std::invalid_argument("ExtractInterfaceChains: the mesh must be two-dimensional");
  const std::size_t np = mesh.Points.size();

  // An interface has a cell of a non-zero material on one side, so both of its
  // ends touch such a cell: edges of the background alone are never hashed.
  std::vector<char> touchesMaterial(np, 0);
  std::size_t candidates = 0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    if (mesh.Materials[c] != 0)
    {
      ++candidates;
      for (int i = 0; i < 3; ++i)
        touchesMaterial[mesh.Cell(c)[i]] = 1;
    }

  // Edges in the order they are first met, so that the output does not depend
  // on the hash map's iteration order. Cells are counter-clockwise: a cell is
  // on the left of each of its edges taken in its own vertex order.
  std::vector<EdgeCells> edges;
  std::unordered_map<EdgeKey, std::size_t, EdgeKeyHash> edgeIndex;
  edgeIndex.reserve(2 * candidates + 16);
  edges.reserve(2 * candidates + 16);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* cell = mesh.Cell(c);
    for (int i = 0; i < 3; ++i)
    {
      const std::int64_t a = cell[i], b = cell[(i + 1) % 3];
      if (!touchesMaterial[a] || !touchesMaterial[b])
        continue;
      const EdgeKey key{ std::min(a, b), std::max(a, b) };
      const auto [it, inserted] = edgeIndex.try_emplace(key, edges.size());
      if (inserted)
        edges.push_back({ key, -1, -1 });
      // A third cell on one edge (a non-manifold mesh) is ignored.
      std::int64_t& side = a < b ? edges[it->second].Left : edges[it->second].Right;
      if (side < 0)
        side = static_cast<std::int64_t>(c);
    }
  }
  edgeIndex = {};

  // Interface edges, directed with the larger material on the left: a region
  // of material m > 0 in the background is thus walked counter-clockwise.
  const BorderSides borderSides(border);
  auto material = [&](std::int64_t cell) { return cell < 0 ? 0 : mesh.Materials[cell]; };
  std::vector<InterfaceEdge> interfaces;
  for (const EdgeCells& e : edges)
  {
    const std::int32_t left = material(e.Left), right = material(e.Right);
    if (left == right)
      continue;
    // Edges along the image border stay straight (section 4.1 smooths material boundaries only).
    if (borderSides(mesh.Points[e.Key[0]]) & borderSides(mesh.Points[e.Key[1]]))
      continue;
    if (left > right)
      interfaces.push_back({ e.Key[0], e.Key[1], left, right });
    else
      interfaces.push_back({ e.Key[1], e.Key[0], right, left });
  }
  edges = {};

  // A chain passes through a vertex with exactly one incoming and one outgoing
  // interface edge of the same material pair, off the border; any other
  // interface vertex (a junction, a pinch, the border) ends chains.
  std::vector<std::int64_t> incoming(np, kNoEdge), outgoing(np, kNoEdge);
  for (std::size_t e = 0; e < interfaces.size(); ++e)
  {
    Attach(outgoing[interfaces[e].From], static_cast<std::int64_t>(e));
    Attach(incoming[interfaces[e].To], static_cast<std::int64_t>(e));
  }
  auto passesThrough = [&](std::int64_t v) {
    const std::int64_t in = incoming[v], out = outgoing[v];
    if (in < 0 || out < 0)
      return false;
    // Different pairs (or a border vertex) at degree 2 occur only in degenerate meshes.
    if (interfaces[in].First != interfaces[out].First || interfaces[in].Second != interfaces[out].Second)
      return false;
    return borderSides(mesh.Points[v]) == 0;
  };

  std::vector<char> used(interfaces.size(), 0);
  auto walk = [&](std::size_t e) {
    InterfaceChain chain;
    chain.FirstMaterial = interfaces[e].First;
    chain.SecondMaterial = interfaces[e].Second;
    chain.Vertices.push_back(interfaces[e].From);
    for (;;)
    {
      used[e] = 1;
      const std::int64_t v = interfaces[e].To;
      if (!passesThrough(v))
      {
        chain.Vertices.push_back(v); // may equal the first vertex: a loop pinned at a junction
        break;
      }
      if (v == chain.Vertices.front())
      {
        chain.Closed = true;
        break;
      }
      chain.Vertices.push_back(v);
      e = static_cast<std::size_t>(outgoing[v]);
    }
    return chain;
  };

  std::vector<InterfaceChain> chains;
  // Open chains first, from their start vertices; whatever is left are loops.
  for (std::size_t e = 0; e < interfaces.size(); ++e)
    if (!used[e] && !passesThrough(interfaces[e].From))
      chains.push_back(walk(e));
  for (std::size_t e = 0; e < interfaces.size(); ++e)
    if (!used[e])
      chains.push_back(walk(e));
  return chains;
}

} // namespace labelmesher
