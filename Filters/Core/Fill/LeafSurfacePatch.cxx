// SPDX-License-Identifier: GPL-2.0-or-later
#include "Fill/LeafSurfacePatch.h"

#include "Octree/LeafFaces.h"

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

/// The face of voxel `centre` at half a voxel along `axis` in direction
/// `step` (a pixel edge in 2D).
ConvexPiece VoxelFace(int dimension, Point3 centre, int axis, int step)
{
  centre[axis] += 0.5 * step;
  if (dimension == 2)
  {
    Point3 a = centre, b = centre;
    a[1 - axis] -= 0.5;
    b[1 - axis] += 0.5;
    return ConvexPiece{ 2, { a, b } };
  }
  const auto others = OtherAxes(axis);
  ConvexPiece square{ 4, {} };
  const int order[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  for (int c = 0; c < 4; ++c)
  {
    Point3 p = centre;
    p[others[0]] += 0.5 * order[c][0];
    p[others[1]] += 0.5 * order[c][1];
    square.Points[c] = p;
  }
  return square;
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
  std::vector<int> parent(20);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x)
      x = parent[x];
    return x;
  };
  for (const auto& seg : segments)
  {
    ++degree[seg[0]];
    ++degree[seg[1]];
    parent[find(seg[0])] = find(seg[1]);
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
    if (find(seg[0]) != find(segments[0][0]))
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

LeafImageBoundary ImageBoundaryInLeaf(const LabelImage& image, const LeafBox& leaf, std::int32_t first,
  std::int32_t second)
{
  LeafImageBoundary boundary;
  ForEachBoundaryFaceInLeaf(image, leaf,
    [&](const std::array<int, 3>& voxel, int axis, int step, std::int32_t here, std::int32_t there) {
      const Point3 centre{ double(leaf.Origin[0] + voxel[0]), double(leaf.Origin[1] + voxel[1]),
        double(leaf.Origin[2] + voxel[2]) };
      const ConvexPiece face = VoxelFace(leaf.Dimension, centre, axis, step);
      boundary.All.push_back(face);
      if ((here == first && there == second) || (here == second && there == first))
        boundary.Interface.push_back(face);
    });
  return boundary;
}

bool SatisfiesFidelity(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second,
  double imageToMesh, double meshToImage)
{
  const std::vector<ConvexPiece> patch = ConeSurfacePatch(leaf, LeafCornerSigns(image, leaf, first, second));
  if (patch.empty())
    return false;
  const LeafImageBoundary boundary = ImageBoundaryInLeaf(image, leaf, first, second);
  for (const ConvexPiece& piece : patch)
    if (!WithinDistance(piece, boundary.Interface, meshToImage))
      return false;
  for (const ConvexPiece& piece : boundary.All)
    if (!WithinDistance(piece, patch, imageToMesh))
      return false;
  return true;
}

} // namespace labelmesher
