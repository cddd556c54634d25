// SPDX-License-Identifier: GPL-2.0-or-later
// The single manifold condition of a two-label leaf (section 2.4), strong enough for the cone patch.
#include "Criteria/SingleManifoldCondition.h"

#include "Octree/LatticeLabels.h"
#include "Octree/LeafFaces.h"
#include "Support/UnionFind.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace labelmesher
{
namespace
{

/// The leaf's voxels as 0 (first label) / 1 (second label), x fastest.
class LocalLabels
{
public:
  LocalLabels(const LabelImage& image, const LeafBox& leaf, std::int32_t second)
    : S(leaf.Size)
    , Depth(leaf.Dimension == 2 ? 1 : leaf.Size)
    , Bits(static_cast<std::size_t>(S) * S * Depth)
  {
    for (int k = 0; k < Depth; ++k)
      for (int j = 0; j < S; ++j)
        for (int i = 0; i < S; ++i)
          Bits[(static_cast<std::size_t>(k) * S + j) * S + i] =
            image.At(leaf.Origin[0] + i, leaf.Origin[1] + j, leaf.Origin[2] + k) == second;
  }
  int operator()(int i, int j, int k) const { return Bits[(static_cast<std::size_t>(k) * S + j) * S + i]; }
  int operator()(const std::array<int, 3>& p) const { return (*this)(p[0], p[1], p[2]); }
  bool Inside(int i, int j, int k) const
  {
    return i >= 0 && j >= 0 && k >= 0 && i < S && j < S && k < Depth;
  }
  int S, Depth;

private:
  std::vector<unsigned char> Bits;
};

/// Pixels of `value` in an n x n face layer are 4-connected, and no 2x2 block is
/// a checkerboard.
bool FaceLayerIsOneArc(const std::vector<unsigned char>& layer, int n)
{
  for (int b = 0; b + 1 < n; ++b)
    for (int a = 0; a + 1 < n; ++a)
    {
      const int p = layer[b * n + a], q = layer[b * n + a + 1], r = layer[(b + 1) * n + a],
                t = layer[(b + 1) * n + a + 1];
      if (p == t && q == r && p != q)
        return false;
    }
  UnionFind uf(layer.size());
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a)
    {
      if (a + 1 < n && layer[b * n + a] == layer[b * n + a + 1])
        uf.Unite(b * n + a, b * n + a + 1);
      if (b + 1 < n && layer[b * n + a] == layer[(b + 1) * n + a])
        uf.Unite(b * n + a, (b + 1) * n + a);
    }
  std::size_t components = 0;
  for (std::size_t i = 0; i < layer.size(); ++i)
    components += uf.IsRoot(i);
  return components <= 2; // one region per label (a uniform layer has one)
}

/// Signs (+1 first label, -1 second, 0 on the boundary) of the lattice points
/// on the leaf's boundary; lattice point (a, b, c) is the leaf corner (0, 0, 0)
/// moved by that many voxels.
class BoundarySigns
{
public:
  BoundarySigns(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second)
    : Image(image)
    , Leaf(leaf)
    , First(first)
    , Second(second)
  {
  }
  int operator()(int a, int b, int c) const
  {
    return SignOf(LatticeLabel(Image, Leaf.Origin[0] + a, Leaf.Origin[1] + b,
                    Leaf.Dimension == 2 ? 0 : Leaf.Origin[2] + c),
      First, Second);
  }
  /// The segment from lattice point (a, b, c) one step along `axis` lies in the
  /// image boundary (LatticeSegmentOnBoundary).
  bool Linked(int a, int b, int c, int axis) const
  {
    return LatticeSegmentOnBoundary(
      Image, Leaf.Origin[0] + a, Leaf.Origin[1] + b, Leaf.Dimension == 2 ? 0 : Leaf.Origin[2] + c, axis);
  }

private:
  const LabelImage& Image;
  const LeafBox& Leaf;
  std::int32_t First, Second;
};

/// Along one leaf edge the image boundary is empty (both ends of one label),
/// one run of boundary points between ends of different labels, or one run
/// starting at a 0-end. Two runs (Figure 9a), or two 0-ends, fail. A run is
/// one piece of the boundary only if the boundary also joins its points along
/// the edge (`linked[t]`: the segment from point t to t + 1 lies in it);
/// otherwise separate pieces touch the edge at neighbouring points.
bool EdgeIsSimple(const std::vector<int>& signs, const std::vector<unsigned char>& linked)
{
  for (std::size_t t = 0; t + 1 < signs.size(); ++t)
    if (signs[t] == 0 && signs[t + 1] == 0 && !linked[t])
      return false;
  std::vector<int> runs;
  for (int v : signs)
    if (runs.empty() || runs.back() != v)
      runs.push_back(v);
  if (runs.size() == 1)
    return runs[0] != 0;
  if (runs.size() == 2)
    return (runs[0] == 0) != (runs[1] == 0);
  return runs.size() == 3 && runs[1] == 0 && runs[0] != 0 && runs[2] != 0 && runs[0] != runs[2];
}

/// Components of the lattice points of class `value` on an n x n face grid,
/// 4-connected. For the boundary class 0, two neighbours are connected only
/// through a segment that lies in the image boundary (`linkedA`, `linkedB`:
/// from point (a, b) one step along a, along b), so that separate pieces of
/// the boundary touching the face count separately.
int Components(const std::vector<int>& grid, int n, int value, const std::vector<unsigned char>& linkedA = {},
  const std::vector<unsigned char>& linkedB = {})
{
  UnionFind uf(grid.size());
  const bool boundary = value == 0;
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a)
    {
      if (grid[b * n + a] != value)
        continue;
      if (a + 1 < n && grid[b * n + a + 1] == value && (!boundary || linkedA[b * n + a]))
        uf.Unite(b * n + a, b * n + a + 1);
      if (b + 1 < n && grid[(b + 1) * n + a] == value && (!boundary || linkedB[b * n + a]))
        uf.Unite(b * n + a, (b + 1) * n + a);
    }
  int count = 0;
  for (std::size_t i = 0; i < grid.size(); ++i)
    count += grid[i] == value && uf.IsRoot(i);
  return count;
}

