// SPDX-License-Identifier: GPL-2.0-or-later
#include "LeafSurfacePatch.h"

#include <numeric>

namespace labelmesher
{
namespace
{

Point3 FromDoubled(std::int64_t u, std::int64_t v, std::int64_t w, int dimension)
{
  return { (u - 1) / 2.0, (v - 1) / 2.0, dimension == 2 ? 0.0 : (w - 1) / 2.0 };
}

/// Index-space position of the point of the leaf at fractions (in halves of the
/// leaf side) h = 0, 1, 2 along each axis: 0 = low side, 1 = middle, 2 = high.
Point3 LeafPoint(const LeafBox& leaf, int hx, int hy, int hz)
{
  const std::int64_t s = leaf.Size;
  return FromDoubled(leaf.Low(0) + hx * s, leaf.Low(1) + hy * s, leaf.Low(2) + hz * s, leaf.Dimension);
}

} // namespace

unsigned CornerLabelBits(const LabelImage& image, const LeafBox& leaf, std::int32_t second)
{
  unsigned bits = 0;
  const int corners = leaf.Dimension == 2 ? 4 : 8;
  for (int c = 0; c < corners; ++c)
  {
    const auto v = leaf.CornerVoxel(c);
    if (image.At(v[0], v[1], v[2]) == second)
      bits |= 1u << c;
  }
  return bits;
}

std::vector<ConvexPiece> ConeSurfacePatch(const LeafBox& leaf, unsigned cornerBits)
{
  std::vector<ConvexPiece> patch;
  const Point3 centre = LeafPoint(leaf, 1, 1, leaf.Dimension == 2 ? 0 : 1);
  auto bit = [&](int c) { return (cornerBits >> c) & 1u; };
  if (leaf.Dimension == 2)
  {
    // Sides (faces) f = 2 axis + side; their ends are corners differing in the other axis.
    for (int axis = 0; axis < 2; ++axis)
      for (int side = 0; side < 2; ++side)
      {
        const int other = 1 - axis;
        const int c0 = side << axis, c1 = c0 | (1 << other);
        if (bit(c0) == bit(c1))
          continue;
        int h[2];
        h[axis] = 2 * side;
        h[other] = 1;
        patch.push_back(ConvexPiece{ 2, { centre, LeafPoint(leaf, h[0], h[1], 0) } });
      }
    if (patch.size() != 2)
      patch.clear();
    return patch;
  }
  // 3D: crossed cube edges are the intersection vertices; each crossed face
  // joins its two crossed edges.
  std::vector<int> crossedEdges[6];
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
    {
      const auto others = OtherAxes(axis);
      for (int e = 0; e < 2; ++e)
        for (int b = 0; b < 2; ++b)
        {
          std::array<int, 3> bits{ 0, 0, 0 };
          bits[axis] = side;
          bits[others[1 - e]] = b;
          const int c0 = (bits[0]) | (bits[1] << 1) | (bits[2] << 2);
          const int c1 = c0 | (1 << others[e]);
          if (bit(c0) != bit(c1))
            crossedEdges[2 * axis + side].push_back(CubeEdgeThrough(others[e], bits));
        }
    }
  std::vector<std::array<int, 2>> segments;
  for (const auto& edges : crossedEdges)
  {
    if (edges.size() == 2)
      segments.push_back({ edges[0], edges[1] });
    else if (!edges.empty())
      return {}; // a saddle: excluded by the single manifold condition
  }
  if (segments.size() < 3)
    return {};
  // One closed polygon: every crossed edge is in two segments, and all connect.
  std::vector<int> parent(12);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x)
      x = parent[x];
    return x;
  };
  for (const auto& s : segments)
    parent[find(s[0])] = find(s[1]);
  for (const auto& s : segments)
    if (find(s[0]) != find(segments[0][0]))
      return {};
  auto midpoint = [&](int edge) {
    const int axis = edge / 4, lowBit = edge & 1, highBit = (edge >> 1) & 1;
    const auto others = OtherAxes(axis);
    int h[3];
    h[axis] = 1;
    h[others[0]] = 2 * lowBit;
    h[others[1]] = 2 * highBit;
    return LeafPoint(leaf, h[0], h[1], h[2]);
  };
  for (const auto& s : segments)
    patch.push_back(ConvexPiece{ 3, { centre, midpoint(s[0]), midpoint(s[1]) } });
  return patch;
}

std::vector<ConvexPiece> ImageBoundaryInLeaf(const LabelImage& image, const LeafBox& leaf)
{
  std::vector<ConvexPiece> pieces;
  const int s = leaf.Size, depth = leaf.Dimension == 2 ? 1 : s;
  for (int k = 0; k < depth; ++k)
    for (int j = 0; j < s; ++j)
      for (int i = 0; i < s; ++i)
      {
        const int x = leaf.Origin[0] + i, y = leaf.Origin[1] + j, z = leaf.Origin[2] + k;
        const std::int32_t here = image.At(x, y, z);
        for (int axis = 0; axis < leaf.Dimension; ++axis)
        {
          int next[3] = { i, j, k };
          if (++next[axis] >= s)
            continue;
          int n[3] = { x, y, z };
          ++n[axis];
          if (image.At(n[0], n[1], n[2]) == here)
            continue;
          // The face at +1/2 along `axis` from voxel (x, y, z).
          Point3 base{ double(x), double(y), double(z) };
          base[axis] += 0.5;
          if (leaf.Dimension == 2)
          {
            const int other = 1 - axis;
            Point3 a = base, b = base;
            a[other] -= 0.5;
            b[other] += 0.5;
            pieces.push_back(ConvexPiece{ 2, { a, b } });
            continue;
          }
          const auto others = OtherAxes(axis);
          ConvexPiece square{ 4, {} };
          const int order[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
          for (int c = 0; c < 4; ++c)
          {
            Point3 p = base;
            p[others[0]] += 0.5 * order[c][0];
            p[others[1]] += 0.5 * order[c][1];
            square.Points[c] = p;
          }
          pieces.push_back(square);
        }
      }
  return pieces;
}

bool SatisfiesFidelity(
  const LabelImage& image, const LeafBox& leaf, std::int32_t second, double imageToMesh, double meshToImage)
{
  const std::vector<ConvexPiece> patch = ConeSurfacePatch(leaf, CornerLabelBits(image, leaf, second));
  if (patch.empty())
    return false;
  const std::vector<ConvexPiece> boundary = ImageBoundaryInLeaf(image, leaf);
  for (const ConvexPiece& piece : patch)
    if (!WithinDistance(piece, boundary, meshToImage))
      return false;
  for (const ConvexPiece& piece : boundary)
    if (!WithinDistance(piece, patch, imageToMesh))
      return false;
  return true;
}

} // namespace labelmesher
