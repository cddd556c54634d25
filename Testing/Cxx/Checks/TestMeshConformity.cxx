// SPDX-License-Identifier: GPL-2.0-or-later
// MeasureConformity: over-shared facets, hanging vertices (on edges and inside
// faces, not relying on a lattice) and boundary watertightness.
#include "Checks/MeshChecks.h"
#include "VoxelMeshes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <random>

using namespace labelmesher;
using labelmesher::testing::Det;
using labelmesher::testing::RandomImage;
using labelmesher::testing::VoxelMesh;

namespace
{
/// Adds a tetrahedron, positively oriented.
void AddTet(SimplexMesh& m, std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d, int material = 1)
{
  if (Det(m.Points[a], m.Points[b], m.Points[c], m.Points[d]) < 0)
    std::swap(b, c);
  m.Connectivity.insert(m.Connectivity.end(), { a, b, c, d });
  m.Materials.push_back(material);
}

SimplexMesh Empty3D(const std::vector<Point3>& pts)
{
  SimplexMesh m;
  m.Dimension = 3;
  m.Points = pts;
  return m;
}
} // namespace

TEST(MeshConformity, KuhnBlockIsConforming)
{
  LabelImage image(3, 2, 2);
  image.Fill(1);
  image(1, 1, 1) = 2; // a second material changes nothing
  const ConformityReport r = MeasureConformity(VoxelMesh(image));
  EXPECT_EQ(r.OverSharedFaces, 0u);
  EXPECT_EQ(r.HangingVertices, 0u);
  EXPECT_EQ(r.NonManifoldBoundaryEdges, 0u);
  EXPECT_TRUE(r.Conforming());
}

TEST(MeshConformity, SingleTetrahedronIsWatertight)
{
  SimplexMesh m = Empty3D({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } });
  AddTet(m, 0, 1, 2, 3);
  EXPECT_TRUE(MeasureConformity(m).Conforming());
}

TEST(MeshConformity, HangingVertexOnAnEdge)
{
  // 2D: one big triangle; across its hypotenuse two triangles meet at its midpoint.
  SimplexMesh m;
  m.Dimension = 2;
  m.Points = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 }, { 2, 2, 0 }, { 1, 1, 0 } };
  m.Connectivity = { 0, 1, 2, 1, 3, 4, 4, 3, 2 };
  m.Materials = { 1, 1, 1 };
  ConformityReport r = MeasureConformity(m);
  EXPECT_EQ(r.HangingVertices, 1u);
  EXPECT_EQ(r.OverSharedFaces, 0u);
  EXPECT_FALSE(r.Conforming());

  // The conforming version: the big triangle split at the midpoint too.
  m.Connectivity = { 0, 1, 4, 0, 4, 2, 1, 3, 4, 4, 3, 2 };
  m.Materials = { 1, 1, 1, 1 };
  r = MeasureConformity(m);
  EXPECT_EQ(r.HangingVertices, 0u);
  EXPECT_EQ(r.NonManifoldBoundaryEdges, 0u);
  EXPECT_TRUE(r.Conforming());
}

TEST(MeshConformity, HangingVertexOffTheLattice3D)
{
  // A tetrahedron edge from (0,0,0) to (1,1,1) holds the vertex (1/3,1/3,1/3)
  // of a neighbouring cell: found without any lattice assumption.
  SimplexMesh m = Empty3D({ { 0, 0, 0 }, { 1, 1, 1 }, { 1, 0, 0 }, { 0, 1, 0 },
    { 1.0 / 3, 1.0 / 3, 1.0 / 3 }, { 0, 0, 1 }, { 1, 0, 1 } });
  AddTet(m, 0, 1, 2, 3);
  AddTet(m, 4, 1, 5, 6);
  const ConformityReport r = MeasureConformity(m);
  EXPECT_EQ(r.HangingVertices, 1u);
  // A point near but not on the edge (about 1e-6 away) is not hanging. (Moving
  // it along (1, 0, 0) instead would put it inside the face y = z: hanging.)
  SimplexMesh n = m;
  n.Points[4] = { 1.0 / 3, 1.0 / 3 + 1e-6, 1.0 / 3 - 1e-6 }; // off both faces too
  EXPECT_EQ(MeasureConformity(n).HangingVertices, 0u);
}

