// SPDX-License-Identifier: GPL-2.0-or-later
// CompareTopology: components and Euler characteristic of the closed voxels of
// every label and of the closed cells of every material, checked on shapes
// whose topology is known (torus, hollow sphere, annulus, edge contact) and on
// voxel-exact meshes of random images, which must match their image.
#include "Checks/MeshChecks.h"
#include "VoxelMeshes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

using namespace labelmesher;
using labelmesher::testing::Det;
using labelmesher::testing::RandomImage;
using labelmesher::testing::VoxelMesh;

namespace
{

RegionTopology ImageTopologyOf(const LabelImage& image, std::int32_t label)
{
  const auto result = CompareTopology(image, SimplexMesh{});
  const auto it = result.find(label);
  return it == result.end() ? RegionTopology{} : it->second.Image;
}

void ExpectTopology(const LabelImage& image, std::int32_t label, std::size_t components, long long chi)
{
  const auto result = CompareTopology(image, VoxelMesh(image));
  ASSERT_EQ(result.count(label), 1u);
  const TopologyComparison& t = result.at(label);
  EXPECT_EQ(t.Image.Components, components);
  EXPECT_EQ(t.Image.EulerCharacteristic, chi);
  EXPECT_EQ(t.Mesh.Components, components);
  EXPECT_EQ(t.Mesh.EulerCharacteristic, chi);
  EXPECT_TRUE(t.Matches());
}
} // namespace

TEST(RegionTopology, SingleVoxelIsABall)
{
  LabelImage image(3, 3, 3);
  image(1, 1, 1) = 5;
  ExpectTopology(image, 5, 1, 1);
  EXPECT_EQ(CompareTopology(image, SimplexMesh{}).size(), 1u);
}

TEST(RegionTopology, SolidTorusHasEulerCharacteristicZero)
{
  // A 3x3x1 ring of voxels (centre removed), away from the image border.
  LabelImage image(5, 5, 3);
  for (int j = 1; j <= 3; ++j)
    for (int i = 1; i <= 3; ++i)
      if (i != 2 || j != 2)
        image(i, j, 1) = 1;
  ExpectTopology(image, 1, 1, 0);
  // A thicker torus touching the image border: same topology.
  LabelImage thick(6, 6, 2);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i)
      if (i == 0 || j == 0 || i == 5 || j == 5 || i == 1 || j == 1)
        thick(i, j, 0) = thick(i, j, 1) = 3;
  ExpectTopology(thick, 3, 1, 0);
}

TEST(RegionTopology, HollowSphereHasEulerCharacteristicTwo)
{
  LabelImage image(5, 5, 5);
  for (int k = 1; k <= 3; ++k)
    for (int j = 1; j <= 3; ++j)
      for (int i = 1; i <= 3; ++i)
        image(i, j, k) = 2;
  image(2, 2, 2) = 0; // the cavity
  ExpectTopology(image, 2, 1, 2);
  // Filling the cavity with another label: label 2 keeps chi 2, label 7 is a ball.
  image(2, 2, 2) = 7;
  ExpectTopology(image, 2, 1, 2);
  ExpectTopology(image, 7, 1, 1);
}

TEST(RegionTopology, VoxelsTouchingAtAnEdgeOrCornerAreOneComponent)
{
  LabelImage edge(4, 4, 4);
  edge(1, 1, 1) = edge(2, 2, 1) = 1;
  // Closed cubes sharing an edge: V = 14, E = 23, F = 12, C = 2 -> chi 1.
  ExpectTopology(edge, 1, 1, 1);
  LabelImage corner(4, 4, 4);
  corner(1, 1, 1) = corner(2, 2, 2) = 1;
  ExpectTopology(corner, 1, 1, 1);
  LabelImage apart(4, 4, 4);
  apart(0, 1, 1) = apart(2, 1, 1) = 1;
  ExpectTopology(apart, 1, 2, 2);
  // Two voxels sharing an edge plus a third closing a loop only through edges
  // and corners: still one component; a loop of edge contacts is a torus.
  LabelImage loop(4, 4, 3);
  loop(1, 0, 1) = loop(2, 1, 1) = loop(1, 2, 1) = loop(0, 1, 1) = 1;
  ExpectTopology(loop, 1, 1, 0);
}

