// SPDX-License-Identifier: GPL-2.0-or-later
// MeasureHausdorff / WithinHausdorff: one-sided distances between the mesh
// boundary and the image boundary, overall and per material, checked against
// values computed by hand (voxel-exact meshes: 0; translated: the shift;
// a cut voxel: corner distances) and for rigour (just above passes, just below
// fails).
#include "Checks/MeshChecks.h"
#include "VoxelMeshes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

using namespace labelmesher;
using labelmesher::testing::Det;
using labelmesher::testing::RandomImage;
using labelmesher::testing::VoxelMesh;

namespace
{

constexpr double Tol = 1.0 / 64.0;

/// Measured value v must be an upper bound of `exact` tight to the tolerance.
void ExpectMeasured(double v, double exact, const char* what)
{
  EXPECT_GE(v, exact - 1e-9) << what;
  EXPECT_LE(v, exact + Tol + 1e-9) << what;
}

/// WithinHausdorff is true just above the exact values and false just below.
void ExpectRigorous(const LabelImage& image, const SimplexMesh& mesh, double i2m, double m2i)
{
  EXPECT_TRUE(WithinHausdorff(image, mesh, i2m + 1e-4, m2i + 1e-4));
  if (i2m > 0)
  {
    EXPECT_FALSE(WithinHausdorff(image, mesh, i2m - 1e-3, m2i + 1e-4));
  }
  if (m2i > 0)
  {
    EXPECT_FALSE(WithinHausdorff(image, mesh, i2m + 1e-4, m2i - 1e-3));
  }
}
} // namespace

TEST(HausdorffDistance, VoxelExactMeshesAreAtDistanceZero)
{
  std::mt19937 rng(7);
  for (int trial = 0; trial < 10; ++trial)
  {
    const bool is2D = trial % 2 == 0;
    const LabelImage image = RandomImage(rng, 8, 7, is2D ? 1 : 6, 1 + trial % 3, 45);
    const SimplexMesh mesh = VoxelMesh(image, trial % 4 < 2);
    const HausdorffReport r = MeasureHausdorff(image, mesh);
    EXPECT_EQ(r.Overall.ImageToMesh, 0.0) << trial;
    EXPECT_EQ(r.Overall.MeshToImage, 0.0) << trial;
    EXPECT_FALSE(r.PerMaterial.empty());
    for (const auto& m : r.PerMaterial)
    {
      EXPECT_NE(m.first, 0);
      EXPECT_EQ(m.second.ImageToMesh, 0.0) << trial << " material " << m.first;
      EXPECT_EQ(m.second.MeshToImage, 0.0) << trial << " material " << m.first;
    }
    EXPECT_TRUE(WithinHausdorff(image, mesh, 0.0, 0.0)) << trial;
  }
}

TEST(HausdorffDistance, CoarseTrianglesOverFineVoxelFacesAreAtDistanceZero)
{
  // A 2x2x2 block meshed as one cube of side 2 in 6 Kuhn tetrahedra: every
  // mesh boundary triangle spans several voxel faces and conversely.
  LabelImage image(4, 4, 4);
  for (int k = 1; k <= 2; ++k)
    for (int j = 1; j <= 2; ++j)
      for (int i = 1; i <= 2; ++i)
        image(i, j, k) = 3;
  LabelImage coarse(2, 2, 2);
  coarse(1, 1, 1) = 3;
  SimplexMesh mesh = VoxelMesh(coarse);
  for (auto& p : mesh.Points)
    for (auto& x : p)
      x = 2 * x - 0.5; // voxel (1,1,1) of the coarse grid, [0.5, 1.5]^3 -> [0.5, 2.5]^3
  const HausdorffReport r = MeasureHausdorff(image, mesh);
  EXPECT_EQ(r.Overall.ImageToMesh, 0.0);
  EXPECT_EQ(r.Overall.MeshToImage, 0.0);
  EXPECT_TRUE(WithinHausdorff(image, mesh, 0.0, 0.0));
  // One voxel less in the image: now both directions are positive.
  image(1, 1, 1) = 0;
  EXPECT_FALSE(WithinHausdorff(image, mesh, 0.0, 0.0));
}

