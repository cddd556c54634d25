// SPDX-License-Identifier: GPL-2.0-or-later
// Tests of the test-image generators: RandomLabelImages (seeded property-test
// inputs) and SyntheticShapes (analytic shapes, the Cassini benchmark volume).
#include "RandomLabelImages.h"
#include "SyntheticShapes.h"
#include "ThinFeatureImages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <cmath>
#include <cstdint>
#include <map>
#include <queue>
#include <set>
#include <vector>

using namespace labelmesher;
using namespace labelmesher::testing;

namespace
{

/// true if some voxel of label 0 cannot be reached from outside the image
/// through 6-connected background: an enclosed cavity.
bool HasEnclosedBackground(const LabelImage& image)
{
  const auto& d = image.Dimensions;
  const int dim = image.Dimension();
  std::vector<char> reached(image.NumberOfVoxels(), 0);
  std::queue<std::array<int, 3>> queue;
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        const bool border = i == 0 || j == 0 || i == d[0] - 1 || j == d[1] - 1 ||
          (dim == 3 && (k == 0 || k == d[2] - 1));
        if (border && image.At(i, j, k) == 0)
        {
          reached[image.Index(i, j, k)] = 1;
          queue.push({ i, j, k });
        }
      }
  const int offsets[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  while (!queue.empty())
  {
    const auto v = queue.front();
    queue.pop();
    for (int n = 0; n < 2 * dim; ++n)
    {
      const int i = v[0] + offsets[n][0], j = v[1] + offsets[n][1], k = v[2] + offsets[n][2];
      if (image.Contains(i, j, k) && image.At(i, j, k) == 0 && !reached[image.Index(i, j, k)])
      {
        reached[image.Index(i, j, k)] = 1;
        queue.push({ i, j, k });
      }
    }
  }
  for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
    if (image.Label(v) == 0 && !reached[v])
      return true;
  return false;
}

/// true if two different non-zero labels share a voxel face.
bool HasTouchingMaterials(const LabelImage& image)
{
  const auto& d = image.Dimensions;
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        const auto l = image.At(i, j, k);
        if (l == 0)
          continue;
        for (const auto& n : { image.At(i + 1, j, k), image.At(i, j + 1, k), image.At(i, j, k + 1) })
          if (n != 0 && n != l)
            return true;
      }
  return false;
}

/// true if some non-zero voxel differs from all its 2*dim face neighbours.
bool HasIsolatedVoxel(const LabelImage& image)
{
  const auto& d = image.Dimensions;
  const bool three = image.Dimension() == 3;
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        const auto l = image.At(i, j, k);
        if (l != 0 && image.At(i - 1, j, k) != l && image.At(i + 1, j, k) != l &&
          image.At(i, j - 1, k) != l && image.At(i, j + 1, k) != l &&
          (!three || (image.At(i, j, k - 1) != l && image.At(i, j, k + 1) != l)))
          return true;
      }
  return false;
}

std::size_t Count(const LabelImage& image, std::int32_t label)
{
  const std::vector<std::int32_t> labels = image.LabelsAsInt32();
  return static_cast<std::size_t>(std::count(labels.begin(), labels.end(), label));
}

const std::vector<RandomFeature> kAllFeatures{ RandomFeature::Blob, RandomFeature::TouchingMaterials,
  RandomFeature::Sheet, RandomFeature::Line, RandomFeature::Cavity, RandomFeature::Tunnel,
  RandomFeature::BorderContact, RandomFeature::Speckle };

} // namespace

// ---- SeededRandom ---------------------------------------------------------------