/// Edges and faces of the leaf meet the image boundary as the cone patch will:
/// every edge simply (EdgeIsSimple); every face either not crossed (corners of
/// one label, possibly 0-corners), with no boundary point inside it, or
/// crossed once, with no two adjacent 0-corners, with the boundary points one
/// set (connected through boundary segments) separating one 4-connected set
/// of each label, and every
/// 0-corner of the leaf a transition of the intersection polygon (checked
/// with the polygon, ConeSurfacePatch). 2D: the sides, and two transitions.
bool EdgesAndFacesAreSimple(const BoundarySigns& sign, const LeafBox& leaf)
{
  const int s = leaf.Size, n = s + 1;
  std::vector<int> line(n);
  std::vector<unsigned char> linked(n);
  if (leaf.Dimension == 2)
  {
    for (int axis = 0; axis < 2; ++axis)
      for (int side = 0; side < 2; ++side)
      {
        // The side at `side` across `axis` runs along the other axis.
        for (int t = 0; t < n; ++t)
        {
          line[t] = axis == 0 ? sign(side * s, t, 0) : sign(t, side * s, 0);
          linked[t] = t < s && (axis == 0 ? sign.Linked(side * s, t, 0, 1) : sign.Linked(t, side * s, 0, 0));
        }
        if (!EdgeIsSimple(line, linked))
          return false;
      }
    return true;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const auto others = OtherAxes(axis);
    for (int hi = 0; hi < 2; ++hi)
      for (int lo = 0; lo < 2; ++lo)
      {
        for (int t = 0; t < n; ++t)
        {
          int p[3];
          p[axis] = t;
          p[others[0]] = lo * s;
          p[others[1]] = hi * s;
          line[t] = sign(p[0], p[1], p[2]);
          linked[t] = t < s && sign.Linked(p[0], p[1], p[2], axis);
        }
        if (!EdgeIsSimple(line, linked))
          return false;
      }
  }
  std::vector<int> grid(static_cast<std::size_t>(n) * n);
  std::vector<unsigned char> linkedA(grid.size()), linkedB(grid.size());
  for (int face = 0; face < 6; ++face)
  {
    const int axis = face / 2, side = face % 2;
    const auto others = OtherAxes(axis);
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
      {
        int p[3];
        p[axis] = side * s;
        p[others[0]] = a;
        p[others[1]] = b;
        const int v = sign(p[0], p[1], p[2]);
        grid[b * n + a] = v;
        linkedA[b * n + a] = v == 0 && a < s && sign.Linked(p[0], p[1], p[2], others[0]);
        linkedB[b * n + a] = v == 0 && b < s && sign.Linked(p[0], p[1], p[2], others[1]);
      }
    const std::array<int, 4> ring{ grid[0], grid[s], grid[n * n - 1], grid[s * n] };
    std::array<int, 8> where{};
    const int transitions = RingTransitions(ring, where);
    if (transitions == 0)
    {
      // One label (and 0-corners): no boundary point inside the face.
      int label = 0;
      for (int v : ring)
        label = label != 0 ? label : v;
      // One label and no boundary point inside the face (those on its edges
      // are runs from its 0-corners, EdgeIsSimple).
      if (label == 0 || Components(grid, n, label) != 1)
        return false;
      for (int b = 1; b < s; ++b)
        for (int a = 1; a < s; ++a)
          if (grid[b * n + a] == 0)
            return false;
    }
    else if (transitions != 2 || Components(grid, n, 1) != 1 || Components(grid, n, -1) != 1 ||
      Components(grid, n, 0, linkedA, linkedB) != 1)
      return false;
  }
  return true;
}

