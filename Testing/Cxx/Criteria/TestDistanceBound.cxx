// SPDX-License-Identifier: GPL-2.0-or-later
//
// WithinDistance (Filters/Core/Criteria/DistanceBound.h), the rigorous test
// "every point of the element lies within h of the union of the pieces", and
// SatisfiesFidelity (Filters/Core/Criteria/LeafFidelity.h), both one-sided
// bounds between a leaf's cone patch and the image boundary in the closed
// leaf. Distances are chosen so that the exact answer is known; each bound is
// tried just above and just below it (d +- 1e-6, well outside the 1e-9
// round-off allowance).

#include "Criteria/DistanceBound.h"
#include "Criteria/LeafFidelity.h"
#include "Fill/LeafSurfacePatch.h"
#include "Octree/LatticeLabels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace labelmesher
{
namespace
{

constexpr double kJust = 1e-6;

ConvexPiece Segment(Point3 a, Point3 b) { return ConvexPiece{ 2, { a, b } }; }
ConvexPiece Triangle(Point3 a, Point3 b, Point3 c) { return ConvexPiece{ 3, { a, b, c } }; }
ConvexPiece Quad(Point3 a, Point3 b, Point3 c, Point3 d) { return ConvexPiece{ 4, { a, b, c, d } }; }
ConvexPiece Point(Point3 a) { return Segment(a, a); }

/// The axis-aligned square [x0, x1] x [y0, y1] in the plane z.
ConvexPiece SquareXY(double x0, double y0, double x1, double y1, double z = 0.0)
{
  return Quad({ x0, y0, z }, { x1, y0, z }, { x1, y1, z }, { x0, y1, z });
}

ConvexPiece Moved(ConvexPiece piece, const Point3& by)
{
  for (int i = 0; i < piece.Count; ++i)
    for (int a = 0; a < 3; ++a)
      piece.Points[i][a] += by[a];
  return piece;
}

/// WithinDistance at d + kJust and not at d - kJust.
void ExpectBoundAt(const ConvexPiece& element, const std::vector<ConvexPiece>& pieces, double d, int maxDepth = 8)
{
  EXPECT_TRUE(WithinDistance(element, pieces, d + kJust, maxDepth)) << "h = d + 1e-6, d = " << d;
  EXPECT_FALSE(WithinDistance(element, pieces, d - kJust, maxDepth)) << "h = d - 1e-6, d = " << d;
}

// ---- one piece at a known distance --------------------------------------------

TEST(DistanceBound, SegmentAgainstAParallelSegment)
{
  // Offset by (0, 0.3, 0.4): distance 0.5 everywhere.
  const ConvexPiece element = Segment({ 0, 0, 0 }, { 1, 0, 0 });
  ExpectBoundAt(element, { Moved(element, { 0, 0.3, 0.4 }) }, 0.5);
  // A segment at right angles, its nearest point (0, 0, 2) over the element's
  // end: the far end (1, 0, 0) is sqrt(1 + 4) away.
  ExpectBoundAt(element, { Segment({ 0, -1, 2 }, { 0, 1, 2 }) }, std::sqrt(5.0));
}

TEST(DistanceBound, TriangleAgainstAParallelTriangleAndASegment)
{
  const ConvexPiece element = Triangle({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 });
  ExpectBoundAt(element, { Moved(element, { 0, 0, 0.25 }) }, 0.25);
  // The segment (0, 0, 2)-(1, 0, 2): the vertex (0, 1, 0) is farthest, at
  // sqrt(1 + 4); the other two are 2 away.
  ExpectBoundAt(element, { Segment({ 0, 0, 2 }, { 1, 0, 2 }) }, std::sqrt(5.0));
}

TEST(DistanceBound, SquareAgainstAShiftedSquare)
{
  // The unit square against itself moved by 0.5 along x and 0.75 along z:
  // the corners at x = 0 are 0.5 from it sideways and 0.75 below:
  // sqrt(0.25 + 0.5625) = sqrt(0.8125).
  const ConvexPiece element = SquareXY(0, 0, 1, 1);
  ExpectBoundAt(element, { Moved(element, { 0.5, 0, 0.75 }) }, std::sqrt(0.8125));
  // A square against a triangle over half of it, 1 above: the corner (1, 0)
  // outside the triangle (0,0)-(0,1)-(1,1) is sqrt(0.5 + 1) away.
  ExpectBoundAt(element, { Triangle({ 0, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 }) }, std::sqrt(1.5));
}

TEST(DistanceBound, AnElementEqualToAPieceIsWithinZero)
{
  const ConvexPiece pieces[] = { Segment({ 0.2, 0.1, 0.7 }, { 1.9, -0.4, 0.3 }),
    Triangle({ 0.2, 0.1, 0.7 }, { 1.9, -0.4, 0.3 }, { 0.5, 1.5, -0.2 }),
    Quad({ 0, 0, 0 }, { 1, 0, 0.5 }, { 1, 1, 1.5 }, { 0, 1, 1 }) };
  for (const ConvexPiece& piece : pieces)
    EXPECT_TRUE(WithinDistance(piece, { piece }, 0.0)) << piece.Count << " points";
}

TEST(DistanceBound, NoPiecesMeansNotWithinAnyDistance)
{
  EXPECT_FALSE(WithinDistance(Segment({ 0, 0, 0 }, { 1, 0, 0 }), {}, 1e9));
}

// ---- unions that need subdivision ---------------------------------------------

TEST(DistanceBound, SegmentBetweenTwoPointsNeedsSubdivision)
{
  // Pieces: the points 0 and 2 on the x axis; element: the segment between
  // them. Each end is at distance 0 from the union, but no single piece is
  // within h of both ends; the farthest point of the element from the union
  // is its midpoint, at 1.
  const ConvexPiece element = Segment({ 0, 0, 0 }, { 2, 0, 0 });
  const std::vector<ConvexPiece> ends{ Point({ 0, 0, 0 }), Point({ 2, 0, 0 }) };
  ExpectBoundAt(element, ends, 1.0);
}

TEST(DistanceBound, TriangleBetweenThreePointsNeedsSubdivision)
{
  // The right triangle (0,0)-(2,0)-(0,2) against its three vertices as point
  // pieces: the point of the triangle farthest from all three is the
  // circumcentre (1, 1), the midpoint of the hypotenuse, sqrt(2) from each.
  const ConvexPiece element = Triangle({ 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 });
  const std::vector<ConvexPiece> corners{ Point({ 0, 0, 0 }), Point({ 2, 0, 0 }), Point({ 0, 2, 0 }) };
  ExpectBoundAt(element, corners, std::sqrt(2.0));
}

TEST(DistanceBound, SquareOverAFrameNeedsSubdivision)
{
  // The square [0, 2]^2 against a frame of four strips around the hole
  // [0.5, 1.5]^2, all in its plane: every corner is on the frame, and the
  // centre (1, 1) is 0.5 from it.
  const ConvexPiece element = SquareXY(0, 0, 2, 2);
  const std::vector<ConvexPiece> frame{ SquareXY(0, 0, 2, 0.5), SquareXY(0, 1.5, 2, 2), SquareXY(0, 0.5, 0.5, 1.5),
    SquareXY(1.5, 0.5, 2, 1.5) };
  ExpectBoundAt(element, frame, 0.5);
  EXPECT_FALSE(WithinDistance(element, frame, 0.0)); // the hole is not covered
}

TEST(DistanceBound, WhatTheDepthCannotDecideCountsAsAViolation)
{
  // The segment between two points (distance 1 at its midpoint): with no
  // subdivision allowed the union is not proved to cover it, so the answer is
  // "no" even where the truth is "yes"; one subdivision proves it.
  const ConvexPiece element = Segment({ 0, 0, 0 }, { 2, 0, 0 });
  const std::vector<ConvexPiece> ends{ Point({ 0, 0, 0 }), Point({ 2, 0, 0 }) };
  EXPECT_FALSE(WithinDistance(element, ends, 1.5, 0));
  EXPECT_TRUE(WithinDistance(element, ends, 1.5, 1));

  // Points 0 and 2/3 against the segment [0, 1]: the distance to the union
  // is largest, 1/3, at x = 1/3 and at x = 1. At h = 1/3 exactly the bound
  // holds, but x = 1/3 is no subdivision point, and every piece of the
  // element around it has one end farther than h from each point: never
  // proved, so "no" at any depth that keeps pieces wider than the round-off
  // allowance. With a margin of 0.01 depth 8 (pieces of 1/256) proves it.
  const ConvexPiece unit = Segment({ 0, 0, 0 }, { 1, 0, 0 });
  const std::vector<ConvexPiece> points{ Point({ 0, 0, 0 }), Point({ 2.0 / 3.0, 0, 0 }) };
  EXPECT_FALSE(WithinDistance(unit, points, 1.0 / 3.0, 8));
  EXPECT_FALSE(WithinDistance(unit, points, 1.0 / 3.0, 16));
  EXPECT_TRUE(WithinDistance(unit, points, 1.0 / 3.0 + 0.01, 8));
  EXPECT_FALSE(WithinDistance(unit, points, 1.0 / 3.0 - kJust, 30)); // and below it never
}

TEST(DistanceBound, FarPiecesDoNotChangeTheAnswer)
{
  // The cases above again among many pieces too far to matter (40 unit
  // squares 50 to 90 away): the answer is the one the near pieces give, just
  // above and just below each distance, and at h = 0 for an exact coverage.
  std::vector<ConvexPiece> far;
  for (int t = 0; t < 40; ++t)
    far.push_back(SquareXY(50.0 + t, -3.0, 51.0 + t, -2.0, 0.5 * t));
  auto with = [&far](std::vector<ConvexPiece> near) {
    near.insert(near.begin() + near.size() / 2, far.begin(), far.end());
    return near;
  };
  ExpectBoundAt(Segment({ 0, 0, 0 }, { 2, 0, 0 }), with({ Point({ 0, 0, 0 }), Point({ 2, 0, 0 }) }), 1.0);
  ExpectBoundAt(Triangle({ 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }),
    with({ Point({ 0, 0, 0 }), Point({ 2, 0, 0 }), Point({ 0, 2, 0 }) }), std::sqrt(2.0));
  ExpectBoundAt(SquareXY(0, 0, 2, 2),
    with({ SquareXY(0, 0, 2, 0.5), SquareXY(0, 1.5, 2, 2), SquareXY(0, 0.5, 0.5, 1.5), SquareXY(1.5, 0.5, 2, 1.5) }),
    0.5);
  EXPECT_TRUE(WithinDistance(SquareXY(0, 0, 2, 2, 0),
    with({ SquareXY(0, 0, 1, 1), SquareXY(1, 0, 2, 1), SquareXY(0, 1, 1, 2), SquareXY(1, 1, 2, 2) }), 0.0));
  // Only far pieces: not within any distance short of theirs.
  EXPECT_FALSE(WithinDistance(Segment({ 0, 0, 0 }, { 2, 0, 0 }), far, 10.0));
  EXPECT_TRUE(WithinDistance(Segment({ 0, 0, 0 }, { 2, 0, 0 }), far, 100.0));
}

// ---- coverage at h = 0 -------------------------------------------------------------

TEST(DistanceBound, CoplanarPiecesCoveringAnElementExactlyGiveDistanceZero)
{
  // The square [0, 2]^2 in the plane z = 3 against its four unit quarters:
  // every point of it is on some quarter, distance 0, although no quarter
  // holds all its corners and subdivision alone never reaches 0.
  const ConvexPiece element = SquareXY(0, 0, 2, 2, 3);
  const std::vector<ConvexPiece> quarters{ SquareXY(0, 0, 1, 1, 3), SquareXY(1, 0, 2, 1, 3), SquareXY(0, 1, 1, 2, 3),
    SquareXY(1, 1, 2, 2, 3) };
  EXPECT_TRUE(WithinDistance(element, quarters, 0.0));
  // The same in the planes x = const and y = const (voxel faces of the other
  // two orientations), and triangles covered by squares.
  auto swap = [](ConvexPiece p, int a, int b) {
    for (int i = 0; i < p.Count; ++i)
      std::swap(p.Points[i][a], p.Points[i][b]);
    return p;
  };
  for (int axis : { 0, 1 })
  {
    std::vector<ConvexPiece> turned;
    for (const ConvexPiece& q : quarters)
      turned.push_back(swap(q, axis, 2));
    EXPECT_TRUE(WithinDistance(swap(element, axis, 2), turned, 0.0)) << "plane normal to axis " << axis;
  }
  EXPECT_TRUE(WithinDistance(Triangle({ 0, 0, 3 }, { 2, 0, 3 }, { 0, 2, 3 }), quarters, 0.0));
  // Without the quarter [1, 2]^2 the corner (2, 2) is 1 from the rest: not
  // within 0.
  const std::vector<ConvexPiece> three(quarters.begin(), quarters.begin() + 3);
  EXPECT_FALSE(WithinDistance(element, three, 0.0));
  // The pieces must lie in the element's plane: the quarters at z = 3 + 1e-6
  // cover nothing at h = 0.
  std::vector<ConvexPiece> lifted;
  for (const ConvexPiece& q : quarters)
    lifted.push_back(Moved(q, { 0, 0, kJust }));
  EXPECT_FALSE(WithinDistance(element, lifted, 0.0));
  EXPECT_TRUE(WithinDistance(element, lifted, 2 * kJust));
}

TEST(DistanceBound, CollinearSegmentsCoveringASegmentGiveDistanceZero)
{
  // 2D (pixel edges): the segment [0, 2] on the line y = 0.5 against [0, 1]
  // and [1, 2] on that line.
  const ConvexPiece element = Segment({ 0, 0.5, 0 }, { 2, 0.5, 0 });
  EXPECT_TRUE(WithinDistance(
    element, { Segment({ 0, 0.5, 0 }, { 1, 0.5, 0 }), Segment({ 2, 0.5, 0 }, { 1, 0.5, 0 }) }, 0.0));
  // With a gap (0.9, 1.1): its middle is 0.1 from the pieces.
  const std::vector<ConvexPiece> gap{ Segment({ 0, 0.5, 0 }, { 0.9, 0.5, 0 }),
    Segment({ 1.1, 0.5, 0 }, { 2, 0.5, 0 }) };
  EXPECT_FALSE(WithinDistance(element, gap, 0.0));
  ExpectBoundAt(element, gap, 0.1);
  // Vertical: the segment x = 1, y in [0, 2], covered by two pixel edges.
  EXPECT_TRUE(WithinDistance(Segment({ 1, 0, 0 }, { 1, 2, 0 }),
    { Segment({ 1, 0, 0 }, { 1, 1, 0 }), Segment({ 1, 1, 0 }, { 1, 2, 0 }) }, 0.0));
}

TEST(DistanceBound, ExactCoverageOutsideAxisAlignedPlanesIsNotRecognised)
{
  // A tilted square exactly covered by its two halves is at distance 0, but
  // only axis-aligned planes are tested for coverage: at h = 0 the answer
  // errs towards "no" (which only refines more); at h = 0.01 subdivision
  // proves it.
  const ConvexPiece element = Quad({ 0, 0, 0 }, { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 0 });
  const std::vector<ConvexPiece> halves{ Triangle({ 0, 0, 0 }, { 1, 0, 1 }, { 1, 1, 1 }),
    Triangle({ 0, 0, 0 }, { 1, 1, 1 }, { 0, 1, 0 }) };
  EXPECT_FALSE(WithinDistance(element, halves, 0.0));
  EXPECT_TRUE(WithinDistance(element, halves, 0.01));
}

// ---- SatisfiesFidelity -------------------------------------------------------------

LeafBox Square(int x, int y, int size) { return LeafBox{ { x, y, 0 }, size, 2 }; }
LeafBox Cube(int x, int y, int z, int size) { return LeafBox{ { x, y, z }, size, 3 }; }

/// Both one-sided bounds just above the distances (toMesh, toImage) pass;
/// either just below fails.
void ExpectFidelityBoundsAt(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second,
  double toMesh, double toImage)
{
  EXPECT_TRUE(SatisfiesFidelity(image, leaf, first, second, toMesh + kJust, toImage + kJust));
  EXPECT_FALSE(SatisfiesFidelity(image, leaf, first, second, toMesh - kJust, toImage + kJust))
    << "h(I,M) just below " << toMesh;
  EXPECT_FALSE(SatisfiesFidelity(image, leaf, first, second, toMesh + kJust, toImage - kJust))
    << "h(M,I) just below " << toImage;
}

TEST(LeafFidelity, FlatInterfaceMatchesThePatchExactly)
{
  // 2D: rows j >= 12 are label 1; the leaf of 8x8 pixels at (8, 8) has its
  // left and right sides crossed at their midpoints, so its patch is the
  // segment y = 11.5 across it, which is the interface: distance 0 both ways.
  LabelImage image(24, 24, 1);
  for (int j = 12; j < 24; ++j)
    for (int i = 0; i < 24; ++i)
      image(i, j, 0) = 1;
  EXPECT_TRUE(SatisfiesFidelity(image, Square(8, 8, 8), 0, 1, 0.0, 0.0));
  // 3D: the plane k >= 6 through the middle of the leaf (4..7)^3; the patch,
  // the cone over the midpoints of its four vertical edges, lies in the
  // plane z = 5.5 of the interface's voxel faces.
  LabelImage volume(12, 12, 12);
  for (int k = 6; k < 12; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i)
        volume(i, j, k) = 1;
  EXPECT_TRUE(SatisfiesFidelity(volume, Cube(4, 4, 4, 4), 0, 1, 0.0, 0.0));
}

TEST(LeafFidelity, NotchFarFromThePatchFailsEachSideAtItsOwnDistance)
{
  // As above, with a notch of background pixels (11..12, 12..13) cut into
  // label 1 from the interface. The patch stays the segment y = 11.5:
  //  - image to mesh: the notch's top edge, y = 13.5, is 2 from the patch;
  //  - mesh to image: under the notch the patch has no interface of its own;
  //    its point (11.5, 11.5) is 1 from the notch's walls x = 10.5, 12.5.
  LabelImage image(24, 24, 1);
  for (int j = 12; j < 24; ++j)
    for (int i = 0; i < 24; ++i)
      image(i, j, 0) = (i == 11 || i == 12) && j <= 13 ? 0 : 1;
  ExpectFidelityBoundsAt(image, Square(8, 8, 8), 0, 1, 2.0, 1.0);
}

/// The plane k >= 6 (label 1 above) in a 12^3 image, with the voxel `dent`
/// turned to background.
LabelImage PlaneWithDent(int di, int dj, int dk)
{
  LabelImage volume(12, 12, 12);
  for (int k = 6; k < 12; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i)
        volume(i, j, k) = i == di && j == dj && k == dk ? 0 : 1;
  return volume;
}

TEST(LeafFidelity, DentInAPlaneFailsEachSideAtItsOwnDistance)
{
  // 3D: the plane k >= 6 through the leaf (4..7)^3, its voxel (6, 4, 6) just
  // above the plane turned to background. The patch is the plane z = 5.5
  // (four cone triangles from the centre (5.5, 5.5, 5.5)); the dent's top
  // face, z = 6.5, is 1 above it (and over one cone triangle), and the patch
  // point (6, 4, 5.5) under the dent is 0.5 from the dent's walls.
  ExpectFidelityBoundsAt(PlaneWithDent(6, 4, 6), Cube(4, 4, 4, 4), 0, 1, 1.0, 0.5);
}

TEST(LeafFidelity, DistanceReachedOverAPatchEdgeIsCertifiedOnlyWithAMargin)
{
  // The dent at (5, 5, 6) instead: its top face lies over the patch's edge
  // from the centre to the corner (3.5, 3.5), so no cone triangle alone is
  // within 1 of all its corners, and every piece of it that straddles that
  // edge has a corner farther than 1 from each triangle. h(I,M) is exactly 1,
  // yet only a margin (1.01 here) is proved within the subdivision depth:
  // the test errs towards refining, never towards accepting (1 - 1e-6 fails).
  const LabelImage volume = PlaneWithDent(5, 5, 6);
  EXPECT_FALSE(SatisfiesFidelity(volume, Cube(4, 4, 4, 4), 0, 1, 1.0 + kJust, 0.5 + kJust));
  EXPECT_TRUE(SatisfiesFidelity(volume, Cube(4, 4, 4, 4), 0, 1, 1.01, 0.5 + kJust));
  EXPECT_FALSE(SatisfiesFidelity(volume, Cube(4, 4, 4, 4), 0, 1, 1.0 - kJust, 1.0));
}

TEST(LeafFidelity, PatchMustStayNearItsOwnInterfaceNotAThirdLabels)
{
  // The leaf-level case behind LabelOctreeMesher.SurfacePatchStaysNearItsOwnInterfaceNotAThirdLabels
  // (TestLabelOctreeMesher.cxx), moved to a 16x16 image: label 4 fills
  // x <= 11, y >= 7; label 1 fills x >= 8, y <= 6. The 4x4 leaf at (4, 4)
  // holds background (rows 4..6) and one row of label 4 (row 7). The boundary
  // of label 1 runs down its right side, so its corner (lattice (8, 4), index
  // (7.5, 3.5)) is a 0-point and a transition of its ring, and its patch runs
  // from the centre (5.5, 5.5) to that corner and to the midpoint (3.5, 5.5)
  // of its left side. The interface between its own labels, 0 and 4, is the
  // pixel edges y = 6.5: the corner is 3 from it, so h(M,I) = 3, though the
  // patch is never more than 1.5 from some boundary in the leaf (label 1's,
  // on its right side). Image to mesh, the far end (7.5, 6.5) of the
  // interface is 3 / sqrt(2) from the patch's diagonal segment.
  LabelImage image(16, 16, 1);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i)
      image(i, j, 0) = (i <= 11 && j >= 7) ? 4 : (i >= 8 && j <= 6 ? 1 : 0);
  const LeafBox leaf = Square(4, 4, 4);
  ExpectFidelityBoundsAt(image, leaf, 0, 4, 3.0 / std::sqrt(2.0), 3.0);

  // Measured against every boundary in the leaf (what the test once did),
  // the patch would pass h(M,I) <= 2.
  const std::vector<ConvexPiece> patch = ConeSurfacePatch(leaf, LeafCornerSigns(image, leaf, 0, 4));
  const LeafImageBoundary boundary = ImageBoundaryInLeaf(image, leaf, 0, 4);
  ASSERT_EQ(patch.size(), 2u);
  ASSERT_LT(boundary.Interface.size(), boundary.All.size());
  for (const ConvexPiece& piece : patch)
    EXPECT_TRUE(WithinDistance(piece, boundary.All, 1.5 + kJust));
  EXPECT_FALSE(SatisfiesFidelity(image, leaf, 0, 4, 3.0, 2.0));
}

TEST(LeafFidelity, LeafWithoutAPatchFails)
{
  // An island of label 1 inside the leaf: its ring has no transition, the
  // cone patch is empty and cannot stand for the island's boundary at any
  // distance.
  LabelImage image(8, 8, 1);
  image(3, 3, 0) = image(4, 3, 0) = image(4, 4, 0) = 1;
  const LeafBox leaf = Square(2, 2, 4);
  EXPECT_TRUE(ConeSurfacePatch(leaf, LeafCornerSigns(image, leaf, 0, 1)).empty());
  EXPECT_FALSE(SatisfiesFidelity(image, leaf, 0, 1, 100.0, 100.0));
}

TEST(LeafFidelity, ImageBoundaryInLeafListsEachFaceOnceAndItsInterfaceApart)
{
  // The 2D leaf of the third-label case: 4 pixel edges between 0 and 4 (row
  // 6 against row 7) and 3 between 0 and 1 on the leaf's right side (rows
  // 4..6 of x = 7 against x = 8); label 4 meets label 4 across the other
  // sides, so nothing else.
  LabelImage image(16, 16, 1);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i)
      image(i, j, 0) = (i <= 11 && j >= 7) ? 4 : (i >= 8 && j <= 6 ? 1 : 0);
  const LeafImageBoundary boundary = ImageBoundaryInLeaf(image, Square(4, 4, 4), 0, 4);
  EXPECT_EQ(boundary.Interface.size(), 4u);
  EXPECT_EQ(boundary.All.size(), 7u);
  for (const ConvexPiece& edge : boundary.Interface)
  {
    ASSERT_EQ(edge.Count, 2);
    EXPECT_EQ(edge.Points[0][1], 6.5);
    EXPECT_EQ(edge.Points[1][1], 6.5);
  }
}

} // namespace
} // namespace labelmesher
