// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LeafBox_h
#define labelmesher_LeafBox_h

/**
 * @file LeafBox.h
 * An octree (quadtree) leaf as a block of voxels, and the local numbering of its
 * corners, faces and edges (p4est's: corner c has bit d set when it lies on the
 * high side of axis d; face f = 2 * axis + side; edge e parallel to axis d has
 * index 4 d + (bit of the lower other axis) + 2 (bit of the higher other axis)).
 *
 * Mesh vertices are kept on a doubled lattice: u = 2 x + 1 for the index-space
 * coordinate x (voxel centres at odd u, voxel faces at even u), so leaf corners,
 * centres, face centres and edge midpoints are all integers.
 */

#include <array>
#include <cstdint>

namespace labelmesher
{

struct LeafBox
{
  std::array<int, 3> Origin{ 0, 0, 0 }; ///< first voxel of the block
  int Size = 1;                         ///< voxels a side (a power of two)
  int Dimension = 3;

  /// Doubled-lattice coordinate of the leaf's low corner along `axis`.
  std::int64_t Low(int axis) const { return Dimension == 2 && axis == 2 ? 0 : 2 * std::int64_t(Origin[axis]); }
  /// Doubled-lattice extent of the leaf (twice its size).
  std::int64_t Extent() const { return 2 * std::int64_t(Size); }
  /// The leaf's voxel at corner `c`.
  std::array<int, 3> CornerVoxel(int c) const
  {
    return { Origin[0] + ((c & 1) ? Size - 1 : 0), Origin[1] + ((c & 2) ? Size - 1 : 0),
      Dimension == 2 ? 0 : Origin[2] + ((c & 4) ? Size - 1 : 0) };
  }
};

/// The two axes spanning a face (or the axes other than `axis`), in increasing order.
inline std::array<int, 2> OtherAxes(int axis)
{
  return axis == 0 ? std::array<int, 2>{ 1, 2 } : (axis == 1 ? std::array<int, 2>{ 0, 2 } : std::array<int, 2>{ 0, 1 });
}

/// p8est edge index of the edge parallel to `axis` whose other coordinates are
/// on the sides given by bits `lowBit` (lower other axis) and `highBit`.
inline int CubeEdge(int axis, int lowBit, int highBit) { return 4 * axis + lowBit + 2 * highBit; }

/// p8est edge index of the edge parallel to `axis` through the corner whose
/// side along each axis is given by `bits` (bits[axis] is ignored).
inline int CubeEdgeThrough(int axis, const std::array<int, 3>& bits)
{
  const auto others = OtherAxes(axis);
  return CubeEdge(axis, bits[others[0]], bits[others[1]]);
}

/// Cube corner of corner q (bit 0: high along the face's first axis, bit 1:
/// along its second) of cube face `face` (= 2 axis + side).
inline int FaceCornerToCube(int face, int q)
{
  const int axis = face / 2, side = face % 2;
  const auto others = OtherAxes(axis);
  return (side << axis) | ((q & 1) << others[0]) | ((q >> 1) << others[1]);
}

/// Cube edge of edge e of cube face `face`; face edges run 0: b = 0, 1: a = 1,
/// 2: b = 1, 3: a = 0 (a, b: the face's first and second axes).
inline int FaceEdgeToCube(int face, int e)
{
  const int axis = face / 2, side = face % 2;
  const auto others = OtherAxes(axis);
  std::array<int, 3> bits{ 0, 0, 0 };
  bits[axis] = side;
  const int along = (e % 2 == 0) ? others[0] : others[1];
  const int fixedAxis = (e % 2 == 0) ? others[1] : others[0];
  bits[fixedAxis] = (e == 1 || e == 2) ? 1 : 0;
  return CubeEdgeThrough(along, bits);
}

/// The four corners of a square (or of a cube face, as face corners) in
/// counter-clockwise ring order; ring side i joins kRingCorners[i] to
/// kRingCorners[i + 1] and is face edge i.
constexpr int kRingCorners[4] = { 0, 1, 3, 2 };

/// An octree leaf after refinement, with what its neighbours impose on it.
struct OctreeLeaf
{
  LeafBox Box;
  std::int32_t First = 0;  ///< smaller label held by the leaf
  std::int32_t Second = 0; ///< larger label (== First: a uniform leaf)
  /// 3D: bit e set when cube edge e carries a midpoint vertex from a finer
  /// neighbour; 2D: bit f set when face (side) f does.
  std::uint16_t EdgeMidpoints = 0;
  /// 3D: bit f set when face f is covered by four finer leaves.
  std::uint8_t SplitFaces = 0;

  bool IsProper() const { return First != Second; }
};

} // namespace labelmesher

#endif