/// 2D: the pixel edges between the labels inside the leaf form one simple path.
/// With one arc on the perimeter and both labels 4-connected without a 2x2
/// checkerboard, the interface has no loop and no branch.
bool InteriorIsOnePath(const LocalLabels& local, int s)
{
  std::vector<unsigned char> layer(static_cast<std::size_t>(s) * s);
  bool onRim[2] = { false, false };
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i)
    {
      layer[j * s + i] = static_cast<unsigned char>(local(i, j, 0));
      if (i == 0 || j == 0 || i == s - 1 || j == s - 1)
        onRim[layer[j * s + i]] = true;
    }
  // A label that does not reach the leaf's rim is an island: its boundary is
  // a closed loop, not a path.
  return onRim[0] && onRim[1] && FaceLayerIsOneArc(layer, s);
}

/// 3D: the voxel faces between the labels inside the leaf form one disk.
bool InteriorIsOneDisk(const LocalLabels& local, int s)
{
  // Manifold around every voxel vertex: within the (up to) 2x2x2 voxels of the
  // leaf around it, each label is face-connected. This excludes edges shared by
  // four interface faces and pinched vertices.
  UnionFind voxelSets; // reset per vertex: its storage is reused
  for (int k = 0; k <= s; ++k)
    for (int j = 0; j <= s; ++j)
      for (int i = 0; i <= s; ++i)
      {
        int present = 0, label[8];
        std::array<int, 3> where[8];
        for (int c = 0; c < 8; ++c)
        {
          const int vi = i - 1 + (c & 1), vj = j - 1 + ((c >> 1) & 1), vk = k - 1 + ((c >> 2) & 1);
          if (local.Inside(vi, vj, vk))
          {
            where[present] = { c & 1, (c >> 1) & 1, (c >> 2) & 1 };
            label[present++] = local(vi, vj, vk);
          }
        }
        if (present < 4)
          continue; // on a leaf edge or corner: no interface face inside can pinch here
        voxelSets.Reset(present);
        for (int a = 0; a < present; ++a)
          for (int b = a + 1; b < present; ++b)
          {
            const int manhattan = std::abs(where[a][0] - where[b][0]) + std::abs(where[a][1] - where[b][1]) +
              std::abs(where[a][2] - where[b][2]);
            if (manhattan == 1 && label[a] == label[b])
              voxelSets.Unite(a, b);
          }
        int components[2] = { 0, 0 };
        for (int a = 0; a < present; ++a)
          components[label[a]] += voxelSets.IsRoot(a);
        if (components[0] > 1 || components[1] > 1)
          return false;
      }

  // Euler characteristic and connectivity of the interface sheet. Faces are
  // numbered by (axis, lower voxel); vertices and edges are counted once each
  // through the faces that use them.
  const int n = s + 1;
  std::vector<unsigned char> vertexUsed(static_cast<std::size_t>(n) * n * n, 0);
  std::vector<unsigned char> edgeUsed(static_cast<std::size_t>(3) * n * n * n, 0);
  auto vertexId = [n](int i, int j, int k) { return (static_cast<std::size_t>(k) * n + j) * n + i; };
  auto edgeId = [&](int axis, int i, int j, int k) { return vertexId(i, j, k) * 3 + axis; };
  std::vector<std::array<int, 4>> faces; // axis, i, j, k of the face's low vertex
  long long faceCount = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < s; ++k)
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i)
        {
          std::array<int, 3> p{ i, j, k }, q = p;
          q[axis] += 1;
          if (q[axis] >= s || local(p) == local(q))
            continue;
          ++faceCount;
          std::array<int, 3> v = q; // the face lies at the low side of voxel q
          faces.push_back({ axis, v[0], v[1], v[2] });
          const auto others = OtherAxes(axis);
          for (int c = 0; c < 4; ++c)
          {
            std::array<int, 3> w = v;
            w[others[0]] += c & 1;
            w[others[1]] += c >> 1;
            vertexUsed[vertexId(w[0], w[1], w[2])] = 1;
          }
          for (int e = 0; e < 2; ++e)
            for (int side = 0; side < 2; ++side)
            {
              std::array<int, 3> w = v;
              w[others[1 - e]] += side;
              edgeUsed[edgeId(others[e], w[0], w[1], w[2])] = 1;
            }
        }
  if (faceCount == 0)
    return false;
  long long vertices = 0, edges = 0;
  for (unsigned char u : vertexUsed)
    vertices += u;
  for (unsigned char u : edgeUsed)
    edges += u;
  if (vertices - edges + faceCount != 1)
    return false;

  // Connected: faces sharing an edge.
  std::vector<std::int64_t> edgeOwner(edgeUsed.size(), -1);
  UnionFind uf(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    const int axis = faces[f][0];
    const auto others = OtherAxes(axis);
    for (int e = 0; e < 2; ++e)
      for (int side = 0; side < 2; ++side)
      {
        std::array<int, 3> w{ faces[f][1], faces[f][2], faces[f][3] };
        w[others[1 - e]] += side;
        auto& owner = edgeOwner[edgeId(others[e], w[0], w[1], w[2])];
        if (owner >= 0)
          uf.Unite(f, static_cast<std::size_t>(owner));
        else
          owner = static_cast<std::int64_t>(f);
      }
  }
  const std::size_t root = uf.Find(0);
  for (std::size_t f = 1; f < faces.size(); ++f)
    if (uf.Find(f) != root)
      return false;
  return true;
}