TEST(RegionTopology, TwoDimensionalAnnulusAndDiagonalPixels)
{
  LabelImage annulus(5, 5, 1);
  for (int j = 1; j <= 3; ++j)
    for (int i = 1; i <= 3; ++i)
      if (i != 2 || j != 2)
        annulus(i, j, 0) = 4;
  ExpectTopology(annulus, 4, 1, 0);
  EXPECT_EQ(ImageTopologyOf(annulus, 4).EulerCharacteristic, 0);

  LabelImage diagonal(3, 3, 1);
  diagonal(0, 0, 0) = diagonal(1, 1, 0) = 1; // touching at a corner: one component
  ExpectTopology(diagonal, 1, 1, 1);
  LabelImage twoDisks(5, 2, 1);
  twoDisks(0, 0, 0) = twoDisks(0, 1, 0) = twoDisks(3, 0, 0) = 1;
  ExpectTopology(twoDisks, 1, 2, 2);
}

TEST(RegionTopology, HandMadeMeshes)
{
  // Two tetrahedra sharing one vertex: one component, chi 1; a third one apart.
  SimplexMesh m;
  m.Dimension = 3;
  m.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { -1, 0, 0 }, { 0, -1, 0 },
    { 0, 0, -1 }, { 5, 5, 5 }, { 6, 5, 5 }, { 5, 6, 5 }, { 5, 5, 6 } };
  m.Connectivity = { 0, 1, 2, 3, 0, 4, 5, 6, 7, 8, 9, 10 };
  m.Materials = { 1, 1, 1 };
  auto t = CompareTopology(LabelImage{}, m);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[1].Mesh.Components, 2u);
  EXPECT_EQ(t[1].Mesh.EulerCharacteristic, 2);
  EXPECT_EQ(t[1].Image.Components, 0u);
  EXPECT_FALSE(t[1].Matches());
  // Different materials are not connected through a shared vertex.
  m.Materials = { 1, 2, 1 };
  t = CompareTopology(LabelImage{}, m);
  EXPECT_EQ(t[1].Mesh.Components, 2u);
  EXPECT_EQ(t[2].Mesh.Components, 1u);
  EXPECT_EQ(t[2].Mesh.EulerCharacteristic, 1);
  // Material 0 cells are not reported.
  m.Materials = { 0, 0, 3 };
  t = CompareTopology(LabelImage{}, m);
  EXPECT_EQ(t.size(), 1u);
  EXPECT_EQ(t.count(3), 1u);
}

TEST(RegionTopology, VoxelMeshesOfRandomImagesMatch)
{
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 12; ++trial)
  {
    const bool is2D = trial % 3 == 0;
    const LabelImage image =
      RandomImage(rng, 9, 8, is2D ? 1 : 7, 1 + trial % 3, 30 + 5 * (trial % 5));
    const auto result = CompareTopology(image, VoxelMesh(image, trial % 2 == 1));
    ASSERT_FALSE(result.empty());
    for (const auto& entry : result)
    {
      EXPECT_NE(entry.first, 0);
      EXPECT_TRUE(entry.second.Matches())
        << "trial " << trial << " label " << entry.first << ": image " << entry.second.Image.Components
        << "/" << entry.second.Image.EulerCharacteristic << " mesh " << entry.second.Mesh.Components << "/"
        << entry.second.Mesh.EulerCharacteristic;
      EXPECT_GT(entry.second.Image.Components, 0u);
    }
  }
}

