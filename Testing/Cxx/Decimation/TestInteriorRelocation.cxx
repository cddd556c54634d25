// SPDX-License-Identifier: GPL-2.0-or-later
// Tests of Decimation/InteriorRelocation: which vertices move, where, and that
// its quality test is what keeps the cells valid; and its effect on the decimator.
#include "DecimatorGuarantees.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/InteriorRelocation.h"
#include "Decimation/MeshDecimator.h"
#include "Decimation/QualityCheck.h"
#include "SyntheticShapes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace labelmesher
{
namespace
{

/// A 2D mesh of the given points (index space) and triangles, every cell of label 1.
SimplexMesh Triangles(const std::vector<Point3>& points, const std::vector<std::int64_t>& cells)
{
  SimplexMesh mesh;
  mesh.Dimension = 2;
  mesh.Points = points;
  mesh.Connectivity = cells;
  mesh.Materials.assign(cells.size() / 3, 1);
  return mesh;
}

double SmallestAngleAround(const EditableMesh& mesh, VertexId v)
{
  double smallest = 180.0;
  for (CellId c : mesh.CellsOf[v])
  {
    Lattice p[4];
    for (int i = 0; i < 3; ++i)
      p[i] = mesh.Position[mesh.Cells[c][i]];
    smallest = std::min(smallest, QualityCheck::SmallestAngle(2, p));
  }
  return smallest;
}

bool AllPositive(const EditableMesh& mesh)
{
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
  {
    Lattice p[4];
    for (int i = 0; i < 3; ++i)
      p[i] = mesh.Position[mesh.Cells[c][i]];
    if (EditableMesh::Orientation(2, p) <= 0)
      return false;
  }
  return true;
}

// The square [0, 4]^2 as a fan around vertex 4 at (1, 1).
const std::vector<Point3> kSquare = { { 0, 0, 0 }, { 4, 0, 0 }, { 4, 4, 0 }, { 0, 4, 0 }, { 1, 1, 0 } };
const std::vector<std::int64_t> kFan = { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4 };

TEST(InteriorRelocation, AnInteriorVertexMovesToWhereItsSmallestAngleIsLarger)
{
  EditableMesh mesh(Triangles(kSquare, kFan));
  const double before = SmallestAngleAround(mesh, 4);
  InteriorRelocation relocation;
  ASSERT_TRUE(relocation.TryMove(mesh, 4));
  EXPECT_GT(SmallestAngleAround(mesh, 4), before + 10.0);
  EXPECT_TRUE(AllPositive(mesh));
  // At the centre (2, 2), doubled (4, 4), all four angles at the corners are 45 degrees: nothing is better.
  EXPECT_EQ(mesh.Position[4], (Lattice{ 4, 4, 0 }));
  EXPECT_NEAR(SmallestAngleAround(mesh, 4), 45.0, 1e-9);
  EXPECT_FALSE(relocation.TryMove(mesh, 4)) << "no candidate is better than the best place";
}

TEST(InteriorRelocation, VerticesOnAnInterfaceOrOnTheBoxNeverMove)
{
  SimplexMesh twoLabels = Triangles(kSquare, kFan);
  twoLabels.Materials[0] = 2; // vertex 4 now lies on the interface between 1 and 2
  EditableMesh mesh(twoLabels);
  InteriorRelocation relocation;
  EXPECT_FALSE(relocation.TryMove(mesh, 4));
  EXPECT_FALSE(relocation.TryMove(mesh, 4, false)) << "not even with the quality test off";
  EditableMesh one(Triangles(kSquare, kFan));
  for (VertexId corner = 0; corner < 4; ++corner)
    EXPECT_FALSE(relocation.TryMove(one, corner, false));
}

TEST(InteriorRelocation, ItsQualityTestKeepsEveryCellPositiveWhereTheCentroidIsOutsideTheKernel)
{
  // Box [0, 8] x [0, 4]. Vertex 7 at (4, 3.5) has the link A w B C F D, with
  // w = (4, 3) poking up into it: the centroid of the neighbours, (4, 2.5),
  // lies below w, outside the polygon's kernel.
  const std::vector<Point3> points = { { 0, 0, 0 }, { 4, 0, 0 }, { 8, 0, 0 }, { 8, 4, 0 }, { 4, 4, 0 }, { 0, 4, 0 },
    { 4, 3, 0 }, { 4, 3.5, 0 } };
  enum { A, E, B, C, F, D, W, V };
  const std::vector<std::int64_t> cells = { A, E, W, E, B, W, A, W, V, W, B, V, B, C, V, C, F, V, F, D, V, D, A, V };
  InteriorRelocation relocation;
  EditableMesh checked(Triangles(points, cells));
  ASSERT_TRUE(AllPositive(checked));
  relocation.TryMove(checked, V);
  EXPECT_TRUE(AllPositive(checked)) << "the test refuses every candidate that inverts a cell";
  EditableMesh unchecked(Triangles(points, cells));
  ASSERT_TRUE(relocation.TryMove(unchecked, V, false));
  EXPECT_FALSE(AllPositive(unchecked)) << "without the test the centroid inverts a cell: the test is what prevents it";
}

TEST(InteriorRelocation, TheDecimatorLeavesFewerCellsWithItAndKeepsEveryGuarantee)
{
  for (const int dimension : { 2, 3 })
  {
    const LabelImage image = dimension == 2 ? testing::MakeDisc(96, 33.7) : testing::MakeCassiniVolume(48);
    DecimationParameters p;
    DecimationCounts with, without;
    const auto problems = testing::ViolatedDecimatorGuarantees(image, {}, p, &with);
    EXPECT_TRUE(problems.empty()) << problems.front();
    p.RelocateInteriorVertices = false;
    EXPECT_TRUE(testing::ViolatedDecimatorGuarantees(image, {}, p, &without).empty());
    EXPECT_EQ(without.Relocations, 0u);
    // In 2D the boundary holds most vertices: relocation gains little there
    // (the digimouse slice: 1,231 -> 1,209 triangles), and nothing on a disc.
    EXPECT_LE(with.CellsAfter, without.CellsAfter) << dimension << "D";
    if (dimension == 3)
    {
      EXPECT_GT(with.Relocations, 0u);
      EXPECT_LT(with.CellsAfter * 2, without.CellsAfter) << "Cassini 48 loses more than half its cells";
    }
    std::printf("%dD: %zu cells, %zu after merges only, %zu with relocation (%zu moves)\n", dimension,
      with.CellsBefore, without.CellsAfter, with.CellsAfter, with.Relocations);
  }
}

} // namespace
} // namespace labelmesher
