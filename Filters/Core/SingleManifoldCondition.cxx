// SPDX-License-Identifier: GPL-2.0-or-later
#include "SingleManifoldCondition.h"

#include <cstdlib>
#include <numeric>
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

bool FacesAreClean(const LabelImage& image, const LeafBox& leaf)
{
  const int s = leaf.Size;
  for (int axis = 0; axis < leaf.Dimension; ++axis)
  {
    const auto others = OtherAxes(axis);
    const int spanB = leaf.Dimension == 2 ? 1 : s;
    for (int side = 0; side < 2; ++side)
      for (int b = 0; b < spanB; ++b)
        for (int a = 0; a < s; ++a)
        {
          std::array<int, 3> in = leaf.Origin;
          in[axis] += side ? s - 1 : 0;
          in[others[0]] += a;
          if (leaf.Dimension == 3)
            in[others[1]] += b;
          std::array<int, 3> out = in;
          out[axis] += side ? 1 : -1;
          if (image.At(in[0], in[1], in[2]) != image.At(out[0], out[1], out[2]))
            return false;
        }
  }
  return true;
}

/// Number of label changes along the line of voxels from `start` stepping `step`.
int Transitions(const LocalLabels& local, std::array<int, 3> p, const std::array<int, 3>& step, int n)
{
  int count = 0, previous = local(p);
  for (int t = 1; t < n; ++t)
  {
    for (int d = 0; d < 3; ++d)
      p[d] += step[d];
    const int v = local(p);
    count += v != previous;
    previous = v;
  }
  return count;
}

struct UnionFind
{
  explicit UnionFind(std::size_t n)
    : Parent(n)
  {
    std::iota(Parent.begin(), Parent.end(), std::size_t(0));
  }
  std::size_t Find(std::size_t x)
  {
    while (Parent[x] != x)
      x = Parent[x] = Parent[Parent[x]];
    return x;
  }
  void Unite(std::size_t a, std::size_t b) { Parent[Find(a)] = Find(b); }
  std::vector<std::size_t> Parent;
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
    components += uf.Find(i) == i;
  return components <= 2; // one region per label (a uniform layer has one)
}

bool EdgesAndFacesAreSimple(const LocalLabels& local, const LeafBox& leaf)
{
  const int s = leaf.Size;
  // Edges: at most one change of label along each (Figure 9a).
  if (leaf.Dimension == 2)
  {
    int perimeterChanges = 0;
    for (int axis = 0; axis < 2; ++axis)
      for (int side = 0; side < 2; ++side)
      {
        std::array<int, 3> start{ 0, 0, 0 }, step{ 0, 0, 0 };
        start[axis] = side ? s - 1 : 0;
        step[1 - axis] = 1;
        const int t = Transitions(local, start, step, s);
        if (t > 1)
          return false;
        perimeterChanges += t;
      }
    return perimeterChanges == 2; // 0 would be an island (Figure 9b), 4 a saddle
  }
  int edgeChanges[12];
  for (int axis = 0; axis < 3; ++axis)
  {
    const auto others = OtherAxes(axis);
    for (int hi = 0; hi < 2; ++hi)
      for (int lo = 0; lo < 2; ++lo)
      {
        std::array<int, 3> start{ 0, 0, 0 }, step{ 0, 0, 0 };
        start[others[0]] = lo ? s - 1 : 0;
        start[others[1]] = hi ? s - 1 : 0;
        step[axis] = 1;
        const int t = Transitions(local, start, step, s);
        if (t > 1)
          return false;
        edgeChanges[CubeEdge(axis, lo, hi)] = t;
      }
  }
  // Faces: one simple arc or uniform (no island, no saddle).
  std::vector<unsigned char> layer(static_cast<std::size_t>(s) * s);
  for (int axis = 0; axis < 3; ++axis)
  {
    const auto others = OtherAxes(axis);
    for (int side = 0; side < 2; ++side)
    {
      // The four edges of this face: parallel to others[0] or others[1].
      int changes = 0;
      for (int bit = 0; bit < 2; ++bit)
      {
        // Edge parallel to others[0]: its other coordinates are axis (=side) and others[1] (=bit).
        changes += edgeChanges[CubeEdge(others[0], axis < others[1] ? side : bit, axis < others[1] ? bit : side)];
        changes += edgeChanges[CubeEdge(others[1], axis < others[0] ? side : bit, axis < others[0] ? bit : side)];
      }
      bool uniform = true;
      for (int b = 0; b < s; ++b)
        for (int a = 0; a < s; ++a)
        {
          std::array<int, 3> p{ 0, 0, 0 };
          p[axis] = side ? s - 1 : 0;
          p[others[0]] = a;
          p[others[1]] = b;
          layer[b * s + a] = static_cast<unsigned char>(local(p));
          uniform = uniform && layer[b * s + a] == layer[0];
        }
      if (changes == 0 && !uniform)
        return false; // an island that touches no edge (Figure 9b)
      if (changes != 0 && changes != 2)
        return false; // a saddle
      if (changes == 2 && !FaceLayerIsOneArc(layer, s))
        return false;
    }
  }
  return true;
}

/// 2D: the pixel edges between the labels inside the leaf form one simple path.
/// With one arc on the perimeter and both labels 4-connected without a 2x2
/// checkerboard, the interface has no loop and no branch.
bool InteriorIsOnePath(const LocalLabels& local, int s)
{
  std::vector<unsigned char> layer(static_cast<std::size_t>(s) * s);
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i)
      layer[j * s + i] = static_cast<unsigned char>(local(i, j, 0));
  return FaceLayerIsOneArc(layer, s);
}

/// 3D: the voxel faces between the labels inside the leaf form one disk.
bool InteriorIsOneDisk(const LocalLabels& local, int s)
{
  // Manifold around every voxel vertex: within the (up to) 2x2x2 voxels of the
  // leaf around it, each label is face-connected. This excludes edges shared by
  // four interface faces and pinched vertices.
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
        int parent[8];
        std::iota(parent, parent + present, 0);
        auto find = [&](int x) {
          while (parent[x] != x)
            x = parent[x];
          return x;
        };
        for (int a = 0; a < present; ++a)
          for (int b = a + 1; b < present; ++b)
          {
            const int manhattan = std::abs(where[a][0] - where[b][0]) + std::abs(where[a][1] - where[b][1]) +
              std::abs(where[a][2] - where[b][2]);
            if (manhattan == 1 && label[a] == label[b])
              parent[find(a)] = find(b);
          }
        int components[2] = { 0, 0 };
        for (int a = 0; a < present; ++a)
          components[label[a]] += find(a) == a;
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

} // namespace

bool SatisfiesSingleManifoldCondition(
  const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second)
{
  if (first == second || leaf.Size < 2)
    return false;
  if (!FacesAreClean(image, leaf))
    return false;
  const LocalLabels local(image, leaf, second);
  if (!EdgesAndFacesAreSimple(local, leaf))
    return false;
  return leaf.Dimension == 2 ? InteriorIsOnePath(local, leaf.Size) : InteriorIsOneDisk(local, leaf.Size);
}

} // namespace labelmesher