/// The interface between the leaf's two labels in the closed leaf is one
/// piece: its voxel faces (pixel edges in 2D) inside the leaf and on its
/// boundary (a voxel of the leaf against an outside one) are connected through
/// shared edges (shared end points in 2D). A second piece on the leaf's
/// boundary is another part of the interface that only touches the leaf, e.g.
/// where a third label separates them; one patch cannot stand for both, and
/// its polygon would join them at a 0-point.
bool InterfaceIsConnected(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second)
{
  const int s = leaf.Size, dimension = leaf.Dimension;
  // Faces are numbered as they come; their sides (3D: the four edges; 2D: the
  // two end points) are keyed by lattice position (leaf-relative, -1..s), and
  // faces with a side key in common are joined.
  auto pack = [s](int kind, int x, int y, int z) {
    const std::int64_t n = s + 2;
    return ((static_cast<std::int64_t>(kind) * n + (z + 1)) * n + (y + 1)) * n + (x + 1);
  };
  std::vector<std::pair<std::int64_t, std::size_t>> sides;
  std::size_t faces = 0;
  ForEachBoundaryFaceInLeaf(image, leaf,
    [&](const std::array<int, 3>& voxel, int axis, int step, std::int32_t here, std::int32_t there) {
      if (!((here == first && there == second) || (here == second && there == first)))
        return;
      // The face's plane is at lattice coordinate voxel[axis] + 1 (step +1) or
      // voxel[axis] (step -1); its sides run along the other axes.
      std::array<int, 3> p = voxel;
      p[axis] += step > 0 ? 1 : 0;
      const std::size_t face = faces++;
      if (dimension == 2)
      {
        const int along = 1 - axis;
        for (int end = 0; end < 2; ++end)
        {
          std::array<int, 3> q = p;
          q[along] += end;
          sides.emplace_back(pack(0, q[0], q[1], 0), face);
        }
        return;
      }
      for (int a = 0; a < 3; ++a)
      {
        if (a == axis)
          continue;
        const int b = 3 - axis - a; // the edge runs along a, at both ends across b
        for (int end = 0; end < 2; ++end)
        {
          std::array<int, 3> q = p;
          q[b] += end;
          sides.emplace_back(pack(a, q[0], q[1], q[2]), face);
        }
      }
    });
  if (faces == 0)
    return false;
  std::sort(sides.begin(), sides.end());
  UnionFind uf(faces);
  for (std::size_t t = 1; t < sides.size(); ++t)
    if (sides[t].first == sides[t - 1].first)
      uf.Unite(sides[t].second, sides[t - 1].second);
  const std::size_t root = uf.Find(0);
  for (std::size_t f = 1; f < faces; ++f)
    if (uf.Find(f) != root)
      return false;
  return true;
}

