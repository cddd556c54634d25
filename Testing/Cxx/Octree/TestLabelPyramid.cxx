// SPDX-License-Identifier: GPL-2.0-or-later
//
// LabelPyramid (Filters/Core/Octree/LabelPyramid.h): the summary of every
// octree block at every level ("one label", "two labels: smallest and
// largest", "more") equals a brute-force count of the labels of the block's
// voxels, voxels outside the image counting as label 0. On small hand-made
// images with known answers, and block by block on seeded random images (2D
// and 3D, sides that are not powers of two, several seeds).

#include "Octree/LabelPyramid.h"
#include "Octree/OctreeRefinement.h"
#include "RandomLabelImages.h"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <set>
#include <sstream>

namespace labelmesher
{
namespace
{

/// What LabelPyramid::Block must return, counted voxel by voxel.
LabelSummary BruteForce(const LabelImage& image, int level, int i, int j, int k)
{
  const int side = 1 << level, depth = image.Dimension() == 2 ? 1 : side;
  std::set<std::int32_t> labels;
  for (int dk = 0; dk < depth; ++dk)
    for (int dj = 0; dj < side; ++dj)
      for (int di = 0; di < side; ++di)
        labels.insert(image.At(i + di, j + dj, k + dk));
  if (labels.size() > 2)
    return { LabelSummary::Many, LabelSummary::Many };
  return { *labels.begin(), *labels.rbegin() };
}

bool Same(const LabelSummary& a, const LabelSummary& b) { return a.First == b.First && a.Second == b.Second; }

std::string Text(const LabelSummary& s)
{
  if (s.HasMoreThanTwo())
    return "many";
  std::ostringstream out;
  out << "{" << s.First << ", " << s.Second << "}";
  return out.str();
}


struct Tally
{
  std::array<std::size_t, 3> Kinds{ 0, 0, 0 }; ///< uniform, two labels, more, at levels >= 1
};

/// Every block of every level 0..depth of the octree cube (2^depth voxels a
/// side from the image's first voxel), compared with the brute-force count.
Tally CompareEveryBlock(const LabelImage& image, int depth, const std::string& what)
{
  const LabelPyramid pyramid(image, depth);
  const int cube = 1 << depth, flat = image.Dimension() == 2;
  Tally tally;
  for (int level = 0; level <= depth; ++level)
  {
    const int side = 1 << level;
    for (int k = 0; k < (flat ? 1 : cube); k += side)
      for (int j = 0; j < cube; j += side)
        for (int i = 0; i < cube; i += side)
        {
          const LabelSummary expected = BruteForce(image, level, i, j, k);
          const LabelSummary got = pyramid.Block(level, i, j, k);
          if (!Same(expected, got))
          {
            ADD_FAILURE() << what << ": level " << level << " block (" << i << ", " << j << ", " << k << "): pyramid "
                          << Text(got) << ", voxels " << Text(expected);
            return tally;
          }
          if (level >= 1)
            ++tally.Kinds[expected.HasMoreThanTwo() ? 2 : (expected.IsUniform() ? 0 : 1)];
        }
  }
  return tally;
}

// ---- known answers ------------------------------------------------------------

TEST(LabelPyramid, SummariesOfHandMadeBlocks)
{
  // 2x2 pixels: labels 9, 3 / 3, 9 (two labels, smallest first), then one of
  // them 200 (three labels).
  LabelImage two(2, 2, 1);
  two(0, 0, 0) = 9, two(1, 0, 0) = 3, two(0, 1, 0) = 3, two(1, 1, 0) = 9;
  LabelSummary s = LabelPyramid(two, 1).Block(1, 0, 0, 0);
  EXPECT_EQ(s.First, 3);
  EXPECT_EQ(s.Second, 9);
  EXPECT_FALSE(s.IsUniform());
  EXPECT_FALSE(s.HasMoreThanTwo());
  two(1, 1, 0) = 200;
  s = LabelPyramid(two, 1).Block(1, 0, 0, 0);
  EXPECT_TRUE(s.HasMoreThanTwo());
  EXPECT_FALSE(s.IsUniform());
  // Level 0 is the voxel itself.
  s = LabelPyramid(two, 1).Block(0, 1, 1, 0);
  EXPECT_TRUE(s.IsUniform());
  EXPECT_EQ(s.First, 200);
  // The largest label an int32 holds is a label like any other.
  constexpr std::int32_t top = std::numeric_limits<std::int32_t>::max();
  LabelImage large(2, 2, 1);
  large(0, 0, 0) = large(1, 1, 0) = top;
  large(1, 0, 0) = large(0, 1, 0) = 1;
  s = LabelPyramid(large, 1).Block(1, 0, 0, 0);
  EXPECT_EQ(s.First, 1);
  EXPECT_EQ(s.Second, top);
  // A row of two: the block's second row lies outside the image (label 0).
  LabelImage row(2, 1, 1);
  row(0, 0, 0) = row(1, 0, 0) = top;
  s = LabelPyramid(row, 1).Block(1, 0, 0, 0);
  EXPECT_EQ(s.First, 0);
  EXPECT_EQ(s.Second, top);
}

TEST(LabelPyramid, VoxelsOutsideTheImageCountAsBackground)
{
  // A 3x5x7 image of label 5. Blocks reaching past its sides hold 0 and 5;
  // blocks wholly past them hold 0 only; the 8^3 root holds 0 and 5.
  LabelImage image(3, 5, 7);
  image.Fill(5);
  const LabelPyramid pyramid(image, 3);
  auto expect = [&](int level, int i, int j, int k, std::int32_t first, std::int32_t second) {
    const LabelSummary s = pyramid.Block(level, i, j, k);
    EXPECT_EQ(s.First, first) << level << ": " << i << ", " << j << ", " << k;
    EXPECT_EQ(s.Second, second) << level << ": " << i << ", " << j << ", " << k;
  };
  expect(0, 2, 4, 6, 5, 5);
  expect(1, 0, 0, 0, 5, 5); // (0..1, 0..1, 0..1): inside
  expect(1, 2, 4, 6, 0, 5); // voxel (2, 4, 6) and seven outside
  expect(1, 4, 0, 0, 0, 0); // wholly past x = 3
  expect(2, 0, 4, 4, 0, 5);
  expect(2, 4, 4, 4, 0, 0);
  expect(3, 0, 0, 0, 0, 5);
  // An image that is all background but one voxel: two labels up to the root.
  LabelImage dot(6, 6, 6);
  dot(5, 5, 5) = 2;
  const LabelPyramid dots(dot, 3);
  EXPECT_TRUE(dots.Block(3, 0, 0, 0).First == 0 && dots.Block(3, 0, 0, 0).Second == 2);
  EXPECT_TRUE(dots.Block(2, 0, 0, 0).IsUniform());
}

// ---- against the brute force ----------------------------------------------------

TEST(LabelPyramid, EveryBlockOfRandom2DImagesMatchesABruteForceCount)
{
  Tally total;
  for (std::uint64_t seed = 1; seed <= 12; ++seed)
  {
    const testing::RandomLabelImage random = testing::GenerateRandomLabelImageWithDescription(700 + seed, 2);
    const int depth = OctreeDepth(random.Image);
    for (int extra : { 0, 1 }) // the mesher's depth, and one more (blocks wholly outside)
    {
      const Tally t = CompareEveryBlock(random.Image, depth + extra, "smooth 2D seed " + std::to_string(700 + seed));
      for (int kind = 0; kind < 3; ++kind)
        total.Kinds[kind] += t.Kinds[kind];
    }
    // Box images: flat interfaces, two labels and background; sides 13..35.
    const int side = 13 + 2 * static_cast<int>(seed);
    const LabelImage boxes = testing::GenerateRandomBoxImage(seed, 2, side).Image;
    const Tally t = CompareEveryBlock(boxes, OctreeDepth(boxes), "box 2D seed " + std::to_string(seed));
    for (int kind = 0; kind < 3; ++kind)
      total.Kinds[kind] += t.Kinds[kind];
    if (HasFailure())
      return;
  }
  // The images exercise all three answers above single voxels.
  EXPECT_GT(total.Kinds[0], 100u);
  EXPECT_GT(total.Kinds[1], 100u);
  EXPECT_GT(total.Kinds[2], 100u);
}

TEST(LabelPyramid, EveryBlockOfRandom3DImagesMatchesABruteForceCount)
{
  Tally total;
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
  {
    const testing::RandomLabelImage random = testing::GenerateRandomLabelImageWithDescription(900 + seed, 3);
    const int depth = OctreeDepth(random.Image);
    const Tally t = CompareEveryBlock(random.Image, depth, "smooth 3D seed " + std::to_string(900 + seed));
    const int side = 7 + 2 * static_cast<int>(seed); // 9..19
    const LabelImage boxes = testing::GenerateRandomBoxImage(seed, 3, side).Image;
    const Tally b = CompareEveryBlock(boxes, OctreeDepth(boxes) + 1, "box 3D seed " + std::to_string(seed));
    for (int kind = 0; kind < 3; ++kind)
      total.Kinds[kind] += t.Kinds[kind] + b.Kinds[kind];
    if (HasFailure())
      return;
  }
  EXPECT_GT(total.Kinds[0], 100u);
  EXPECT_GT(total.Kinds[1], 100u);
  EXPECT_GT(total.Kinds[2], 100u);
}

TEST(LabelPyramid, EveryBlockOfLabelNoiseMatchesABruteForceCount)
{
  // Independent voxels over few labels, with non-cubic sides: many blocks of
  // two and of more labels, at every level.
  testing::SeededRandom random(4242);
  for (const std::array<int, 3>& dims : { std::array<int, 3>{ 11, 6, 1 }, std::array<int, 3>{ 5, 9, 3 },
         std::array<int, 3>{ 17, 3, 10 }, std::array<int, 3>{ 1, 1, 2 } })
  {
    LabelImage image(dims[0], dims[1], dims[2]);
    const int labels = 1 + static_cast<int>(random.Int(1, 3));
    for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
      image.SetLabel(v, random.Chance(0.7) ? 4 : static_cast<std::int32_t>(random.Int(0, labels)));
    CompareEveryBlock(image, OctreeDepth(image) + 1,
      "noise " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" + std::to_string(dims[2]));
  }
}

} // namespace
} // namespace labelmesher
