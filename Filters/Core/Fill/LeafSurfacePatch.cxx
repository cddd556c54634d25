// SPDX-License-Identifier: GPL-2.0-or-later
// The cone surface patch of a proper boundary leaf (section 3.1.1, "Waterproof surface mesh").
#include "Fill/LeafSurfacePatch.h"

#include "Support/UnionFind.h"

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

std::vector<ConvexPiece> ConeSurfacePatch(const LeafBox& leaf, const CornerSigns& signs)
{
  std::vector<ConvexPiece> patch;
  const Point3 centre = LeafPoint(leaf, 1, 1, leaf.Dimension == 2 ? 0 : 1);
  std::array<int, 8> where{};
  if (leaf.Dimension == 2)
  {
    // The square's own ring: sides y = 0, x = 1, y = 1, x = 0.
    const std::array<int, 4> ring{ signs[kRingCorners[0]], signs[kRingCorners[1]], signs[kRingCorners[2]],
      signs[kRingCorners[3]] };
    if (RingTransitions(ring, where) != 2)
      return {};
    // A 0-corner off the polygon would be image boundary the patch misses.
    for (int i = 0; i < 4; ++i)
      if (ring[i] == 0 && where[0] != 2 * i && where[1] != 2 * i)
        return {};
    const int halves[8][2] = { { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 1 }, { 2, 2 }, { 1, 2 }, { 0, 2 }, { 0, 1 } };
    for (int t = 0; t < 2; ++t)
      patch.push_back(ConvexPiece{ 2, { centre, LeafPoint(leaf, halves[where[t]][0], halves[where[t]][1], 0) } });
    return patch;
  }
  // 3D: each crossed face joins its two transition points; a point is a cube
  // edge (its midpoint, node e) or a cube corner (node 12 + c).
  std::vector<std::array<int, 2>> segments;
  for (int face = 0; face < 6; ++face)
  {
    std::array<int, 4> ring;
    for (int i = 0; i < 4; ++i)
      ring[i] = signs[FaceCornerToCube(face, kRingCorners[i])];
    const int count = RingTransitions(ring, where);
    if (count == 0)
      continue;
    if (count != 2)
      return {}; // a saddle
    std::array<int, 2> segment;
    for (int t = 0; t < 2; ++t)
      segment[t] = where[t] % 2 ? FaceEdgeToCube(face, where[t] / 2)
                                : 12 + FaceCornerToCube(face, kRingCorners[where[t] / 2]);
    segments.push_back(segment);
  }
  if (segments.size() < 2)
    return {};
  // One simple closed polygon: every point on it has two segments, all connect.
  int degree[20] = {};
  UnionFind polygon(20);
  for (const auto& seg : segments)
  {
    ++degree[seg[0]];
    ++degree[seg[1]];
    polygon.Unite(seg[0], seg[1]);
  }
  for (int node = 0; node < 20; ++node)
    if (degree[node] != 0 && degree[node] != 2)
      return {};
  // Every 0-corner is a vertex of the polygon: one off it would be image
  // boundary that the patch misses.
  for (int c = 0; c < 8; ++c)
    if (signs[c] == 0 && degree[12 + c] != 2)
      return {};
  for (const auto& seg : segments)
    if (polygon.Find(seg[0]) != polygon.Find(segments[0][0]))
      return {};
  auto position = [&](int node) {
    if (node >= 12)
    {
      const int c = node - 12;
      return LeafPoint(leaf, 2 * (c & 1), 2 * ((c >> 1) & 1), 2 * ((c >> 2) & 1));
    }
    const int axis = node / 4, lowBit = node & 1, highBit = (node >> 1) & 1;
    const auto others = OtherAxes(axis);
    int h[3];
    h[axis] = 1;
    h[others[0]] = 2 * lowBit;
    h[others[1]] = 2 * highBit;
    return LeafPoint(leaf, h[0], h[1], h[2]);
  };
  for (const auto& seg : segments)
    patch.push_back(ConvexPiece{ 3, { centre, position(seg[0]), position(seg[1]) } });
  return patch;
}

} // namespace labelmesher