TEST(MeshConformity, HangingVertexInsideAFace)
{
  // Tetrahedron above z = 0; below, three tetrahedra fan around p = (0.25, 0.25, 0),
  // which lies strictly inside the upper tetrahedron's bottom face.
  SimplexMesh m = Empty3D({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.25, 0.25, 0 },
    { 0.3, 0.3, -1 } });
  AddTet(m, 0, 1, 2, 3);
  AddTet(m, 0, 1, 4, 5);
  AddTet(m, 1, 2, 4, 5);
  AddTet(m, 2, 0, 4, 5);
  ConformityReport r = MeasureConformity(m);
  EXPECT_EQ(r.HangingVertices, 1u);
  EXPECT_EQ(r.OverSharedFaces, 0u);
  // The same vertex unused by any cell is not a mesh vertex: not hanging.
  SimplexMesh lone = Empty3D({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.25, 0.25, 0 } });
  AddTet(lone, 0, 1, 2, 3);
  EXPECT_EQ(MeasureConformity(lone).HangingVertices, 0u);
  // A vertex on the face's plane but outside the face is not hanging.
  SimplexMesh out = m;
  out.Points[4] = { 0.75, 0.75, 0 };
  EXPECT_EQ(MeasureConformity(out).HangingVertices, 0u);
}

TEST(MeshConformity, OverSharedFace)
{
  SimplexMesh m = Empty3D({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 },
    { 0.2, 0.2, 2 } });
  AddTet(m, 0, 1, 2, 3);
  AddTet(m, 0, 1, 2, 4);
  EXPECT_EQ(MeasureConformity(m).OverSharedFaces, 0u);
  AddTet(m, 0, 1, 2, 5);
  EXPECT_EQ(MeasureConformity(m).OverSharedFaces, 1u);
}

TEST(MeshConformity, BoundaryNotWatertight)
{
  // Two tetrahedra sharing only the edge (0, 1): that edge has 4 boundary faces.
  SimplexMesh m = Empty3D({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, -1, 0 },
    { 0, 0, -1 } });
  AddTet(m, 0, 1, 2, 3);
  AddTet(m, 0, 1, 4, 5);
  ConformityReport r = MeasureConformity(m);
  EXPECT_EQ(r.NonManifoldBoundaryEdges, 1u);
  EXPECT_EQ(r.HangingVertices, 0u);
  EXPECT_FALSE(r.Conforming());

  // 2D: two triangles sharing only a vertex: 4 boundary edges there.
  SimplexMesh t;
  t.Dimension = 2;
  t.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { -1, 0, 0 }, { 0, -1, 0 } };
  t.Connectivity = { 0, 1, 2, 0, 3, 4 };
  t.Materials = { 1, 1 };
  EXPECT_EQ(MeasureConformity(t).NonManifoldBoundaryEdges, 1u);
  // A single triangle is watertight.
  SimplexMesh u;
  u.Dimension = 2;
  u.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  u.Connectivity = { 0, 1, 2 };
  u.Materials = { 1 };
  EXPECT_EQ(MeasureConformity(u).NonManifoldBoundaryEdges, 0u);
}

TEST(MeshConformity, RandomVoxelMeshesHaveNoHangingOrOverSharedFaces)
{
  std::mt19937 rng(12345);
  for (int trial = 0; trial < 5; ++trial)
  {
    LabelImage image(7, 6, trial % 2 ? 1 : 5);
    for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
      image.SetLabel(v, static_cast<std::int32_t>(rng() % 3));
    const SimplexMesh m = VoxelMesh(image);
    const ConformityReport r = MeasureConformity(m);
    EXPECT_EQ(r.OverSharedFaces, 0u) << trial;
    EXPECT_EQ(r.HangingVertices, 0u) << trial;
  }
}

TEST(MeshConformity, LargeMeshIsFast)
{
  LabelImage image(60, 60, 60);
  image.Fill(1);
  const SimplexMesh m = VoxelMesh(image); // 1.3 M tetrahedra
  const auto t0 = std::chrono::steady_clock::now();
  const ConformityReport r = MeasureConformity(m);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.Conforming());
  std::printf("MeasureConformity on %zu tetrahedra: %.2f s\n", m.NumberOfCells(), seconds);
  EXPECT_LT(seconds, 30.0);
}
