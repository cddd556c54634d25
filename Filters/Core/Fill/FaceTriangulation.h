// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_FaceTriangulation_h
#define labelmesher_FaceTriangulation_h

/**
 * @file FaceTriangulation.h
 * How one square face of an octree leaf is triangulated (section 3.1.2,
 * Figures 6 and 10, Algorithm 3). The rule is a function of data that both
 * leaves sharing the face see identically — the labels at its corners, the
 * midpoints on its edges, whether it is split by four finer leaves — and of the
 * face's position only, never of which leaf asks: that is what makes the fill
 * conforming.
 *
 * Points are given in face-local quarter units (a, b) in {0..4}^2, a along the
 * lower-numbered in-face axis. Kinds:
 *  - Plain: no extra point; the fixed Kuhn diagonal (0,0)-(4,4), which is the
 *    diagonal the six-tetrahedra split of a cube induces on its faces.
 *  - Fan: some edge midpoints; fan from the face centre (TRIANGULATION_1).
 *  - Split: covered by four finer leaves; their four plain sub-faces.
 *  - Crossed: corners of both labels (proper boundary leaves only). The
 *    intersection edge joins the two transition points of the face's ring: the
 *    midpoint of an edge whose ends carry different labels, or a 0-corner
 *    between corners of different labels (the 81-case table of Figure 6,
 *    restricted to what the single manifold condition admits: no saddle, no
 *    two adjacent 0-corners), and the pieces
 *    on either side are triangulated by the candidate — fan from the face
 *    centre or from a piece vertex — whose cone tetrahedra have the largest
 *    minimum dihedral angle. The choice is computed once into a table keyed
 *    by the corner labels.
 */

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

struct FacePoint
{
  int A = 0, B = 0; ///< quarter units, 0..4
  bool operator==(const FacePoint& o) const { return A == o.A && B == o.B; }
};

struct FaceTriangle
{
  std::array<FacePoint, 3> Points;
  /// Face corner (0..3, bit 0 = high a, bit 1 = high b), not a 0-corner, whose
  /// label the triangle's side of the intersection edge carries.
  int SideCorner = 0;
};

enum class FaceKind
{
  Plain,
  Fan,
  Split,
  Crossed
};

/// Face edges: 0 (b = 0), 1 (a = 4), 2 (b = 4), 3 (a = 0).
/// `midpointMask` bit i: face edge i carries its midpoint (Fan only).
/// Crossed only: bit q of `negative` when corner q carries the second label,
/// of `zero` when it lies on the image boundary (a 0-vertex).
std::vector<FaceTriangle> TriangulateFace(
  FaceKind kind, unsigned midpointMask, unsigned negative = 0, unsigned zero = 0);

/// A face is crossed when it has corners of both labels.
bool IsCrossedFace(unsigned negative, unsigned zero);

/// Face edge i joins these two face corners.
inline std::array<int, 2> FaceEdgeCorners(int edge)
{
  static const int table[4][2] = { { 0, 1 }, { 1, 3 }, { 2, 3 }, { 0, 2 } };
  return { table[edge][0], table[edge][1] };
}

/// Smallest dihedral angle (degrees) of the tetrahedra coning every triangle
/// of a unit face triangulation to the apex at height `apexHeight` above the
/// face centre (0.5 for the face of a cube).
double ConedMinimumDihedralAngle(const std::vector<FaceTriangle>& triangles, double apexHeight);

} // namespace labelmesher

#endif
