// SPDX-License-Identifier: GPL-2.0-or-later
//
// The guarantees of the initial ORD mesh, asserted on seeded random label
// images (2-4 labels, touching materials, one-voxel sheets and lines, cavities,
// tunnels, labels on the image border, speckle; RandomLabelImages.h) with
// distance bounds drawn from {0, 1, 2, 3}:
//   - every dihedral (planar) angle is at least the bound the enumeration
//     proves (TestAngleBoundEnumeration), and no cell is inverted;
//   - the mesh is conforming and its boundary watertight;
//   - h(I, M) <= ImageToMeshDistance and h(M, I) <= MeshToImageDistance,
//     overall and per material (exact test, WithinHausdorff);
//   - per material, components and Euler characteristic of the meshed region
//     equal those of the voxel region.
// The same on images of stacked axis-aligned boxes (GenerateRandomBoxImage):
// flat interfaces meeting at edges and corners, one-voxel gaps, pieces of one
// label touching at a point, which the smooth shapes above rarely produce.
// The measuring code (Checks/) is independent of the mesher's own tests.
// A failure prints the seed and what its image contains.

#include "LabelOctreeMesher.h"
#include "MesherGuarantees.h"
#include "RandomLabelImages.h"
#include "ThinFeatureImages.h"

#include <gtest/gtest.h>

#include <sstream>