TEST(HausdorffDistance, TranslatedMeshIsAtTheShift)
{
  // Moving a voxel-exact mesh by t = 0.3 along x: every point of either
  // boundary has a point of the other within 0.3 (its translate), and the
  // centre of an x-facing voxel face is exactly 0.3 from the other boundary
  // (the nearest other planes are at least 0.5 away). So both one-sided
  // distances are 0.3, overall and for every material.
  std::mt19937 rng(99);
  for (int trial = 0; trial < 4; ++trial)
  {
    const bool is2D = trial % 2 == 1;
    const LabelImage image = RandomImage(rng, 7, 6, is2D ? 1 : 5, 2, 50);
    const SimplexMesh mesh = VoxelMesh(image, false, { 0.3, 0, 0 });
    const HausdorffReport r = MeasureHausdorff(image, mesh);
    ExpectMeasured(r.Overall.ImageToMesh, 0.3, "overall I->M");
    ExpectMeasured(r.Overall.MeshToImage, 0.3, "overall M->I");
    for (const auto& m : r.PerMaterial)
    {
      ExpectMeasured(m.second.ImageToMesh, 0.3, "material I->M");
      ExpectMeasured(m.second.MeshToImage, 0.3, "material M->I");
    }
    ExpectRigorous(image, mesh, 0.3, 0.3);
  }
}

TEST(HausdorffDistance, MissingCornerVoxel)
{
  // Image: a 4^3 block. Mesh: the block without its corner voxel (0,0,0).
  // h(I, M) = 1: the image corner (-.5,-.5,-.5) is 1 from the cavity faces and
  // from the nearest remaining outer faces; h(M, I) = 1: the cavity's inner
  // corner (.5,.5,.5) is 1 from the image's outer planes.
  LabelImage image(4, 4, 4);
  image.Fill(1);
  LabelImage meshed = image;
  meshed(0, 0, 0) = 0;
  const SimplexMesh mesh = VoxelMesh(meshed);
  const HausdorffReport r = MeasureHausdorff(image, mesh);
  ExpectMeasured(r.Overall.ImageToMesh, 1.0, "I->M");
  ExpectMeasured(r.Overall.MeshToImage, 1.0, "M->I");
  ExpectMeasured(r.PerMaterial.at(1).ImageToMesh, 1.0, "material I->M");
  ExpectRigorous(image, mesh, 1.0, 1.0);
}

TEST(HausdorffDistance, HalfPixelTriangle2D)
{
  // One pixel; the mesh is the lower-left half triangle of it. The pixel
  // corner (.5,.5) is 1/sqrt(2) from the hypotenuse; the hypotenuse midpoint
  // (0,0) is 0.5 from the pixel edges (an interior maximum: branch and bound).
  LabelImage image(1, 1, 1);
  image(0, 0, 0) = 1;
  SimplexMesh mesh;
  mesh.Dimension = 2;
  mesh.Points = { { -0.5, -0.5, 0 }, { 0.5, -0.5, 0 }, { -0.5, 0.5, 0 } };
  mesh.Connectivity = { 0, 1, 2 };
  mesh.Materials = { 1 };
  const HausdorffReport r = MeasureHausdorff(image, mesh);
  ExpectMeasured(r.Overall.ImageToMesh, std::sqrt(0.5), "I->M");
  ExpectMeasured(r.Overall.MeshToImage, 0.5, "M->I");
  ExpectRigorous(image, mesh, std::sqrt(0.5), 0.5);
}

TEST(HausdorffDistance, CornerTetrahedronInAVoxel)
{
  // One voxel; the mesh is its corner tetrahedron at (-.5,-.5,-.5). The far
  // voxel corner (.5,.5,.5) projects onto the centroid of the slanted face:
  // h(I, M) = 2/sqrt(3). The slanted face's centroid (-1/6,-1/6,-1/6) is 1/3
  // from the voxel faces, its largest distance: h(M, I) = 1/3.
  LabelImage image(1, 1, 2); // two slices: Dimensions[2] == 1 would mean 2D
  image(0, 0, 0) = 1;
  SimplexMesh mesh;
  mesh.Dimension = 3;
  mesh.Points = { { -0.5, -0.5, -0.5 }, { 0.5, -0.5, -0.5 }, { -0.5, 0.5, -0.5 }, { -0.5, -0.5, 0.5 } };
  mesh.Connectivity = { 0, 1, 2, 3 };
  mesh.Materials = { 1 };
  const HausdorffReport r = MeasureHausdorff(image, mesh);
  ExpectMeasured(r.Overall.ImageToMesh, 2 / std::sqrt(3.0), "I->M");
  ExpectMeasured(r.Overall.MeshToImage, 1.0 / 3.0, "M->I");
  ExpectRigorous(image, mesh, 2 / std::sqrt(3.0), 1.0 / 3.0);
}

