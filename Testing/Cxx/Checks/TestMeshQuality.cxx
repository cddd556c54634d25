// SPDX-License-Identifier: GPL-2.0-or-later
// MeasureQuality: dihedral angles (3D), planar angles (2D) and inverted cells,
// checked against values computed analytically.
#include "Checks/MeshChecks.h"
#include "VoxelMeshes.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace labelmesher;
using labelmesher::testing::Det;
using labelmesher::testing::RandomImage;
using labelmesher::testing::VoxelMesh;

namespace
{
const double Pi = 3.14159265358979323846;
double Deg(double radians) { return radians * 180.0 / Pi; }

SimplexMesh Tets(const std::vector<Point3>& points, const std::vector<std::int64_t>& conn)
{
  SimplexMesh m;
  m.Dimension = 3;
  m.Points = points;
  m.Connectivity = conn;
  m.Materials.assign(conn.size() / 4, 1);
  return m;
}

SimplexMesh Triangles(const std::vector<Point3>& points, const std::vector<std::int64_t>& conn)
{
  SimplexMesh m;
  m.Dimension = 2;
  m.Points = points;
  m.Connectivity = conn;
  m.Materials.assign(conn.size() / 3, 1);
  return m;
}

/// The unit cube split into the 6 Kuhn tetrahedra around its (0,0,0)-(1,1,1) diagonal.
SimplexMesh KuhnCube()
{
  std::vector<Point3> pts;
  for (int c = 0; c < 8; ++c)
    pts.push_back({ double(c & 1), double((c >> 1) & 1), double((c >> 2) & 1) });
  std::vector<std::int64_t> conn;
  const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (const auto& p : perms)
  {
    std::int64_t v[4] = { 0, 1 << p[0], (1 << p[0]) | (1 << p[1]), 7 };
    if (Det(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]) < 0)
      std::swap(v[1], v[2]);
    conn.insert(conn.end(), v, v + 4);
  }
  return Tets(pts, conn);
}
} // namespace

TEST(MeshQuality, KuhnCubeHasDihedralAnglesFrom45To90)
{
  const QualityReport q = MeasureQuality(KuhnCube());
  EXPECT_NEAR(q.MinimumAngle, 45.0, 1e-9);
  EXPECT_NEAR(q.MaximumAngle, 90.0, 1e-9);
  EXPECT_EQ(q.InvertedCells, 0u);
}

TEST(MeshQuality, RegularTetrahedronHasArccosOneThird)
{
  // Alternate corners of a cube: a regular tetrahedron, positively oriented.
  const SimplexMesh m =
    Tets({ { 0, 0, 0 }, { 1, 1, 0 }, { 1, 0, 1 }, { 0, 1, 1 } }, { 0, 1, 3, 2 });
  ASSERT_GT(Det(m.Points[0], m.Points[1], m.Points[3], m.Points[2]), 0);
  const QualityReport q = MeasureQuality(m);
  const double expected = Deg(std::acos(1.0 / 3.0)); // 70.5288 degrees
  EXPECT_NEAR(q.MinimumAngle, expected, 1e-9);
  EXPECT_NEAR(q.MaximumAngle, expected, 1e-9);
  EXPECT_NEAR(expected, 70.5288, 1e-4);
  EXPECT_EQ(q.InvertedCells, 0u);
}

TEST(MeshQuality, CornerTetrahedron)
{
  // Three right dihedral angles at the axes, arccos(1/sqrt(3)) at the others.
  const QualityReport q =
    MeasureQuality(Tets({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }, { 0, 1, 2, 3 }));
  EXPECT_NEAR(q.MinimumAngle, Deg(std::acos(1.0 / std::sqrt(3.0))), 1e-9);
  EXPECT_NEAR(q.MaximumAngle, 90.0, 1e-9);
  EXPECT_EQ(q.InvertedCells, 0u);
}

TEST(MeshQuality, SliverHasAnglesNearZeroAnd180)
{
  const double eps = 1e-3;
  // Square (0,0,0),(1,0,0),(1,1,eps),(0,1,0) seen as a tetrahedron: nearly flat.
  SimplexMesh m = Tets({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, eps } }, { 0, 1, 2, 3 });
  if (Det(m.Points[0], m.Points[1], m.Points[2], m.Points[3]) < 0)
    std::swap(m.Connectivity[1], m.Connectivity[2]);
  const QualityReport q = MeasureQuality(m);
  EXPECT_LT(q.MinimumAngle, 0.2);
  EXPECT_GT(q.MaximumAngle, 179.8);
  EXPECT_EQ(q.InvertedCells, 0u);
}

TEST(MeshQuality, InvertedAndFlatTetrahedraAreCounted)
{
  SimplexMesh m = KuhnCube();
  std::swap(m.Connectivity[1], m.Connectivity[2]); // invert cell 0
  // A flat cell (four coplanar points) is "inverted" too: volume <= 0.
  m.Connectivity.insert(m.Connectivity.end(), { 0, 1, 2, 3 });
  m.Materials.push_back(1);
  const QualityReport q = MeasureQuality(m);
  EXPECT_EQ(q.InvertedCells, 2u);
  // Inverting a cell does not change its angles; the flat one has 0 and 180.
  EXPECT_NEAR(q.MinimumAngle, 0.0, 1e-9);
  EXPECT_NEAR(q.MaximumAngle, 180.0, 1e-9);
}

TEST(MeshQuality, TrianglesPlanarAngles)
{
  // Right triangle with legs 4 and 1: 90, atan(1/4), atan(4).
  const QualityReport q = MeasureQuality(Triangles({ { 0, 0, 0 }, { 4, 0, 0 }, { 0, 1, 0 } }, { 0, 1, 2 }));
  EXPECT_NEAR(q.MinimumAngle, Deg(std::atan(0.25)), 1e-9);
  EXPECT_NEAR(q.MaximumAngle, 90.0, 1e-9);
  EXPECT_EQ(q.InvertedCells, 0u);

  const double h = std::sqrt(3.0) / 2;
  const QualityReport e = MeasureQuality(Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, h, 0 } }, { 0, 1, 2 }));
  EXPECT_NEAR(e.MinimumAngle, 60.0, 1e-9);
  EXPECT_NEAR(e.MaximumAngle, 60.0, 1e-9);
}

TEST(MeshQuality, ClockwiseTriangleIsInverted)
{
  const SimplexMesh m = Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } },
    { 0, 1, 2, /* clockwise: */ 1, 2, 3, /* degenerate: */ 0, 1, 1 });
  const QualityReport q = MeasureQuality(m);
  EXPECT_EQ(q.InvertedCells, 2u);
}

TEST(MeshQuality, EmptyMesh)
{
  const QualityReport q = MeasureQuality(SimplexMesh{});
  EXPECT_EQ(q.InvertedCells, 0u);
  EXPECT_EQ(q.MinimumAngle, 0.0);
  EXPECT_EQ(q.MaximumAngle, 0.0);
}
