// SPDX-License-Identifier: GPL-2.0-or-later
// TopologyCheck (requirement 3 of section 3.1.3) on hand-made meshes where the answer is known:
// the link condition accepts removing a vertex of degree three and refuses the merge across a
// pinch (a vertex adjacent to both ends of the edge without a triangle with them); the strata
// rule lets an interface vertex slide along its interface, and refuses a merge that would take a
// material away from an edge, move a vertex where the interface meets the box, or make a
// material vanish.
#include "Decimation/EdgeCollapse.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/TopologyCheck.h"
#include "HandMadeMeshes.h"

#include <gtest/gtest.h>

namespace
{
using labelmesher::EdgeCollapse;
using labelmesher::EditableMesh;
using labelmesher::TopologyCheck;
using labelmesher::testing::Triangles2D;

/// The square [0, 4]^2 of one label, with the triangle a b c split at e inside it:
///   a = 4 (1, 2), b = 5 (3, 2), c = 6 (2, 3.5), d = 7 (2, 1), e = 8 (2, 2.5).
/// c is a neighbour of a and of b, but (a, b, c) is no triangle: e lies between.
EditableMesh Pinch()
{
  return EditableMesh(Triangles2D({ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 0, 4 }, { 1, 2 }, { 3, 2 }, { 2, 3.5 }, { 2, 1 }, { 2, 2.5 } },
    { { 4, 5, 8 }, { 4, 8, 6 }, { 8, 5, 6 }, { 4, 7, 5 }, { 0, 1, 7 }, { 0, 7, 4 }, { 1, 5, 7 }, { 1, 2, 5 },
      { 2, 6, 5 }, { 2, 3, 6 }, { 3, 4, 6 }, { 0, 4, 3 } },
    std::vector<std::int32_t>(12, 1)));
}

/// [0, 4] x [0, 2], label 1 below y = 1 and label 2 above; the interface runs through
/// 3 (0, 1), 4 (1, 1), 5 (2, 1) and 6 (4, 1).
///   7 ----- 8 ------------- 9
///   | 2  /  |   2      /    |
///   3 - 4 - 5 ------------- 6
///   | 1  \  |   1      \    |
///   0 ----- 1 ------------- 2
EditableMesh TwoStrips()
{
  return EditableMesh(Triangles2D({ { 0, 0 }, { 2, 0 }, { 4, 0 }, { 0, 1 }, { 1, 1 }, { 2, 1 }, { 4, 1 }, { 0, 2 }, { 2, 2 }, { 4, 2 } },
    { { 0, 1, 4 }, { 0, 4, 3 }, { 1, 5, 4 }, { 1, 2, 6 }, { 1, 6, 5 }, { 3, 4, 7 }, { 4, 8, 7 }, { 4, 5, 8 },
      { 5, 6, 9 }, { 5, 9, 8 } },
    { 1, 1, 1, 1, 1, 2, 2, 2, 2, 2 }));
}

/// What the decimator concludes of a merge before the fidelity check: the plan makes a
/// non-conforming mesh (EdgeCollapse::PlanInterfaces, the first line of defence), the topology
/// check refuses it, or accepts it.
enum class Verdict
{
  NotConforming,
  Refused,
  Accepted
};

Verdict Judge(const EditableMesh& mesh, int from, int to)
{
  EdgeCollapse merge;
  EXPECT_TRUE(merge.Plan(mesh, from, to)) << from << " and " << to << " are not neighbours";
  if (!merge.PlanInterfaces(mesh))
    return Verdict::NotConforming;
  TopologyCheck check;
  return check.Accepts(mesh, merge) ? Verdict::Accepted : Verdict::Refused;
}

TEST(TopologyCheck, LinkConditionInsideOneMaterial)
{
  const EditableMesh mesh = Pinch();
  ASSERT_TRUE(TopologyCheck::IsInterior(mesh, 8));
  ASSERT_TRUE(TopologyCheck::IsInterior(mesh, 4));
  EXPECT_FALSE(TopologyCheck::IsInterior(mesh, 0)) << "a box corner";
  TopologyCheck check;
  EdgeCollapse merge;
  // e has degree three: merging it into c removes it, the disc stays a disc.
  ASSERT_TRUE(merge.Plan(mesh, 8, 6));
  EXPECT_TRUE(check.AcceptsInteriorMove(mesh, merge));
  // a into b: c is in Lk(a) and Lk(b) but not in Lk(ab) = {d, e}; the merge would glue two
  // triangles onto each other.
  ASSERT_TRUE(merge.Plan(mesh, 4, 5));
  EXPECT_FALSE(check.AcceptsInteriorMove(mesh, merge));
  // The full check accepts the first; the second never reaches it: gluing two triangles puts
  // three cells on one edge, which the plan refuses first.
  EXPECT_EQ(Judge(mesh, 8, 6), Verdict::Accepted);
  EXPECT_EQ(Judge(mesh, 4, 5), Verdict::NotConforming);
}

TEST(TopologyCheck, StrataAcrossAnInterface)
{
  const EditableMesh mesh = TwoStrips();
  // 4 slides along the interface onto 5: both labels stay around the edge, the interface stays one line.
  EXPECT_EQ(Judge(mesh, 4, 5), Verdict::Accepted);
  // 4 into 0 (a corner of label 1): label 2 is not around the edge 4-0.
  EXPECT_EQ(Judge(mesh, 4, 0), Verdict::Refused);
  // 3, where the interface meets the box, is a corner of the strata in 2D: it may not slide
  // down the box's side onto 0, though the result conforms.
  EXPECT_EQ(Judge(mesh, 3, 0), Verdict::Refused);
}

TEST(TopologyCheck, AMaterialMayNotVanish)
{
  // A square fan around its centre 4: label 1 only in the two cells at corner 0. Merging 4 into 0
  // removes both, and with them label 1.
  const EditableMesh fan(Triangles2D({ { 0, 0 }, { 2, 0 }, { 2, 2 }, { 0, 2 }, { 1, 1 } },
    { { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } }, { 1, 2, 2, 1 }));
  EXPECT_EQ(Judge(fan, 4, 0), Verdict::Refused);
}

} // namespace
