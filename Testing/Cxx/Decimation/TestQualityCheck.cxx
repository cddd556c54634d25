// SPDX-License-Identifier: GPL-2.0-or-later
// QualityCheck (requirement 1 of section 3.1.3) on hand-made stars where the answer is known:
// the angles of known cells; a merge onto a corner of a square fan (45 degree cells: accepted at
// a 40 degree bound, refused at 50); a merge that would fold a cell of a dented star (refused by
// the exact orientation test) and one that would flatten a cell (refused too: a flat cell counts
// as inverted, no tolerance lets it through).
#include "Decimation/EdgeCollapse.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/QualityCheck.h"
#include "HandMadeMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using labelmesher::EdgeCollapse;
using labelmesher::EditableMesh;
using labelmesher::Lattice;
using labelmesher::QualityCheck;
using labelmesher::SimplexMesh;

constexpr double kDegrees = 180.0 / 3.14159265358979323846;

/// Triangles of label 1 (HandMadeMeshes.h).
SimplexMesh Triangles(const std::vector<std::array<double, 2>>& points, const std::vector<std::array<std::int64_t, 3>>& cells)
{
  return labelmesher::testing::Triangles2D(points, cells, std::vector<std::int32_t>(cells.size(), 1));
}

/// Prepare, OrientationsHold, then (when the orientations hold) Plan and AnglesHold.
bool MergeAllowed(const EditableMesh& mesh, double bound, int from, int to)
{
  QualityCheck check(mesh.Dimension, bound);
  check.Prepare(mesh, from);
  if (!check.OrientationsHold(mesh, to))
    return false;
  EdgeCollapse merge;
  EXPECT_TRUE(merge.Plan(mesh, from, to));
  return check.AnglesHold(mesh, merge);
}

TEST(QualityCheck, AnglesOfKnownCells)
{
  // Doubled lattice. The regular tetrahedron: every dihedral angle is acos(1/3).
  const Lattice regular[4] = { { 0, 0, 0 }, { 2, 2, 0 }, { 2, 0, 2 }, { 0, 2, 2 } };
  EXPECT_NEAR(QualityCheck::LargestCosine(3, regular), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(QualityCheck::SmallestAngle(3, regular), std::acos(1.0 / 3.0) * kDegrees, 1e-9);
  // A Kuhn tetrahedron of a cube: dihedral angles 45, 60 and 90 degrees.
  const Lattice kuhn[4] = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 2, 0 }, { 2, 2, 2 } };
  EXPECT_NEAR(QualityCheck::SmallestAngle(3, kuhn), 45.0, 1e-9);
  // A right isosceles triangle, and one with a 1:2 leg ratio (smallest angle atan(1/2)).
  const Lattice right[3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 } };
  EXPECT_NEAR(QualityCheck::SmallestAngle(2, right), 45.0, 1e-9);
  const Lattice thin[3] = { { 0, 0, 0 }, { 4, 0, 0 }, { 0, 2, 0 } };
  EXPECT_NEAR(QualityCheck::SmallestAngle(2, thin), std::atan(0.5) * kDegrees, 1e-9);
  EXPECT_DOUBLE_EQ(QualityCheck::AngleOfCosine(1.5), 0.0);
  EXPECT_DOUBLE_EQ(QualityCheck::AngleOfCosine(-2.0), 180.0);
}

TEST(QualityCheck, TheBoundDecidesAMergeOfRightTriangles)
{
  // A square fan around its centre (4); merging the centre onto corner 0 leaves two right
  // isosceles triangles: smallest angle 45 degrees.
  const EditableMesh fan(Triangles({ { 0, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 }, { 1, 1 } },
    { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } }));
  EXPECT_TRUE(MergeAllowed(fan, 40.0, 4, 0));
  EXPECT_TRUE(MergeAllowed(fan, 45.0 - 1e-9, 4, 0));
  EXPECT_FALSE(MergeAllowed(fan, 45.0 + 1e-9, 4, 0));
  EXPECT_FALSE(MergeAllowed(fan, 50.0, 4, 0));
}

TEST(QualityCheck, AMergeThatFoldsACellIsRefusedExactly)
{
  // A star around P = 5 dented at D = 3: moving P onto C = 2 turns (D, E, P) into (D, E, C),
  // clockwise. Moving P onto A = 0 keeps every cell counter-clockwise. The dent makes the star's
  // rim leave the box: the mesh is a piece whose rim is its border.
  const std::vector<std::array<double, 2>> points = { { 0, 0 }, { 4, 0 }, { 4, 4 }, { 2, 3 }, { 0, 4 }, { 2, 2 } };
  const std::vector<std::array<std::int64_t, 3>> cells = { { 0, 1, 5 }, { 1, 2, 5 }, { 2, 3, 5 }, { 3, 4, 5 }, { 4, 0, 5 } };
  const EditableMesh star(Triangles(points, cells), Lattice{ 0, 0, 0 }, Lattice{ 8, 8, 0 });
  QualityCheck check(2, 1.0);
  check.Prepare(star, 5);
  EXPECT_FALSE(check.OrientationsHold(star, 2));
  EXPECT_TRUE(check.OrientationsHold(star, 0));
}

TEST(QualityCheck, AMergeThatFlattensACellIsRefused)
{
  // As above with D = (2, 4) on the top edge: moving P onto C makes (D, E, C) three points of one
  // line, area exactly 0.
  const EditableMesh star(Triangles({ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 2, 4 }, { 0, 4 }, { 2, 2 } },
    { { 0, 1, 5 }, { 1, 2, 5 }, { 2, 3, 5 }, { 3, 4, 5 }, { 4, 0, 5 } }));
  QualityCheck check(2, 1.0);
  check.Prepare(star, 5);
  EXPECT_FALSE(check.OrientationsHold(star, 2));
  EXPECT_TRUE(check.OrientationsHold(star, 0));
}

} // namespace