TEST(RegionTopology, RemovingAVoxelChangesTheImageSide)
{
  // A mesh of the full ring compared with an image where the ring is cut: the
  // comparison must notice (the ring becomes a ball).
  LabelImage ring(5, 5, 3);
  for (int j = 1; j <= 3; ++j)
    for (int i = 1; i <= 3; ++i)
      if (i != 2 || j != 2)
        ring(i, j, 1) = 1;
  const SimplexMesh mesh = VoxelMesh(ring);
  LabelImage cut = ring;
  cut(1, 2, 1) = 0;
  const auto t = CompareTopology(cut, mesh).at(1);
  EXPECT_EQ(t.Image.EulerCharacteristic, 1);
  EXPECT_EQ(t.Mesh.EulerCharacteristic, 0);
  EXPECT_FALSE(t.Matches());
}

TEST(RegionTopology, LargeImageIsStreamed)
{
  // A 200^3 image: a ball (label 2) inside a thick spherical shell (label 1),
  // then a tunnel drilled through both along x. Before drilling: shell chi 2,
  // ball chi 1; after: the shell with two holes is a thick annulus (chi 0) and
  // the pierced ball a solid torus (chi 0).
  const int n = 200;
  LabelImage image(n, n, n);
  const double c = 99.5;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double r2 = (i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c);
        if (r2 <= 90.0 * 90.0 && r2 >= 60.0 * 60.0)
          image(i, j, k) = 1;
        else if (r2 < 60.0 * 60.0)
          image(i, j, k) = 2;
      }
  const auto t0 = std::chrono::steady_clock::now();
  const auto result = CompareTopology(image, SimplexMesh{});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("CompareTopology image side, %d^3 voxels: %.2f s\n", n, seconds);
  EXPECT_EQ(result.at(1).Image.Components, 1u);
  EXPECT_EQ(result.at(1).Image.EulerCharacteristic, 2);
  EXPECT_EQ(result.at(2).Image.Components, 1u);
  EXPECT_EQ(result.at(2).Image.EulerCharacteristic, 1);
  EXPECT_LT(seconds, 30.0);

  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      if ((j - c) * (j - c) + (k - c) * (k - c) < 10.0 * 10.0)
        for (int i = 0; i < n; ++i)
          image(i, j, k) = 0;
  const auto drilled = CompareTopology(image, SimplexMesh{});
  EXPECT_EQ(drilled.at(1).Image.Components, 1u);
  EXPECT_EQ(drilled.at(1).Image.EulerCharacteristic, 0);
  EXPECT_EQ(drilled.at(2).Image.Components, 1u);
  EXPECT_EQ(drilled.at(2).Image.EulerCharacteristic, 0);
}

TEST(RegionTopology, MoreMaterialsThanOneByteHolds)
{
  // 300 labels (from 70,000: four bytes per voxel in the image, two in the padded copy of
  // compact indices): every one a lone voxel but label 70,299, the frame of the middle slice
  // (a ring: one component, Euler characteristic 0).
  LabelImage image(40, 40, 3);
  int placed = 0;
  for (int j = 1; j < 38 && placed < 299; j += 2)
    for (int i = 1; i < 39 && placed < 299; i += 2)
      image(i, j, 1) = 70000 + placed++;
  ASSERT_EQ(placed, 299);
  ASSERT_EQ(image.BytesPerLabel(), 4);
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i)
      if (i == 0 || j == 0 || i == 39 || j == 39)
        image(i, j, 1) = 70299;
  const auto result = CompareTopology(image, SimplexMesh{});
  ASSERT_EQ(result.size(), 300u);
  for (int l = 0; l < 299; ++l)
  {
    EXPECT_EQ(result.at(70000 + l).Image.Components, 1u) << l;
    EXPECT_EQ(result.at(70000 + l).Image.EulerCharacteristic, 1) << l;
  }
  EXPECT_EQ(ImageTopologyOf(image, 70299).Components, 1u);
  EXPECT_EQ(ImageTopologyOf(image, 70299).EulerCharacteristic, 0);
}