/// Every 0-corner of the leaf lies on the interface between the leaf's two
/// labels: both are among the voxels around it. The intersection polygon runs
/// through the leaf's 0-corners and stands for that interface; a 0-corner that
/// only one of the two labels touches (with a third) lies on another piece of
/// the boundary, and the patches of the leaves around it would join regions
/// of a label there at a point (random box image 2288: two blocks of a label
/// two pixels apart, each reaching a corner of the 1|0 boundary between them).
bool ZeroCornersLieOnTheInterface(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second)
{
  const bool flat = leaf.Dimension == 2;
  for (int c = 0; c < (flat ? 4 : 8); ++c)
  {
    const int i = leaf.Origin[0] + ((c & 1) ? leaf.Size : 0);
    const int j = leaf.Origin[1] + ((c & 2) ? leaf.Size : 0);
    const int k = flat ? 0 : leaf.Origin[2] + ((c & 4) ? leaf.Size : 0);
    if (LatticeLabel(image, i, j, k) != kOnBoundary)
      continue;
    bool hasFirst = false, hasSecond = false;
    for (int v = 0; v < (flat ? 4 : 8); ++v)
    {
      const std::int32_t label = image.At(i - 1 + (v & 1), j - 1 + ((v >> 1) & 1), flat ? 0 : k - 1 + ((v >> 2) & 1));
      hasFirst = hasFirst || label == first;
      hasSecond = hasSecond || label == second;
    }
    if (!(hasFirst && hasSecond))
      return false;
  }
  return true;
}

} // namespace

bool SatisfiesSingleManifoldCondition(
  const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second)
{
  if (first == second || leaf.Size < 2)
    return false;
  if (!ZeroCornersLieOnTheInterface(image, leaf, first, second))
    return false;
  if (!EdgesAndFacesAreSimple(BoundarySigns(image, leaf, first, second), leaf))
    return false;
  if (!InterfaceIsConnected(image, leaf, first, second))
    return false;
  const LocalLabels local(image, leaf, second);
  return leaf.Dimension == 2 ? InteriorIsOnePath(local, leaf.Size) : InteriorIsOneDisk(local, leaf.Size);
}

} // namespace labelmesher
