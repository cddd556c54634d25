// SPDX-License-Identifier: GPL-2.0-or-later
//
// The guarantees of the decimated mesh (Decimation/MeshDecimator.h), asserted
// on seeded random label images after mesher and decimator, with distance
// bounds drawn from {0, 1, 2, 3} (the mesher's and the decimator's alike) and
// the angle from {5, 10, 15, 19.47, the proven 30 (3D) / 45 (2D)}:
//   - every dihedral (planar) angle is at least the angle asked for, and no
//     cell is inverted;
//   - the mesh is conforming and its boundary watertight;
//   - h(I, M) and h(M, I) within their bounds, overall and per material;
//   - per material, components and Euler characteristic of the voxel region.
// On the smooth random images and on images of stacked boxes, 2D and 3D. The
// measuring code (Checks/) is independent of the decimator's own checks. A
// failure prints the seed, the parameters and what the image contains.

#include "DecimatorGuarantees.h"
#include "MesherGuarantees.h"
#include "RandomLabelImages.h"
#include "ThinFeatureImages.h"

#include <gtest/gtest.h>

#include <sstream>

namespace labelmesher
{
namespace
{

struct Shard
{
  int Dimension;
  int Index;
};

void CheckGuarantees(const testing::RandomLabelImage& random, DecimationCounts* total = nullptr)
{
  const MesherParameters mesher = testing::DrawDistanceBounds(random.Seed);
  const DecimationParameters decimation = testing::DrawDecimationParameters(random.Seed, random.Image.Dimension(), mesher);
  DecimationCounts counts;
  const std::vector<std::string> problems =
    testing::ViolatedDecimatorGuarantees(random.Image, mesher, decimation, &counts);
  if (total)
  {
    total->CellsBefore += counts.CellsBefore;
    total->CellsAfter += counts.CellsAfter;
  }
  std::ostringstream listed;
  for (const std::string& problem : problems)
    listed << "  " << problem << "\n";
  EXPECT_TRUE(problems.empty()) << listed.str() << "seed " << random.Seed << ", h(I,M) <= " << mesher.ImageToMeshDistance
                                << ", h(M,I) <= " << mesher.MeshToImageDistance << ", angle >= " << decimation.MinimumAngle
                                << "\n"
                                << random.Describe();
}

/// `images` images from `generate(seed)`, seeds from `first` on; the
/// decimator must also decimate (the guarantees alone would hold for a copy).
template <typename Generate>
void CheckShard(std::uint64_t first, int images, Generate&& generate)
{
  DecimationCounts total;
  for (int i = 0; i < images; ++i)
  {
    CheckGuarantees(generate(first + static_cast<std::uint64_t>(i)), &total);
    if (::testing::Test::HasFailure())
      return;
  }
  EXPECT_LT(total.CellsAfter * 2, total.CellsBefore);
}

class DecimatorProperties : public ::testing::TestWithParam<Shard>
{
};

TEST_P(DecimatorProperties, AngleConformityHausdorffAndTopologyHold)
{
  const Shard shard = GetParam();
  const int images = shard.Dimension == 3 ? 25 : 100;
  CheckShard(500000u + 1000u * shard.Dimension + static_cast<std::uint64_t>(shard.Index) * images, images,
    [&](std::uint64_t seed) { return testing::GenerateRandomLabelImageWithDescription(seed, shard.Dimension); });
}

class DecimatorBoxImageProperties : public ::testing::TestWithParam<Shard>
{
};

TEST_P(DecimatorBoxImageProperties, AngleConformityHausdorffAndTopologyHold)
{
  const Shard shard = GetParam();
  const int images = shard.Dimension == 3 ? 25 : 250;
  CheckShard(700000u + 1000u * shard.Dimension + static_cast<std::uint64_t>(shard.Index) * images, images,
    [&](std::uint64_t seed) { return testing::GenerateRandomBoxImage(seed, shard.Dimension, shard.Dimension == 3 ? 14 : 24); });
}

class DecimatorThinFeatureProperties : public ::testing::TestWithParam<Shard>
{
};

TEST_P(DecimatorThinFeatureProperties, AngleConformityHausdorffAndTopologyHold)
{
  const Shard shard = GetParam();
  const int images = shard.Dimension == 3 ? 25 : 100;
  CheckShard(800000u + 1000u * shard.Dimension + static_cast<std::uint64_t>(shard.Index) * images, images,
    [&](std::uint64_t seed) { return testing::GenerateThinFeatureImage(seed, shard.Dimension, shard.Dimension == 3 ? 12 : 20); });
}

std::vector<Shard> Shards(int dimension, int count)
{
  std::vector<Shard> shards;
  for (int i = 0; i < count; ++i)
    shards.push_back({ dimension, i });
  return shards;
}

auto ShardName = [](const ::testing::TestParamInfo<Shard>& info) { return "shard" + std::to_string(info.param.Index); };

// Smooth images: 800 in 2D, 200 in 3D; boxes: 2,000 in 2D, 100 in 3D.
INSTANTIATE_TEST_SUITE_P(TwoD, DecimatorProperties, ::testing::ValuesIn(Shards(2, 8)), ShardName);
INSTANTIATE_TEST_SUITE_P(ThreeD, DecimatorProperties, ::testing::ValuesIn(Shards(3, 8)), ShardName);
INSTANTIATE_TEST_SUITE_P(TwoD, DecimatorBoxImageProperties, ::testing::ValuesIn(Shards(2, 8)), ShardName);
INSTANTIATE_TEST_SUITE_P(ThreeD, DecimatorBoxImageProperties, ::testing::ValuesIn(Shards(3, 4)), ShardName);
// Thin features beside other pieces (ThinFeatureImages.h): 400 in 2D, 100 in 3D.
INSTANTIATE_TEST_SUITE_P(TwoD, DecimatorThinFeatureProperties, ::testing::ValuesIn(Shards(2, 4)), ShardName);
INSTANTIATE_TEST_SUITE_P(ThreeD, DecimatorThinFeatureProperties, ::testing::ValuesIn(Shards(3, 4)), ShardName);

} // namespace
} // namespace labelmesher
