// SPDX-License-Identifier: GPL-2.0-or-later
//
// SatisfiesSingleManifoldCondition (Filters/Core/Criteria/SingleManifoldCondition.h)
// on hand-made leaves: one test per case the header lists, in 2D and in 3D,
// each with a variant that passes and one that fails where both exist. Every
// failing case says in its comment why false is the right answer; the
// verdicts are the only thing asserted. The last tests pin, leaf by leaf, the
// two random 2D seeds that once failed the whole mesher (TestMesherProperties,
// MesherPropertiesRegression.SeedsThatOnceFailed).
//
// Conventions (LabelImage.h, LatticeLabels.h): voxel (i, j, k) spans
// [i - 1/2, i + 1/2] x ...; lattice point (i, j, k) is the voxel corner between
// voxels i - 1 and i along x (and so on), so a leaf with Origin o and Size s
// has its corners at lattice o and o + s. A lattice point is a "0-point" when
// the voxels around it carry different labels. Outside the image is label 0.

#include "Criteria/LeafFidelity.h"
#include "Criteria/SingleManifoldCondition.h"
#include "HandMadeImages.h"
#include "RandomLabelImages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace labelmesher
{
namespace
{

using testing::Picture;
using testing::PlaneWithOneVoxel;
using testing::Volume;

LeafBox Square(int x, int y, int size) { return LeafBox{ { x, y, 0 }, size, 2 }; }
LeafBox Cube(int x, int y, int z, int size) { return LeafBox{ { x, y, z }, size, 3 }; }

bool Manifold(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second)
{
  return SatisfiesSingleManifoldCondition(image, leaf, first, second);
}

// ---- what is never a manifold leaf ------------------------------------------

TEST(SingleManifoldCondition, SingleVoxelsAndUniformLabelPairsAreNeverAccepted)
{
  // A single voxel holds one label, so it is never a proper leaf; a leaf
  // asked about one label twice has no interface. The same leaf asked about
  // its two labels is a plane through it and passes.
  const LabelImage image = Volume(8, [](int, int, int k) { return k >= 4 ? 1 : 0; });
  EXPECT_FALSE(Manifold(image, Cube(3, 3, 3, 1), 0, 1));
  EXPECT_FALSE(Manifold(image, Cube(2, 2, 2, 4), 1, 1));
  EXPECT_TRUE(Manifold(image, Cube(2, 2, 2, 4), 0, 1));
}

// ---- edge runs ---------------------------------------------------------------

TEST(SingleManifoldCondition, TwoDimensionalStraightInterfaceCrossingTwoSidesPasses)
{
  // Rows j >= 4 are label 1: the interface is the line between rows 3 and 4,
  // crossing the left and right sides of the leaf once each.
  const LabelImage image = Picture({
    "11111111",
    "11111111",
    "11111111",
    "11111111",
    "........",
    "........",
    "........",
    "........",
  });
  EXPECT_TRUE(Manifold(image, Square(2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, TwoDimensionalSideCrossedTwiceFails)
{
  // Label 1 enters the leaf (pixels 2..5) through its left side and leaves
  // through the same side (rows 3 and 4): along that side the lattice signs
  // are +, 0, -, 0, +, two runs of boundary points (Figure 9a). The cone from
  // the centre meets every side at most once, so it cannot follow this bump.
  // Everything else about the leaf is simple: one path inside, both labels
  // 4-connected.
  const LabelImage image = Picture({
    "........",
    "........",
    "........",
    "1111....",
    "1111....",
    "........",
    "........",
    "........",
  });
  EXPECT_FALSE(Manifold(image, Square(2, 2, 4), 0, 1));
  // Widened to every row (label 1 in columns 0..3), the boundary crosses the
  // bottom and top sides once each instead.
  const LabelImage wide = Picture({
    "1111....",
    "1111....",
    "1111....",
    "1111....",
    "1111....",
    "1111....",
    "1111....",
    "1111....",
  });
  EXPECT_TRUE(Manifold(wide, Square(2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, TwoDimensionalRunEndingAtAZeroCornerPasses)
{
  // The diagonal staircase j >= i (label 1 above it) passes through the
  // leaf's corners (2, 2) and (6, 6), which are 0-points. The bottom side
  // reads 0, 0, +, +, + and the right side +, +, +, 0, 0: short runs of
  // boundary points hanging from the 0-corners, joined along the side by the
  // staircase's own pixel edges; the left and top sides are label 1 but for
  // their 0-corner, and inside the staircase is one simple path.
  const LabelImage image = Picture({
    "11111111",
    "1111111.",
    "111111..",
    "11111...",
    "1111....",
    "111.....",
    "11......",
    "1.......",
  });
  EXPECT_TRUE(Manifold(image, Square(2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalEdgeCrossedTwiceFails)
{
  // A bar of label 1 (i <= 3, 3 <= j <= 4, all k) enters the leaf at
  // (2..5)^3 through its face x = 2 and leaves through it again: the leaf
  // edges along y on that face (x = 2, z = 2 and z = 6) read +, 0, -, 0, +.
  const LabelImage image = Volume(8, [](int i, int j, int) { return i <= 3 && j >= 3 && j <= 4 ? 1 : 0; });
  EXPECT_FALSE(Manifold(image, Cube(2, 2, 2, 4), 0, 1));
  // Widened to the half-space j >= 3 (all i, k), the boundary is the plane
  // between j = 2 and 3, which crosses each of those edges once.
  const LabelImage slab = Volume(8, [](int, int j, int) { return j >= 3 ? 1 : 0; });
  EXPECT_TRUE(Manifold(slab, Cube(2, 2, 2, 4), 0, 1));
}

// ---- face crossings ----------------------------------------------------------

TEST(SingleManifoldCondition, ThreeDimensionalPlaneThroughTheLeafPasses)
{
  // k >= 4 is label 1: the interface is the plane between layers 3 and 4,
  // crossing the four side faces of the leaf (2..5)^3 once each.
  const LabelImage image = Volume(8, [](int, int, int k) { return k >= 4 ? 1 : 0; });
  EXPECT_TRUE(Manifold(image, Cube(2, 2, 2, 4), 0, 1));
  // And the same plane in a leaf that holds label 1 below it and 0 above.
  const LabelImage flipped = Volume(8, [](int, int, int k) { return k >= 4 ? 0 : 1; });
  EXPECT_TRUE(Manifold(flipped, Cube(2, 2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalIslandOnAnUncrossedFaceFails)
{
  // The plane k >= 4, and one voxel of label 1 under the middle of the leaf's
  // bottom face (voxel (3, 3, 1), outside the leaf): the bottom face's
  // corners are all label 0, so the patch does not cross it, yet image
  // boundary touches the face inside (Figure 9b's island): the face stencil
  // would not have it, and the leaf's interface would be two pieces.
  const LabelImage island = PlaneWithOneVoxel(8, 4, 3, 3, 1, 1);
  EXPECT_FALSE(Manifold(island, Cube(2, 2, 2, 4), 0, 1));
  // Two voxels lower it no longer touches the leaf.
  const LabelImage away = PlaneWithOneVoxel(8, 4, 3, 3, 0, 1);
  EXPECT_TRUE(Manifold(away, Cube(2, 2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalSecondBoundarySetOnACrossedFaceFails)
{
  // A leaf of 8 voxels (4..11)^3 cut by the plane k >= 10, and one voxel of a
  // third label outside its face x = 4, at (3, 7, 6): the face is crossed
  // (corners of both labels), but its boundary points are two sets, the
  // plane's line at z = 10 and the square (4, 7..8, 6..7) that the third
  // label touches, which no boundary segment joins. The patch has one
  // intersection edge per face; the second set would not be on it.
  const LabelImage apart = PlaneWithOneVoxel(16, 10, 3, 7, 6, 2);
  EXPECT_FALSE(Manifold(apart, Cube(4, 4, 4, 8), 0, 1));
  // The same voxel at (3, 7, 9), against the plane's line: its boundary
  // points are joined to the line through the boundary between it and label
  // 0 (one set), and the interface between the leaf's labels is still one
  // plane.
  const LabelImage touching = PlaneWithOneVoxel(16, 10, 3, 7, 9, 2);
  EXPECT_TRUE(Manifold(touching, Cube(4, 4, 4, 8), 0, 1));
}

// ---- saddles -------------------------------------------------------------------

TEST(SingleManifoldCondition, ThreeDimensionalSaddleFaceFailsEvenOverAnInteriorDisk)
{
  // Label 1 above the height field g(i, j) = 4 + max(0, |i + j - 7| - 1)
  // (leaf-local i, j, leaf (4..11)^3): a valley along the anti-diagonal. The
  // interface is a graph over the square, one disk, manifold everywhere (the
  // flat valley floor keeps it free of checkerboards). But towards the
  // corners (0, 0) and (7, 7) the height field rises above the leaf, so on
  // the top face label 0 holds those two corners and label 1 the other two:
  // +, -, +, - around its ring, a saddle, crossed by the boundary along two
  // arcs, while the patch meets each face in one intersection edge.
  auto height = [](int i, int j) { return 4 + std::max(0, std::abs(i + j - 7) - 1); };
  const LabelImage valley = Volume(16, [&](int i, int j, int k) { return k - 4 >= height(i - 4, j - 4) ? 1 : 0; });
  EXPECT_FALSE(Manifold(valley, Cube(4, 4, 4, 8), 0, 1));
  // A shallower valley, heights 3..6, stays below the top face (all of it
  // label 1): only the four side faces are crossed, each once.
  auto shallow = [](int i, int j) { return 3 + std::min(3, std::max(0, std::abs(i + j - 7) - 1)); };
  const LabelImage gentle = Volume(16, [&](int i, int j, int k) { return k - 4 >= shallow(i - 4, j - 4) ? 1 : 0; });
  EXPECT_TRUE(Manifold(gentle, Cube(4, 4, 4, 8), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalQuadrantSaddleFails)
{
  // Label 1 where exactly one of i >= 4, j >= 4 holds (all k): the faces
  // z = 2 and z = 6 of the leaf (2..5)^3 are saddles (+, -, +, -), and
  // inside, four interface faces meet along the line x = y = 4 (a pinched
  // edge): neither is one disk.
  const LabelImage image = Volume(8, [](int i, int j, int) { return (i >= 4) != (j >= 4) ? 1 : 0; });
  EXPECT_FALSE(Manifold(image, Cube(2, 2, 2, 4), 0, 1));
}

// ---- adjacent 0-corners ----------------------------------------------------------

TEST(SingleManifoldCondition, TwoDimensionalBoundaryAlongAWholeSideFails)
{
  // Label 1 fills x >= 6 and the upper left of the leaf (x <= 4, y >= 4):
  // the line between pixel columns 5 and 6 is image boundary along the whole
  // right side of the leaf (2..5)^2, so its two corners on that side are
  // adjacent 0-corners. A cone patch meets a side in one point; it cannot lie
  // along the side.
  const LabelImage image = Picture({
    "11111.11",
    "11111.11",
    "11111.11",
    "11111.11",
    "......11",
    "......11",
    "......11",
    "......11",
  });
  EXPECT_FALSE(Manifold(image, Square(2, 2, 4), 0, 1));
  // The column one pixel further right does not touch the leaf, which is
  // then crossed once by the L-shaped boundary of the upper left block.
  const LabelImage away = Picture({
    "11111..1",
    "11111..1",
    "11111..1",
    "11111..1",
    ".......1",
    ".......1",
    ".......1",
    ".......1",
  });
  EXPECT_TRUE(Manifold(away, Square(2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalBoundaryAlongAWholeFaceFails)
{
  // The 3D analogue: label 1 fills i >= 6 and the part k >= 4, i <= 4 of the
  // leaf (2..5)^3: the plane between layers i = 5 and 6 is image boundary over
  // the leaf's whole face x = 6 (all four corners 0, every edge of the face
  // on the boundary end to end).
  const LabelImage image = Volume(8, [](int i, int, int k) { return i >= 6 || (k >= 4 && i <= 4) ? 1 : 0; });
  EXPECT_FALSE(Manifold(image, Cube(2, 2, 2, 4), 0, 1));
  const LabelImage away = Volume(8, [](int i, int, int k) { return i >= 7 || (k >= 4 && i <= 4) ? 1 : 0; });
  EXPECT_TRUE(Manifold(away, Cube(2, 2, 2, 4), 0, 1));
}

// ---- separate pieces of boundary touching a leaf side ---------------------------

/// The image of LabelOctreeMesher.PiecesOfBoundaryTouchingALeafSideSeparatelyStaySeparate
/// (TestLabelOctreeMesher.cxx): a slab (rows 0..2) and a blob (rows 5..8,
/// columns 4..10) of label 5, one background row apart, the blob reaching
/// down with a stem pixel (7, 4); `stem` false leaves the stem out.
LabelImage SlabStemAndBlob(bool stem)
{
  LabelImage image(12, 9, 1);
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 12; ++i)
    {
      const bool slab = j <= 2, blob = j >= 5 && i >= 4 && i <= 10;
      image(i, j, 0) = slab || (stem && j == 4 && i == 7) || blob ? 5 : 0;
    }
  return image;
}

TEST(SingleManifoldCondition, TwoDimensionalSeparatePiecesTouchingASideCountSeparately)
{
  // The leaf of 2x2 pixels at (8, 2) holds the slab's top row and the gap
  // row. On its left side (x = 8) the lattice points (8, 3) and (8, 4) are
  // both 0-points: (8, 3) on the slab's boundary, (8, 4) because the stem
  // pixel (7, 4) touches that corner from outside. The segment between them
  // has background on both sides, so they belong to different pieces of the
  // boundary; read as one run, the leaf's surface reached (8, 4) and joined
  // the slab to the blob at a vertex.
  EXPECT_FALSE(Manifold(SlabStemAndBlob(true), Square(8, 2, 2), 0, 5));
  // Without the stem the leaf is a plain crossing of the slab's boundary.
  EXPECT_TRUE(Manifold(SlabStemAndBlob(false), Square(8, 2, 2), 0, 5));
}

TEST(SingleManifoldCondition, ThreeDimensionalSeparatePiecesTouchingAnEdgeCountSeparately)
{
  // A slab of label 1 (j <= 2, all i, k) and one voxel of label 1 at
  // (7, 4, 1), which touches the leaf (8..9, 2..3, 2..3) only at its corner
  // lattice point (8, 4, 2), diagonally from outside. Along the leaf edge
  // x = 8, z = 2 (parallel to y) the points (8, 3, 2) (on the slab's
  // boundary) and (8, 4, 2) are both 0-points, but the four voxels around the
  // segment between them are background: two pieces of boundary.
  auto slab = [](int, int j, int) { return j <= 2 ? 1 : 0; };
  const LabelImage corner =
    Volume(12, [&](int i, int j, int k) { return i == 7 && j == 4 && k == 1 ? 1 : slab(i, j, k); });
  EXPECT_FALSE(Manifold(corner, Cube(8, 2, 2, 2), 0, 1));
  EXPECT_TRUE(Manifold(Volume(12, slab), Cube(8, 2, 2, 2), 0, 1));
}

// ---- the interface cut off by a third label --------------------------------------

TEST(SingleManifoldCondition, TwoDimensionalInterfacePieceCutOffByAThirdLabelFails)
{
  // Label 1 in two parts, left (x <= 2, y >= 3) and right (x >= 4, y >= 3),
  // kept apart by background below and label 2 above pixel (3, 3). The leaf
  // of 2x2 pixels at (2, 2) holds one pixel of the left part, (2, 3); the
  // right part touches its right side along the pixel edge between (3, 3)
  // and (4, 3). So the interface between 0 and 1 in the closed leaf is two
  // pieces; its sides pass the run tests (the 0-points on the right side are
  // joined through label 2's boundary), and a patch through the corner (4, 4)
  // would join the two parts of label 1.
  const LabelImage cut = Picture({
    "1112111.",
    "1112111.",
    "1112111.",
    "1112111.",
    "111.111.",
    "........",
    "........",
    "........",
  });
  EXPECT_FALSE(Manifold(cut, Square(2, 2, 2), 0, 1));
  // With label 1 instead of 2 above (3, 3), the two parts are one and the
  // interface in the leaf runs on from (3, 4) to (4, 4) along the top side
  // and down the right side: one piece.
  const LabelImage joined = Picture({
    "1111111.",
    "1111111.",
    "1111111.",
    "1111111.",
    "111.111.",
    "........",
    "........",
    "........",
  });
  EXPECT_TRUE(Manifold(joined, Square(2, 2, 2), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalInterfacePieceCutOffByAThirdLabelFails)
{
  // The leaf (4..7)^3 is cut by the plane k >= 6 (label 1 above). Outside its
  // face x = 8, voxel (8, 4, 4) is label 1 and the voxel above it, (8, 4, 5),
  // label 2: the face between leaf voxel (7, 4, 4) (label 0) and (8, 4, 4) is
  // a second piece of the 0|1 interface, separated from the plane by the 0|2
  // face above it. Every edge and face passes (the 0-points down the leaf
  // edge x = 8, y = 4 are joined through label 2's boundary), so only the
  // interface check can see that the leaf holds two pieces.
  auto plane = [](int, int, int k) { return k >= 6 ? 1 : 0; };
  auto withVoxelAbove = [&](std::int32_t above) {
    return Volume(12, [&, above](int i, int j, int k) {
      if (i == 8 && j == 4 && k == 4)
        return 1;
      if (i == 8 && j == 4 && k == 5)
        return above;
      return plane(i, j, k);
    });
  };
  EXPECT_FALSE(Manifold(withVoxelAbove(2), Cube(4, 4, 4, 4), 0, 1));
  // With label 1 above it, the extra face joins the plane along its top edge.
  EXPECT_TRUE(Manifold(withVoxelAbove(1), Cube(4, 4, 4, 4), 0, 1));
}

// ---- inside the leaf: one path (2D), one disk (3D) ---------------------------------

TEST(SingleManifoldCondition, TwoDimensionalPathPlusLoopFails)
{
  // A straight interface (label 1 in rows 5 and up) through the leaf of 8x8
  // pixels at (2, 2), and a background pixel (5, 7) enclosed in label 1
  // inside the leaf, away from its sides: the interface is a path and a
  // closed loop, not one simple path.
  const LabelImage image = Picture({
    "111111111111",
    "111111111111",
    "111111111111",
    "111111111111",
    "11111.111111",
    "111111111111",
    "111111111111",
    "............",
    "............",
    "............",
    "............",
    "............",
  });
  EXPECT_FALSE(Manifold(image, Square(2, 2, 8), 0, 1));
  LabelImage filled = image;
  filled(5, 7, 0) = 1;
  EXPECT_TRUE(Manifold(filled, Square(2, 2, 8), 0, 1));
}

TEST(SingleManifoldCondition, ZeroCornerOfAThirdLabelsBoundaryFails)
{
  // Random box image 2288 (24^2, h = 2), pixels x 8..15, y 4..11: two blocks
  // of label 4 two pixels apart, separated by label 1 and background. The
  // leaves (10..11, 6..7) and (10..11, 8..9) hold labels 1 and 4, and share
  // the corner (11.5, 7.5), a 0-point of the 1|0 boundary that no 4 touches.
  // Their polygons ran through it, so the cells of 4 of both leaves met there
  // and joined the two blocks into one component.
  const LabelImage image = Picture({
    "11444444",
    "11444444",
    "11444444",
    "1111....",
    "1111....",
    "44444444",
    "44444444",
    "44444444",
  });
  EXPECT_FALSE(Manifold(image, Square(2, 2, 2), 1, 4));
  EXPECT_FALSE(Manifold(image, Square(2, 4, 2), 1, 4));
  // Without the background the corner is inside label 1, and the lower leaf
  // is a plain crossing.
  LabelImage filled = image;
  for (int j = 3; j <= 4; ++j)
    for (int i = 4; i < 8; ++i)
      filled(i, j, 0) = 1;
  EXPECT_TRUE(Manifold(filled, Square(2, 2, 2), 1, 4));
}

// A 2D leaf whose only interface is a closed loop around an island inside it
// (no boundary on its sides): the sides are all of one label, the loop is
// connected and both labels are 4-connected without a checkerboard, yet the
// interface is a loop, not the one simple path the header promises. Found by
// this test and fixed (a label must reach the leaf's rim). The 3D analogue is
// ThreeDimensionalIslandInsideTheLeafFails. The mesher was not affected: such
// a leaf has an empty cone patch, which SatisfiesFidelity rejects (asserted too).
TEST(SingleManifoldCondition, TwoDimensionalIslandInsideTheLeafFails)
{
  const LabelImage image = Picture({
    "........",
    "........",
    "........",
    "....1...",
    "...11...",
    "........",
    "........",
    "........",
  });
  EXPECT_FALSE(SatisfiesFidelity(image, Square(2, 2, 4), 0, 1, 100.0, 100.0));
  EXPECT_FALSE(Manifold(image, Square(2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalIslandInsideTheLeafFails)
{
  // One voxel of label 1 in the middle of the leaf (2..5)^3: every face is of
  // label 0 and the interface is the voxel's closed surface, a sphere (Euler
  // characteristic 2), not a disk.
  const LabelImage island = Volume(8, [](int i, int j, int k) { return i == 3 && j == 4 && k == 3 ? 1 : 0; });
  EXPECT_FALSE(Manifold(island, Cube(2, 2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalPlanePlusSeparateIslandFails)
{
  // The leaf (2..9)^3 cut by the plane k >= 5, with one background voxel
  // just above the plane, (5, 5, 5): a plane with a dent, still one disk. Two
  // layers higher, (5, 5, 7), the background voxel is enclosed in label 1
  // (and off the leaf's faces), and its closed surface is a second piece of
  // the interface.
  const LabelImage dent = PlaneWithOneVoxel(12, 5, 5, 5, 5, 0);
  EXPECT_TRUE(Manifold(dent, Cube(2, 2, 2, 8), 0, 1));
  const LabelImage bubble = PlaneWithOneVoxel(12, 5, 5, 5, 7, 0);
  EXPECT_FALSE(Manifold(bubble, Cube(2, 2, 2, 8), 0, 1));
}

// ---- checkerboards and pinched vertices ---------------------------------------------

TEST(SingleManifoldCondition, TwoDimensionalCheckerboardFails)
{
  // Label 1 in two opposite quadrants of the leaf (2..5)^2 (exactly one of
  // x >= 4, y >= 4): every side is crossed once, and the interface in the
  // closed leaf is connected, but four interface edges meet at the leaf's
  // centre, where the pixels form a 2x2 checkerboard: a cross, not a simple
  // path (in 2D the pinched vertex is this checkerboard).
  const LabelImage image = Picture({
    "....1111",
    "....1111",
    "....1111",
    "....1111",
    "1111....",
    "1111....",
    "1111....",
    "1111....",
  });
  EXPECT_FALSE(Manifold(image, Square(2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalPinchedEdgesInsideTheLeafFail)
{
  // Leaf (4..11)^3 (leaf-local coordinates below), label 1 below the plane
  // k = 3 (a slab). Two voxels of the slab's top layer are carved out,
  // (3..4, 5, 2), with (3..4, 6, 2) next to them, so that the carving opens
  // upwards; on top of the carved pair sits a bar of label 1, (3..4, 5, 3).
  // The bar touches the slab only along edges (e.g. the one between its voxel
  // (3, 5, 3) and the slab's (3, 4, 2)): around those edges the four voxels
  // alternate 1, 0, 1, 0, four interface faces meet, and the interface is not
  // a 2-manifold, although it is connected and no face of the leaf sees it.
  auto local = [](std::function<std::int32_t(int, int, int)> f) {
    return Volume(16, [f](int i, int j, int k) { return f(i - 4, j - 4, k - 4); });
  };
  auto barOnSlab = [](bool carved) {
    return [carved](int i, int j, int k) -> std::int32_t {
      const bool column = i >= 3 && i <= 4;
      if (column && j == 5 && k == 3)
        return 1; // the bar
      if (column && (j == 6 || (carved && j == 5)) && k == 2)
        return 0; // the carving
      return k < 3 ? 1 : 0;
    };
  };
  EXPECT_FALSE(Manifold(local(barOnSlab(true)), Cube(4, 4, 4, 8), 0, 1));
  // Not carved under the bar, the bar stands on the slab face to face: a bump
  // beside a dent, one disk.
  EXPECT_TRUE(Manifold(local(barOnSlab(false)), Cube(4, 4, 4, 8), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalPinchedVertexFails)
{
  // Label 1 in two opposite octants of the leaf (2..5)^3, i, j, k all < 4 or
  // all >= 4: the two blocks touch at the single point (4, 4, 4), around which
  // label 1 is not face-connected; the interface is two disks pinched there.
  const LabelImage image =
    Volume(8, [](int i, int j, int k) { return (i < 4 && j < 4 && k < 4) || (i >= 4 && j >= 4 && k >= 4) ? 1 : 0; });
  EXPECT_FALSE(Manifold(image, Cube(2, 2, 2, 4), 0, 1));
}

TEST(SingleManifoldCondition, ThreeDimensionalStaircaseDiskPasses)
{
  // Label 1 above the staircase 4 k >= i + j + 8 (leaf-local coordinates of
  // the leaf (2..9)^3 of a 12^3 image): heights 2..6, rising in steps along
  // both axes, which never form a checkerboard. A bent sheet, connected and
  // manifold: one disk, crossing only the four side faces.
  const LabelImage image =
    Volume(12, [](int i, int j, int k) { return 4 * (k - 2) >= (i - 2) + (j - 2) + 8 ? 1 : 0; });
  EXPECT_TRUE(Manifold(image, Cube(2, 2, 2, 8), 0, 1));
  // The steeper staircase 2 k >= i + j reaches the bottom face at its corner
  // voxel (2, 2, 2) alone: the bottom face's corners are label 0 and 0-corner,
  // so it counts as not crossed, yet boundary points lie inside it (around
  // that voxel): rejected.
  const LabelImage steep = Volume(12, [](int i, int j, int k) { return 2 * (k - 2) >= (i - 2) + (j - 2) ? 1 : 0; });
  EXPECT_FALSE(Manifold(steep, Cube(2, 2, 2, 8), 0, 1));
}

// ---- the image border ------------------------------------------------------------------

TEST(SingleManifoldCondition, OutsideTheImageIsBackground)
{
  // A 4x4 image, all of it one leaf, label 1 in rows 2..3: outside the image
  // is label 0, so label 1 meets the outside along the whole top side of the
  // leaf (and the upper halves of its left and right sides): rejected. The
  // same rows in a larger image, where label 1 goes on beyond the leaf, are a
  // plain crossing.
  EXPECT_FALSE(Manifold(Picture({ "1111", "1111", "....", "...." }), Square(0, 0, 4), 0, 1));
  EXPECT_TRUE(Manifold(Picture({
                         "11111111",
                         "11111111",
                         "11111111",
                         "11111111",
                         "11111111",
                         "11111111",
                         "........",
                         "........",
                       }),
    Square(0, 0, 4), 0, 1));
  // Two foreground labels in a leaf on the border: every side is boundary
  // end to end (1 or 2 inside, 0 outside).
  EXPECT_FALSE(Manifold(Picture({ "2222", "2222", "1111", "1111" }), Square(0, 0, 4), 1, 2));
  // 3D: label 1 in the octant i, j, k >= 2 of an 8^3 image, leaf (0..3)^3 at
  // the image's corner: the interface is the octant's corner, three squares
  // meeting at (2, 2, 2), one disk. The leaf's three low faces lie on the
  // image border, next to outside voxels of label 0 like the leaf's own
  // voxels there, so they carry no boundary, and the leaf passes. Extruded
  // through the whole image along z (i, j >= 2 only), label 1 meets the
  // outside across the leaf's bottom face: boundary inside a face whose
  // corners are not of both labels, rejected.
  const LabelImage octant = Volume(8, [](int i, int j, int k) { return i >= 2 && j >= 2 && k >= 2 ? 1 : 0; });
  EXPECT_TRUE(Manifold(octant, Cube(0, 0, 0, 4), 0, 1));
  const LabelImage column = Volume(8, [](int i, int j, int) { return i >= 2 && j >= 2 ? 1 : 0; });
  EXPECT_FALSE(Manifold(column, Cube(0, 0, 0, 4), 0, 1));
}

// ---- the two random seeds that once failed -------------------------------------------

/// The image of a regression seed, with its checksum checked against the one
/// TestMesherProperties pins (so that a change of the generator cannot
/// quietly make these tests about another image).
LabelImage RegressionImage(std::uint64_t seed, std::uint64_t checksum)
{
  const testing::RandomLabelImage random = testing::GenerateRandomLabelImageWithDescription(seed, 2);
  EXPECT_EQ(testing::LabelImageChecksum(random.Image), checksum) << "seed " << seed << " names another image now";
  return random.Image;
}

TEST(SingleManifoldCondition, Seed21401LeafWithTwoPiecesOnItsSideFails)
{
  // 2D seed 21401 (16 x 19 pixels, labels 0 and 245 at this leaf; its bounds
  // are h(I,M) = 2, h(M,I) = 3). Of all the leaves the octree judges, the fix
  // of commit 72ff921 (0-points on a side count as one run only where the
  // boundary joins them) changes the verdict of exactly one: the 2x2 leaf at
  // (8, 2), over the top row of a slab of 245 (rows 0..2) and the empty row 3;
  // pixel (7, 4), the stem of the blob above, touches its corner (8, 4) from
  // outside, and the points (8, 3) and (8, 4) of its left side are 0-points of
  // two different pieces of boundary. Found by judging every leaf of the
  // image's octree with and without the fix (a scratch copy of the condition).
  // It passes fidelity at the seed's bounds, so the condition is what rejects
  // it; without the stem pixel it passes the condition too. (Today the
  // neighbour rule splits this leaf anyway, its left side having a 0-corner
  // and finer leaves beside it, so the seed's whole-mesher test no longer
  // depends on this verdict; this test does.)
  const LabelImage image = RegressionImage(21401, 0x3c660a8530f68c41ull);
  const LeafBox leaf = Square(8, 2, 2);
  ASSERT_EQ(image.At(7, 4, 0), 245);
  EXPECT_TRUE(SatisfiesFidelity(image, leaf, 0, 245, 2.0, 3.0));
  EXPECT_FALSE(Manifold(image, leaf, 0, 245));
  LabelImage withoutStem = image;
  withoutStem(7, 4, 0) = 0;
  EXPECT_TRUE(Manifold(withoutStem, leaf, 0, 245));
}

TEST(SingleManifoldCondition, Seed30826LeavesWithAnInterfacePieceCutOffFail)
{
  // 2D seed 30826 (49 x 51 pixels, bounds h(I,M) = h(M,I) = 3). The fix of
  // commit 2b5f327 (the interface in the closed leaf must be one piece)
  // changes the verdict of four leaves of its octree; accepting the two
  // 2x2 leaves below (with the fix disabled for them alone, everything else
  // as now) is what joins two parts of label 255 at the lattice point
  // (28, 12) (mesh: 2 components of 255, image: 3); accepting either alone,
  // or their 4x4 parents, does not. Around there, column 27 separates the
  // left part of 255 (pixel (26, 11) and up) from the right part ((28, 11)
  // and up): background at (27, 11) and below, label 3 at (27, 12) and above.
  //  - leaf (26, 10), labels 0 | 255: its 0|255 interface is the edges of
  //    pixel (26, 11) and, separately, the edge between (27, 11) and the
  //    right part's (28, 11) on its right side;
  //  - leaf (26, 12), labels 3 | 255: its 3|255 interface is the edge
  //    between (26, 12..13) and (27, 12..13) and, separately, the edge
  //    between (27, 12) and (28, 12) on its right side.
  // Both pass fidelity at the seed's bounds.
  const LabelImage image = RegressionImage(30826, 0x2fbc168d1b3cd90cull);
  ASSERT_EQ(image.At(26, 11, 0), 255);
  ASSERT_EQ(image.At(27, 11, 0), 0);
  ASSERT_EQ(image.At(27, 12, 0), 3);
  ASSERT_EQ(image.At(28, 11, 0), 255);
  ASSERT_EQ(image.At(28, 12, 0), 255);
  const LeafBox low = Square(26, 10, 2), high = Square(26, 12, 2);
  EXPECT_TRUE(SatisfiesFidelity(image, low, 0, 255, 3.0, 3.0));
  EXPECT_TRUE(SatisfiesFidelity(image, high, 3, 255, 3.0, 3.0));
  EXPECT_FALSE(Manifold(image, low, 0, 255));
  EXPECT_FALSE(Manifold(image, high, 3, 255));
}

} // namespace
} // namespace labelmesher
