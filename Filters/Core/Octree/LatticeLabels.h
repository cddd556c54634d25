// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LatticeLabels_h
#define labelmesher_LatticeLabels_h

/**
 * @file LatticeLabels.h
 * The label of a point of the voxel-corner lattice, the same for every leaf
 * that has the point: the common label of the voxels around it, or "on the
 * boundary" when they differ (the 0-vertices of section 3.1.1). Because it is
 * global, the corner signs of a face, and so its stencil, are the same seen
 * from either leaf: the fill conforms even where the image boundary lies on
 * the face between two leaves.
 *
 * Signs relative to a proper leaf holding labels First < Second: +1 for First,
 * -1 for Second, 0 on the boundary.
 */

#include "Support/LabelImage.h"
#include "Octree/LeafBox.h"

#include <array>
#include <cstdint>

namespace labelmesher
{

constexpr std::int32_t kOnBoundary = -1;

/// Label of the lattice point between voxels i-1 and i along x (and so on), or
/// kOnBoundary. In 2D only the four pixels around (i, j) count.
inline std::int32_t LatticeLabel(const LabelImage& image, int i, int j, int k)
{
  const bool flat = image.Dimension() == 2;
  const std::int32_t first = image.At(i - 1, j - 1, flat ? 0 : k - 1);
  for (int c = 1; c < (flat ? 4 : 8); ++c)
    if (image.At(i - 1 + (c & 1), j - 1 + ((c >> 1) & 1), flat ? 0 : k - 1 + ((c >> 2) & 1)) != first)
      return kOnBoundary;
  return first;
}

/// Whether the lattice segment from point (i, j, k) to its neighbour one step
/// along `axis` lies in the image boundary: the voxels around it (four in 3D,
/// two in 2D) are not all of one label. Two 0-points next to each other are
/// joined by the image boundary along the segment only when this holds;
/// otherwise they are touched by separate pieces of it.
inline bool LatticeSegmentOnBoundary(const LabelImage& image, int i, int j, int k, int axis)
{
  const bool flat = image.Dimension() == 2;
  int p[3] = { i, j, k };
  int around[2], count = 0;
  for (int a = 0; a < (flat ? 2 : 3); ++a)
    if (a != axis)
      around[count++] = a;
  // The voxels with index p[axis] along the axis, p - 1 or p across it.
  std::int32_t first = 0;
  for (int c = 0; c < (1 << count); ++c)
  {
    int v[3] = { p[0], p[1], flat ? 0 : p[2] };
    for (int b = 0; b < count; ++b)
      v[around[b]] = p[around[b]] - 1 + ((c >> b) & 1);
    const std::int32_t label = image.At(v[0], v[1], v[2]);
    if (c == 0)
      first = label;
    else if (label != first)
      return true;
  }
  return false;
}

inline int SignOf(std::int32_t label, std::int32_t first, std::int32_t second)
{
  return label == first ? 1 : (label == second ? -1 : 0);
}

/// Signs of a leaf's corners: bit c of Negative for the second label, of Zero
/// for a point on the boundary.
struct CornerSigns
{
  unsigned Negative = 0;
  unsigned Zero = 0;
  int operator[](int c) const { return ((Zero >> c) & 1u) ? 0 : (((Negative >> c) & 1u) ? -1 : 1); }
};

inline CornerSigns LeafCornerSigns(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second)
{
  CornerSigns signs;
  const int corners = leaf.Dimension == 2 ? 4 : 8;
  for (int c = 0; c < corners; ++c)
  {
    const int i = leaf.Origin[0] + ((c & 1) ? leaf.Size : 0);
    const int j = leaf.Origin[1] + ((c & 2) ? leaf.Size : 0);
    const int k = leaf.Dimension == 2 ? 0 : leaf.Origin[2] + ((c & 4) ? leaf.Size : 0);
    const int s = SignOf(LatticeLabel(image, i, j, k), first, second);
    if (s == 0)
      signs.Zero |= 1u << c;
    else if (s < 0)
      signs.Negative |= 1u << c;
  }
  return signs;
}

/// The points where the surface crosses the boundary ring of a square whose
/// corner signs are given in ring order (counter-clockwise): the midpoint of a
/// side with opposite non-zero ends (ring position 2 i + 1 for side i, from
/// corner i to corner i + 1) and a 0-corner whose two ring neighbours have
/// opposite non-zero signs (ring position 2 i). Returns the count (2 for a
/// crossed square without saddle).
inline int RingTransitions(const std::array<int, 4>& ring, std::array<int, 8>& where)
{
  int count = 0;
  for (int i = 0; i < 4; ++i)
  {
    const int here = ring[i], next = ring[(i + 1) % 4], previous = ring[(i + 3) % 4];
    if (here == 0 && previous != 0 && next != 0 && previous != next)
      where[count++] = 2 * i;
    if (here != 0 && next != 0 && here != next)
      where[count++] = 2 * i + 1;
  }
  return count;
}

/// The faces (3D) or sides (2D) of a proper leaf that cannot take points of
/// finer neighbours: 3D faces the surface crosses (their stencil is fixed);
/// 2D sides with a midpoint intersection vertex or a 0-corner (a hanging point
/// there would sit between the surface and the corner that labels its cell).
inline unsigned RigidFaces(const CornerSigns& signs, int dimension)
{
  unsigned rigid = 0;
  for (int face = 0; face < 2 * dimension; ++face)
  {
    const int axis = face / 2, side = face % 2;
    if (dimension == 2)
    {
      const int c0 = side << axis, c1 = c0 | (1 << (1 - axis));
      if (signs[c0] * signs[c1] <= 0)
        rigid |= 1u << face;
      continue;
    }
    bool positive = false, negative = false;
    for (int q = 0; q < 4; ++q)
    {
      positive = positive || signs[FaceCornerToCube(face, q)] > 0;
      negative = negative || signs[FaceCornerToCube(face, q)] < 0;
    }
    if (positive && negative)
      rigid |= 1u << face;
  }
  return rigid;
}

} // namespace labelmesher

#endif