TEST(HausdorffDistance, PerMaterialAndMissingMaterials)
{
  // Two labels side by side; the mesh swaps nothing overall but mislabels
  // voxel (1,0,0): overall boundaries differ only inside, per material more.
  LabelImage image(2, 1, 1);
  image(0, 0, 0) = 1;
  image(1, 0, 0) = 2;
  LabelImage wrong = image;
  wrong(1, 0, 0) = 1;
  const SimplexMesh mesh = VoxelMesh(wrong);
  const HausdorffReport r = MeasureHausdorff(image, mesh);
  // Overall: the image has the interface x = 0.5 (segment), the mesh does not:
  // its midpoint (0.5, 0) is 0.5 from the outer boundary.
  ExpectMeasured(r.Overall.ImageToMesh, 0.5, "overall I->M");
  EXPECT_EQ(r.Overall.MeshToImage, 0.0);
  // Material 1 in the mesh is the 2x1 rectangle; in the image the left pixel.
  ExpectMeasured(r.PerMaterial.at(1).ImageToMesh, 0.5, "material 1 I->M");
  ExpectMeasured(r.PerMaterial.at(1).MeshToImage, 1.0, "material 1 M->I");
  // Material 2 has an image boundary but no mesh boundary: infinity.
  EXPECT_EQ(r.PerMaterial.at(2).ImageToMesh, std::numeric_limits<double>::infinity());
  EXPECT_EQ(r.PerMaterial.at(2).MeshToImage, std::numeric_limits<double>::infinity());
  EXPECT_FALSE(WithinHausdorff(image, mesh, 10.0, 10.0));
  // Overall alone would pass at (0.5, 0): the per-material check is what fails.
  EXPECT_TRUE(WithinHausdorff(image, VoxelMesh(image), 0.0, 0.0));
}

TEST(HausdorffDistance, VoxelExactSphereIsFast)
{
  const int n = 64;
  LabelImage image(n, n, n);
  const double c = (n - 1) / 2.0, radius = n * 0.4;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if ((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c) <= radius * radius)
          image(i, j, k) = 1;
  const SimplexMesh mesh = VoxelMesh(image);
  auto t0 = std::chrono::steady_clock::now();
  const HausdorffReport r = MeasureHausdorff(image, mesh);
  const double measure = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.Overall.ImageToMesh, 0.0);
  EXPECT_EQ(r.Overall.MeshToImage, 0.0);
  t0 = std::chrono::steady_clock::now();
  EXPECT_TRUE(WithinHausdorff(image, mesh, 0.0, 0.0));
  const double within = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Shifted by half a voxel diagonally: distances are at most |shift|.
  const SimplexMesh shifted = VoxelMesh(image, false, { 0.25, 0.25, 0.0 });
  t0 = std::chrono::steady_clock::now();
  const HausdorffReport s = MeasureHausdorff(image, shifted);
  const double measureShifted = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LE(s.Overall.ImageToMesh, std::sqrt(0.125) + Tol + 1e-9);
  EXPECT_LE(s.Overall.MeshToImage, std::sqrt(0.125) + Tol + 1e-9);
  EXPECT_GE(s.Overall.ImageToMesh, 0.25 - 1e-9);
  std::printf("%d^3 sphere, %zu tets: Measure %.2f s, Within(0, 0) %.2f s, Measure shifted %.2f s "
              "(%.4f, %.4f)\n",
    n, mesh.NumberOfCells(), measure, within, measureShifted, s.Overall.ImageToMesh,
    s.Overall.MeshToImage);
}

TEST(HausdorffDistance, OneVertexPushedOutOfAFlatFace)
{
  // A 3x3x3 block meshed voxel-exactly; the lattice vertex (1.5, 1.5, 2.5) on
  // its top face is pushed up by 0.2: the mesh boundary rises in a tent whose
  // apex is 0.2 above the top plane, the largest h(M, I). The image point under
  // the apex is nearest to the tent triangles spanned by the apex and two axis
  // neighbours (the Kuhn split has two of them), of normal (0.2, 0.2, 1) (up
  // to signs): h(I, M) = 0.2 / sqrt(1.08).
  LabelImage image(5, 5, 5);
  for (int k = 1; k <= 3; ++k)
    for (int j = 1; j <= 3; ++j)
      for (int i = 1; i <= 3; ++i)
        image(i, j, k) = 1;
  SimplexMesh mesh = VoxelMesh(image);
  int moved = 0;
  for (auto& p : mesh.Points)
    if (p[0] == 1.5 && p[1] == 1.5 && p[2] == 3.5)
    {
      p[2] += 0.2;
      ++moved;
    }
  ASSERT_EQ(moved, 1);
  const HausdorffReport r = MeasureHausdorff(image, mesh);
  const double i2m = 0.2 / std::sqrt(1.08);
  ExpectMeasured(r.Overall.MeshToImage, 0.2, "M->I");
  ExpectMeasured(r.Overall.ImageToMesh, i2m, "I->M");
  ExpectRigorous(image, mesh, i2m, 0.2);
  // Elsewhere the boundaries still coincide: the per-material values agree.
  ExpectMeasured(r.PerMaterial.at(1).MeshToImage, 0.2, "material M->I");
}