namespace labelmesher
{
namespace
{

constexpr int kImagesPerShard = 50;

struct Shard
{
  int Dimension;
  int Index;
};

std::string Explain(const testing::RandomLabelImage& random, const MesherParameters& p)
{
  std::ostringstream s;
  s << "seed " << random.Seed << ", h(I,M) <= " << p.ImageToMeshDistance << ", h(M,I) <= " << p.MeshToImageDistance
    << "\n"
    << random.Describe();
  return s.str();
}

void CheckGuarantees(const testing::RandomLabelImage& random)
{
  const MesherParameters parameters = testing::DrawDistanceBounds(random.Seed);
  const std::vector<std::string> problems = testing::ViolatedMesherGuarantees(random.Image, parameters);
  std::string listed;
  for (const std::string& problem : problems)
    listed += "  " + problem + "\n";
  EXPECT_TRUE(problems.empty()) << listed << Explain(random, parameters);
}

class MesherProperties : public ::testing::TestWithParam<Shard>
{
};

TEST_P(MesherProperties, AngleConformityHausdorffAndTopologyHold)
{
  const Shard shard = GetParam();
  for (int i = 0; i < kImagesPerShard; ++i)
  {
    const std::uint64_t seed = 1000u * shard.Dimension + static_cast<std::uint64_t>(shard.Index) * kImagesPerShard + i;
    CheckGuarantees(testing::GenerateRandomLabelImageWithDescription(seed, shard.Dimension));
    if (HasFailure())
      return; // one failing seed is enough to report
  }
}

// Seeds outside the shards above that once failed, each with the checksum of
// its image then (so a change of the generator cannot quietly retire them).
TEST(MesherPropertiesRegression, SeedsThatOnceFailed)
{
  const struct
  {
    std::uint64_t Seed;
    int Dimension;
    std::uint64_t Checksum;
    const char* What;
  } cases[] = {
    { 21401, 2, 0x3c660a8530f68c41ull,
      "two 0-points on a leaf side from separate pieces of boundary joined a slab and a blob" },
    { 30826, 2, 0x2fbc168d1b3cd90cull,
      "a piece of the interface on a leaf's side, cut off by a third label, joined two parts of a label" },
  };
  for (const auto& c : cases)
  {
    const testing::RandomLabelImage random = testing::GenerateRandomLabelImageWithDescription(c.Seed, c.Dimension);
    ASSERT_EQ(testing::LabelImageChecksum(random.Image), c.Checksum) << "seed " << c.Seed << " names another image now";
    SCOPED_TRACE(c.What);
    CheckGuarantees(random);
  }
  // Box images (GenerateRandomBoxImage, with their sizes).
  const struct
  {
    std::uint64_t Seed;
    int Dimension, Size;
    std::uint64_t Checksum;
    const char* What;
  } boxes[] = {
    { 2288, 2, 24, 0x8e1fa69094c53866ull,
      "two leaves' polygons ran through a 0-corner of a third label's boundary and joined two blocks of a label" },
  };
  for (const auto& c : boxes)
  {
    const testing::RandomLabelImage random = testing::GenerateRandomBoxImage(c.Seed, c.Dimension, c.Size);
    ASSERT_EQ(testing::LabelImageChecksum(random.Image), c.Checksum) << "box seed " << c.Seed << " names another image now";
    SCOPED_TRACE(c.What);
    CheckGuarantees(random);
  }
}

class BoxImageProperties : public ::testing::TestWithParam<Shard>
{
};

TEST_P(BoxImageProperties, AngleConformityHausdorffAndTopologyHold)
{
  // 2D: 24 x 24 pixels, 3D: 14^3 voxels (the 3D ones cost about 30 ms each).
  const Shard shard = GetParam();
  const int images = shard.Dimension == 3 ? 50 : 250;
  for (int i = 0; i < images; ++i)
  {
    const std::uint64_t seed = 100000u * shard.Dimension + static_cast<std::uint64_t>(shard.Index) * images + i;
    CheckGuarantees(testing::GenerateRandomBoxImage(seed, shard.Dimension, shard.Dimension == 3 ? 14 : 24));
    if (HasFailure())
      return;
  }
}

class ThinFeatureProperties : public ::testing::TestWithParam<Shard>
{
};

TEST_P(ThinFeatureProperties, AngleConformityHausdorffAndTopologyHold)
{
  // 2D: 20 x 20 pixels, 3D: 12^3 voxels (ThinFeatureImages.h).
  const Shard shard = GetParam();
  const int images = shard.Dimension == 3 ? 50 : 250;
  for (int i = 0; i < images; ++i)
  {
    const std::uint64_t seed = 200000u * shard.Dimension + static_cast<std::uint64_t>(shard.Index) * images + i;
    CheckGuarantees(testing::GenerateThinFeatureImage(seed, shard.Dimension, shard.Dimension == 3 ? 12 : 20));
    if (HasFailure())
      return;
  }
}

std::vector<Shard> Shards(int dimension, int count)
{
  std::vector<Shard> shards;
  for (int i = 0; i < count; ++i)
    shards.push_back({ dimension, i });
  return shards;
}

// 600 images in 3D and 600 in 2D, in shards of 50 so that ctest runs them in parallel.
INSTANTIATE_TEST_SUITE_P(ThreeD, MesherProperties, ::testing::ValuesIn(Shards(3, 12)),
  [](const ::testing::TestParamInfo<Shard>& info) { return "shard" + std::to_string(info.param.Index); });
INSTANTIATE_TEST_SUITE_P(TwoD, MesherProperties, ::testing::ValuesIn(Shards(2, 12)),
  [](const ::testing::TestParamInfo<Shard>& info) { return "shard" + std::to_string(info.param.Index); });
// 2,000 box images in 2D and 200 in 3D.
INSTANTIATE_TEST_SUITE_P(TwoD, BoxImageProperties, ::testing::ValuesIn(Shards(2, 8)),
  [](const ::testing::TestParamInfo<Shard>& info) { return "shard" + std::to_string(info.param.Index); });
INSTANTIATE_TEST_SUITE_P(ThreeD, BoxImageProperties, ::testing::ValuesIn(Shards(3, 4)),
  [](const ::testing::TestParamInfo<Shard>& info) { return "shard" + std::to_string(info.param.Index); });
// Thin features beside other pieces: 1,000 in 2D and 200 in 3D.
INSTANTIATE_TEST_SUITE_P(TwoD, ThinFeatureProperties, ::testing::ValuesIn(Shards(2, 4)),
  [](const ::testing::TestParamInfo<Shard>& info) { return "shard" + std::to_string(info.param.Index); });
INSTANTIATE_TEST_SUITE_P(ThreeD, ThinFeatureProperties, ::testing::ValuesIn(Shards(3, 4)),
  [](const ::testing::TestParamInfo<Shard>& info) { return "shard" + std::to_string(info.param.Index); });

} // namespace
} // namespace labelmesher