TEST(SeededRandom, IntegersStayInRangeAndCoverIt)
{
  SeededRandom random(42);
  std::vector<int> hits(7, 0);
  for (int n = 0; n < 7000; ++n)
  {
    const auto v = random.Int(-3, 3);
    ASSERT_GE(v, -3);
    ASSERT_LE(v, 3);
    ++hits[static_cast<std::size_t>(v + 3)];
  }
  for (int h : hits)
    EXPECT_GT(h, 800); // ~1000 each
  for (int n = 0; n < 1000; ++n)
  {
    const double u = random.Unit();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
  EXPECT_EQ(random.Int(5, 5), 5);
}

TEST(SeededRandom, SequenceIsFixedByTheStandard)
{
  // std::mt19937_64's 10000th output for the default seed is fixed by the
  // standard ([rand.predef]); our mapping builds only on raw words.
  SeededRandom random(5489u);
  std::uint64_t x = 0;
  for (int n = 0; n < 10000; ++n)
    x = random.Next();
  EXPECT_EQ(x, 9981545732273789042ull);
}

// ---- RandomLabelImages --------------------------------------------------------

TEST(RandomLabelImages, SameSeedGivesIdenticalImage)
{
  for (int dimension : { 2, 3 })
    for (std::uint64_t seed : { 0ull, 1ull, 17ull, 123456789ull, 0xFFFFFFFFFFFFFFFFull })
    {
      const auto a = GenerateRandomLabelImageWithDescription(seed, dimension);
      const auto b = GenerateRandomLabelImageWithDescription(seed, dimension);
      EXPECT_EQ(a.Image.Dimensions, b.Image.Dimensions);
      EXPECT_EQ(a.Image.LabelsAsInt32(), b.Image.LabelsAsInt32()) << a.Describe();
      EXPECT_EQ(a.Describe(), b.Describe());
      EXPECT_EQ(GenerateRandomLabelImage(seed, dimension).LabelsAsInt32(), a.Image.LabelsAsInt32());
    }
}

TEST(RandomLabelImages, PinnedChecksumsStayStable)
{
  // Reported failing seeds must name the same image later: a change here means
  // the generator changed (update the pins deliberately, never silently).
  const std::uint64_t c2 = LabelImageChecksum(GenerateRandomLabelImage(1, 2));
  const std::uint64_t c3 = LabelImageChecksum(GenerateRandomLabelImage(1, 3));
  EXPECT_EQ(c2, 0x0141515feac6d145ull) << DescribeRandomLabelImage(1, 2);
  EXPECT_EQ(c3, 0x48dbbd1b3be9f330ull) << DescribeRandomLabelImage(1, 3);
}

TEST(RandomLabelImages, DifferentSeedsDiffer)
{
  for (int dimension : { 2, 3 })
  {
    std::set<std::uint64_t> checksums;
    for (std::uint64_t seed = 0; seed < 200; ++seed)
      checksums.insert(LabelImageChecksum(GenerateRandomLabelImage(seed, dimension)));
    EXPECT_EQ(checksums.size(), 200u) << "dimension " << dimension;
  }
  // 2D and 3D images of one seed are unrelated.
  EXPECT_NE(GenerateRandomLabelImage(7, 2).Dimensions, GenerateRandomLabelImage(7, 3).Dimensions);
}

TEST(RandomLabelImages, LabelCountsAndSizesWithinRange)
{
  const RandomImageOptions options;
  for (int dimension : { 2, 3 })
  {
    std::size_t small = 0, total = 0;
    bool sparse = false;
    for (std::uint64_t seed = 0; seed < 500; ++seed)
    {
      const auto r = GenerateRandomLabelImageWithDescription(seed, dimension);
      const auto& image = r.Image;
      ASSERT_EQ(image.Dimension(), dimension) << r.Describe();
      ASSERT_EQ(image.NumberOfVoxels(),
        std::size_t(image.Dimensions[0]) * image.Dimensions[1] * image.Dimensions[2]);
      const int lo = dimension == 3 ? options.MinSize3D : options.MinSize2D;
      const int hi = dimension == 3 ? options.MaxSize3D : options.MaxSize2D;
      for (int a = 0; a < dimension; ++a)
      {
        ASSERT_GE(image.Dimensions[a], lo) << r.Describe();
        ASSERT_LE(image.Dimensions[a], hi) << r.Describe();
      }
      const auto present = PresentLabels(image);
      ASSERT_GE(present.size(), 2u) << r.Describe();
      ASSERT_LE(present.size(), 4u) << r.Describe();
      ASSERT_EQ(present, r.LabelIds) << r.Describe();
      for (auto l : image.LabelsAsInt32())
        ASSERT_GE(l, 0);
      for (auto l : present)
      {
        ASSERT_LE(l, options.MaxLabelId);
        sparse = sparse || l > 4;
      }
      const int side = dimension == 3 ? 16 : 32;
      small += image.NumberOfVoxels() <= std::size_t(std::pow(side, dimension)) ? 1 : 0;
      ++total;
    }
    EXPECT_TRUE(sparse) << "no sparse label ids in dimension " << dimension;
    // Property tests run thousands of these: most must be small.
    EXPECT_GT(small, total * 6 / 10) << "dimension " << dimension;
  }
}

TEST(RandomLabelImages, EveryFeatureOccursWithin200Seeds)
{
  for (int dimension : { 2, 3 })
  {
    std::map<RandomFeature, int> drawn;
    int border = 0, thin = 0, cavity = 0, touching = 0, isolated = 0, noBorder = 0;
    for (std::uint64_t seed = 0; seed < 200; ++seed)
    {
      const auto r = GenerateRandomLabelImageWithDescription(seed, dimension);
      for (const auto& f : r.Features)
        ++drawn[f.Kind];
      const bool b = HasForegroundOnBorder(r.Image);
      border += b;
      noBorder += !b;
      thin += HasOneVoxelThickStructure(r.Image);
      cavity += HasEnclosedBackground(r.Image);
      touching += HasTouchingMaterials(r.Image);
      isolated += HasIsolatedVoxel(r.Image);
    }
    for (RandomFeature f : kAllFeatures)
      EXPECT_GE(drawn[f], 10) << ToString(f) << " drawn too rarely in dimension " << dimension;
    // Detected from the voxels, independently of what the generator says it drew.
    EXPECT_GE(border, 10) << "dimension " << dimension;
    EXPECT_GE(noBorder, 10) << "dimension " << dimension;
    EXPECT_GE(thin, 10) << "dimension " << dimension;
    EXPECT_GE(cavity, 5) << "dimension " << dimension;
    EXPECT_GE(touching, 10) << "dimension " << dimension;
    EXPECT_GE(isolated, 5) << "dimension " << dimension;
    std::cout << "dimension " << dimension << " over 200 seeds: border " << border << ", thin " << thin
              << ", enclosed background " << cavity << ", touching materials " << touching
              << ", isolated voxel " << isolated << "\n";
  }
}

TEST(RandomLabelImages, FeatureSelectionIsHonoured)
{
  RandomImageOptions options;
  options.Features = { RandomFeature::Sheet };
  options.FeatureProbability = 1.0;
  for (std::uint64_t seed = 0; seed < 50; ++seed)
  {
    const auto r = GenerateRandomLabelImageWithDescription(seed, 3, options);
    EXPECT_TRUE(r.Has(RandomFeature::Sheet)) << r.Describe();
    for (const auto& f : r.Features)
      EXPECT_TRUE(f.Kind == RandomFeature::Sheet || f.Kind == RandomFeature::Blob ||
        f.Kind == RandomFeature::TouchingMaterials || f.Text.rfind("fill-in", 0) == 0)
        << r.Describe();
  }
  RandomImageOptions single;
  single.MinLabels = single.MaxLabels = 1;
  for (std::uint64_t seed = 0; seed < 50; ++seed)
    EXPECT_EQ(PresentLabels(GenerateRandomLabelImage(seed, 2, single)).size(), 1u);
}

TEST(RandomLabelImages, DescriptionNamesSeedAndFeatures)
{
  const auto r = GenerateRandomLabelImageWithDescription(99, 3);
  const std::string text = r.Describe();
  EXPECT_NE(text.find("seed=99"), std::string::npos) << text;
  EXPECT_EQ(text, DescribeRandomLabelImage(99, 3));
  for (const auto& f : r.Features)
    EXPECT_NE(text.find(f.Text), std::string::npos);
}

TEST(RandomLabelImages, ThousandImagesAreCheap)
{
  std::size_t voxels = 0;
  for (std::uint64_t seed = 1000; seed < 2000; ++seed)
    voxels += GenerateRandomLabelImage(seed, 3).NumberOfVoxels();
  std::cout << "1000 3D images, " << voxels << " voxels in all\n";
  EXPECT_LT(voxels, 1000u * 20000u); // mean below ~27^3
}

TEST(ThinStructureDetector, FindsSheetsButNotSlabs)
{
  LabelImage slab(6, 6, 6);
  for (int k = 2; k < 4; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i)
        slab(i, j, k) = 3;
  EXPECT_FALSE(HasOneVoxelThickStructure(slab));
  EXPECT_TRUE(HasForegroundOnBorder(slab));
  LabelImage sheet(6, 6, 6);
  for (int j = 1; j < 5; ++j)
    for (int i = 1; i < 5; ++i)
      sheet(i, j, 2) = 3;
  EXPECT_TRUE(HasOneVoxelThickStructure(sheet));
  EXPECT_FALSE(HasForegroundOnBorder(sheet));
}

// ---- ThinFeatureImages ---------------------------------------------------------

namespace
{
/// true if two voxels of one non-zero label lie two apart along an axis with a voxel of another
/// label (or background) between them: a one-voxel gap between pieces of the same label.
bool HasOneVoxelGapWithinALabel(const LabelImage& image)
{
  const auto& d = image.Dimensions;
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        const std::int32_t l = image.At(i, j, k);
        if (l == 0)
          continue;
        const int step[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
        for (const auto& e : step)
          if (image.At(i + 2 * e[0], j + 2 * e[1], k + 2 * e[2]) == l && image.At(i + e[0], j + e[1], k + e[2]) != l &&
            image.Contains(i + 2 * e[0], j + 2 * e[1], k + 2 * e[2]))
            return true;
      }
  return false;
}
} // namespace

TEST(ThinFeatureImages, SameSeedSameImageAndSeedsDiffer)
{
  for (int dimension : { 2, 3 })
  {
    std::set<std::uint64_t> checksums;
    for (std::uint64_t seed = 0; seed < 50; ++seed)
    {
      const RandomLabelImage a = GenerateThinFeatureImage(seed, dimension, 12);
      const RandomLabelImage b = GenerateThinFeatureImage(seed, dimension, 12);
      EXPECT_EQ(LabelImageChecksum(a.Image), LabelImageChecksum(b.Image)) << "seed " << seed;
      EXPECT_EQ(a.Describe(), b.Describe());
      checksums.insert(LabelImageChecksum(a.Image));
    }
    EXPECT_GE(checksums.size(), 45u) << "dimension " << dimension;
  }
}

TEST(ThinFeatureImages, ThinFeaturesOneVoxelFromOtherPiecesAreCommon)
{
  // What the generator is for: counted over 200 seeds each, so a change that loses them fails.
  for (int dimension : { 2, 3 })
  {
    int thin = 0, gapWithinLabel = 0, gapOfThirdLabel = 0, corner = 0;
    for (std::uint64_t seed = 0; seed < 200; ++seed)
    {
      const RandomLabelImage r = GenerateThinFeatureImage(seed, dimension, dimension == 3 ? 12 : 20);
      ASSERT_FALSE(PresentLabels(r.Image).empty()) << r.Describe();
      for (std::int32_t l : PresentLabels(r.Image))
        EXPECT_TRUE(l == 1 || l == 2 || l == 3 || l == 5) << r.Describe();
      thin += HasOneVoxelThickStructure(r.Image);
      gapWithinLabel += HasOneVoxelGapWithinALabel(r.Image);
      gapOfThirdLabel += r.Describe().find("gap label=5") != std::string::npos;
      corner += r.Describe().find("corner label=") != std::string::npos;
    }
    EXPECT_GE(thin, 140) << "dimension " << dimension;
    EXPECT_GE(gapWithinLabel, 60) << "dimension " << dimension;
    EXPECT_GE(gapOfThirdLabel, 30) << "dimension " << dimension;
    EXPECT_GE(corner, 50) << "dimension " << dimension;
  }
}

TEST(ThinFeatureImages, RefusesBadArguments)
{
  EXPECT_THROW(GenerateThinFeatureImage(1, 4, 12), std::invalid_argument);
  EXPECT_THROW(GenerateThinFeatureImage(1, 3, 5), std::invalid_argument);
}

// ---- SyntheticShapes -----------------------------------------------------------

TEST(SyntheticShapes, DiscAndEllipseAreasMatch)
{
  const auto disc = MakeDisc(64, 20.0, 5);
  EXPECT_EQ(disc.Dimension(), 2);
  EXPECT_NEAR(double(Count(disc, 5)), 3.14159265 * 400, 0.02 * 3.14159265 * 400);
  const auto ellipse = MakeEllipse(80, 50, 30.0, 12.0, 30.0, 2);
  EXPECT_NEAR(double(Count(ellipse, 2)), 3.14159265 * 360, 0.03 * 3.14159265 * 360);
  EXPECT_FALSE(HasForegroundOnBorder(ellipse));
}

TEST(SyntheticShapes, TouchingBlobsShareAnInterface)
{
  const auto blobs = MakeTouchingBlobs2D(64, 40, 1, 7);
  EXPECT_EQ(PresentLabels(blobs), (std::vector<std::int32_t>{ 1, 7 }));
  EXPECT_TRUE(HasTouchingMaterials(blobs));
  EXPECT_EQ(Count(blobs, 1), Count(blobs, 7)); // mirror symmetric
  EXPECT_FALSE(HasForegroundOnBorder(blobs));
}

TEST(SyntheticShapes, SphereEllipsoidTorusVolumes)
{
  const double pi = 3.14159265358979;
  const auto sphere = MakeSphere(40, 15.0);
  EXPECT_NEAR(double(Count(sphere, 1)), 4.0 / 3.0 * pi * 15 * 15 * 15, 0.02 * 4.0 / 3.0 * pi * 3375);
  const auto ellipsoid = MakeEllipsoid(40, 30, 20, 15, 10, 6, 4);
  EXPECT_NEAR(double(Count(ellipsoid, 4)), 4.0 / 3.0 * pi * 900, 0.03 * 4.0 / 3.0 * pi * 900);
  const auto torus = MakeTorus(40, 12.0, 4.0, 9);
  EXPECT_NEAR(double(Count(torus, 9)), 2 * pi * pi * 12 * 16, 0.03 * 2 * pi * pi * 192);
  // The tunnel: the voxel at the centre is background and not enclosed.
  EXPECT_EQ(torus.At(19, 19, 19), 0);
  EXPECT_FALSE(HasEnclosedBackground(torus));
}

TEST(SyntheticShapes, NestedSpheres)
{
  const auto nested = MakeNestedSpheres(32, { 14.0, 9.0, 4.0 }, { 1, 2, 0 });
  EXPECT_EQ(PresentLabels(nested), (std::vector<std::int32_t>{ 1, 2 }));
  EXPECT_TRUE(HasEnclosedBackground(nested)); // label 0 innermost: a cavity
  EXPECT_TRUE(HasTouchingMaterials(nested));
  EXPECT_THROW(MakeNestedSpheres(10, { 2.0, 3.0 }, { 1, 2 }), std::invalid_argument);
}

TEST(SyntheticShapes, CassiniVolumeHasTwoLobesMeetingAtANeck)
{
  for (int n : { 40, 100 })
  {
    const CassiniOptions options;
    const auto image = MakeCassiniVolume(n, options);
    ASSERT_EQ(image.Dimensions, (std::array<int, 3>{ n, n, n }));
    EXPECT_EQ(PresentLabels(image), (std::vector<std::int32_t>{ 1, 2 }));
    EXPECT_EQ(Count(image, 1), Count(image, 2)); // symmetric about the neck
    EXPECT_TRUE(HasTouchingMaterials(image));
    EXPECT_FALSE(HasForegroundOnBorder(image));
    // Extent along x: 2 sqrt(a^2 + b^2) = n - 2 margin.
    int first = n, last = -1;
    const int c = n / 2;
    for (int i = 0; i < n; ++i)
      if (image.At(i, c, c) != 0 || image.At(i, c - 1, c - 1) != 0)
      {
        first = std::min(first, i);
        last = std::max(last, i);
      }
    EXPECT_NEAR(last - first + 1, n - 2 * options.Margin, 2.0) << n;
    // The neck is much thinner than the lobes.
    const double a = CassiniFocalDistance(n, options);
    const double neck = a * std::sqrt(options.ShapeRatio * options.ShapeRatio - 1);
    const double lobe = options.ShapeRatio * options.ShapeRatio * a / 2; // max |y| = b^2 / 2a
    EXPECT_LT(neck, 0.5 * lobe);
    std::size_t neckVoxels = 0;
    const int mid = n / 2 - 1; // last layer of label 1 for even n
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        neckVoxels += image.At(mid, j, k) == 1 && image.At(mid + 1, j, k) == 2;
    EXPECT_GT(neckVoxels, 0u);
    EXPECT_NEAR(double(neckVoxels), 3.14159265 * neck * neck, 0.25 * 3.14159265 * neck * neck + 4);
  }
  CassiniOptions one;
  one.SplitLobes = false;
  EXPECT_EQ(PresentLabels(MakeCassiniVolume(50, one)), (std::vector<std::int32_t>{ 1 }));
}
