// SPDX-License-Identifier: GPL-2.0-or-later
// EdgeCollapse (one merge of section 3.1.3, Figure 15) planned and applied on a square fan of two
// materials: the cells that vanish, move and stay; the interface faces before and after (the
// box's sides count as faces against its outside); the mesh after Apply; and the merges the plan
// must refuse (not neighbours).
#include "Decimation/EdgeCollapse.h"
#include "Decimation/EditableMesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace
{
using labelmesher::CellId;
using labelmesher::EdgeCollapse;
using labelmesher::EditableMesh;
using labelmesher::InterfaceFace;
using labelmesher::SimplexMesh;
using labelmesher::VertexId;

/// The square [0, 2]^2 split into four triangles around its centre (vertex 4): the lower two
/// (cells 0 and 3, at the left and bottom) of label 1, the others of label 2.
///   3 ------ 2
///   | \ 2  / |
///   | 3  4 1 |
///   | / 0  \ |
///   0 ------ 1
SimplexMesh Fan()
{
  SimplexMesh mesh;
  mesh.Dimension = 2;
  mesh.Points = { { 0, 0, 0 }, { 2, 0, 0 }, { 2, 2, 0 }, { 0, 2, 0 }, { 1, 1, 0 } };
  mesh.Connectivity = { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4 };
  mesh.Materials = { 1, 2, 2, 1 };
  return mesh;
}

std::vector<CellId> Sorted(std::vector<CellId> cells)
{
  std::sort(cells.begin(), cells.end());
  return cells;
}

/// The interior interface faces (both sides real materials) of a list.
std::vector<std::array<VertexId, 3>> Interior(const std::vector<InterfaceFace>& faces)
{
  std::vector<std::array<VertexId, 3>> inside;
  for (const InterfaceFace& f : faces)
    if (!EditableMesh::IsOutside(f.Low))
      inside.push_back(f.Vertices);
  return inside;
}

TEST(EdgeCollapse, PlansWhichCellsVanishMoveAndStay)
{
  const EditableMesh mesh(Fan());
  EdgeCollapse merge;
  ASSERT_TRUE(merge.Plan(mesh, 4, 0));
  EXPECT_EQ(merge.From, 4);
  EXPECT_EQ(merge.To, 0);
  EXPECT_EQ(Sorted(merge.Removed), (std::vector<CellId>{ 0, 3 }));
  EXPECT_EQ(Sorted(merge.Moved), (std::vector<CellId>{ 1, 2 }));
  EXPECT_TRUE(merge.Kept.empty());
  ASSERT_EQ(merge.MovedCells.size(), 2u);
  for (const auto& cell : merge.MovedCells)
  {
    EXPECT_EQ(std::count(cell.begin(), cell.begin() + 3, 4), 0) << "From is replaced";
    EXPECT_EQ(std::count(cell.begin(), cell.begin() + 3, 0), 1) << "by To";
  }
  EdgeCollapse notNeighbours;
  EXPECT_FALSE(notNeighbours.Plan(mesh, 0, 2)) << "0 and 2 share no edge";
}

TEST(EdgeCollapse, InterfacesBeforeAndAfter)
{
  const EditableMesh mesh(Fan());
  EdgeCollapse merge;
  ASSERT_TRUE(merge.Plan(mesh, 4, 0));
  ASSERT_TRUE(merge.PlanInterfaces(mesh));
  // Before: the two interior edges 1-4 and 3-4 separate labels 1 and 2 (each once, sorted).
  EXPECT_EQ(Interior(merge.Before), (std::vector<std::array<VertexId, 3>>{ { 1, 4, -1 }, { 3, 4, -1 } }));
  // After: label 1 is gone, so no interior interface touches 0; the box's sides touching 0 now
  // border label 2.
  EXPECT_TRUE(Interior(merge.After).empty());
  for (const InterfaceFace& f : merge.After)
  {
    EXPECT_TRUE(f.Contains(0));
    EXPECT_TRUE(f.Separates(2));
  }
  EXPECT_TRUE(std::is_sorted(merge.Before.begin(), merge.Before.end()));
  EXPECT_TRUE(std::is_sorted(merge.After.begin(), merge.After.end()));
}

TEST(EdgeCollapse, ApplyEditsTheMesh)
{
  EditableMesh mesh(Fan());
  EdgeCollapse merge;
  ASSERT_TRUE(merge.Plan(mesh, 4, 0));
  merge.Apply(mesh);
  EXPECT_EQ(mesh.AliveCells(), 2u);
  EXPECT_EQ(mesh.AliveVertices(), 4u);
  EXPECT_TRUE(mesh.CellsOf[4].empty());
  EXPECT_EQ(mesh.CellsOf[0].size(), 2u);
  const SimplexMesh after = mesh.ToSimplexMesh();
  ASSERT_EQ(after.NumberOfCells(), 2u);
  for (std::size_t c = 0; c < 2; ++c)
  {
    const std::int64_t* v = after.Cell(c);
    const auto& a = after.Points[v[0]];
    const auto& b = after.Points[v[1]];
    const auto& d = after.Points[v[2]];
    EXPECT_GT((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]), 0.0) << "counter-clockwise";
    EXPECT_EQ(after.Materials[c], 2);
  }
}

} // namespace
