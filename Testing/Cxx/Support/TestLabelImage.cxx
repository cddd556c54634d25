// SPDX-License-Identifier: GPL-2.0-or-later
// LabelImage stores labels as narrowly as they allow (1, 2 or 4 bytes) and
// widens itself when a label does not fit; every reader sees the same int32s.
#include "Support/LabelImage.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

namespace labelmesher
{
namespace
{

std::vector<std::int32_t> Visited(const LabelImage& image)
{
  std::vector<std::int32_t> out;
  image.WithLabels([&](const auto* labels) { out.assign(labels, labels + image.NumberOfVoxels()); });
  return out;
}

TEST(LabelImage, StartsBackgroundInOneBytePerVoxel)
{
  const LabelImage image(4, 3, 2);
  EXPECT_EQ(image.BytesPerLabel(), 1);
  EXPECT_EQ(image.NumberOfVoxels(), 24u);
  EXPECT_EQ(image.LabelsAsInt32(), std::vector<std::int32_t>(24, 0));
  EXPECT_EQ(image.At(-1, 0, 0), 0);
  EXPECT_EQ(image.At(4, 0, 0), 0);
}

TEST(LabelImage, WidensOnlyWhenALabelDoesNotFitAndKeepsEveryLabel)
{
  LabelImage image(5, 4, 3);
  std::mt19937 rng(7);
  std::vector<std::int32_t> expected(image.NumberOfVoxels(), 0);
  auto write = [&](std::int32_t largest) {
    for (std::size_t v = 0; v < expected.size(); v += 1 + rng() % 3)
    {
      expected[v] = static_cast<std::int32_t>(rng() % (static_cast<std::uint32_t>(largest) + 1));
      image.SetLabel(v, expected[v]);
    }
    EXPECT_EQ(image.LabelsAsInt32(), expected);
    EXPECT_EQ(Visited(image), expected);
  };
  write(255);
  EXPECT_EQ(image.BytesPerLabel(), 1);
  image(1, 2, 1) = 255;
  expected[image.Index(1, 2, 1)] = 255;
  EXPECT_EQ(image.BytesPerLabel(), 1);
  image(2, 1, 1) = 256;
  expected[image.Index(2, 1, 1)] = 256;
  EXPECT_EQ(image.BytesPerLabel(), 2);
  write(65535);
  EXPECT_EQ(image.BytesPerLabel(), 2);
  image.Set(0, 0, 2, 65536);
  expected[image.Index(0, 0, 2)] = 65536;
  EXPECT_EQ(image.BytesPerLabel(), 4);
  write(2147483646);
  EXPECT_EQ(image.At(0, 0, 2), expected[image.Index(0, 0, 2)]);
  // Small labels never narrow it again; a negative label (refused later by the mesher) is kept.
  image.Fill(3);
  EXPECT_EQ(image.BytesPerLabel(), 4);
  image(4, 3, 2) = -5;
  EXPECT_EQ(image.At(4, 3, 2), -5);
}

TEST(LabelImage, ANegativeLabelIsStoredAsItIs)
{
  LabelImage image(2, 2, 1);
  image(1, 1, 0) = -1;
  EXPECT_EQ(image.BytesPerLabel(), 4);
  EXPECT_EQ(image.At(1, 1, 0), -1);
  EXPECT_EQ(image.At(0, 1, 0), 0);
}

TEST(LabelImage, TheWidthFollowsTheLabelRange)
{
  EXPECT_EQ(LabelImage::BytesForLabels(0, 0), 1);
  EXPECT_EQ(LabelImage::BytesForLabels(0, 255), 1);
  EXPECT_EQ(LabelImage::BytesForLabels(0, 256), 2);
  EXPECT_EQ(LabelImage::BytesForLabels(3, 65535), 2);
  EXPECT_EQ(LabelImage::BytesForLabels(0, 65536), 4);
  EXPECT_EQ(LabelImage::BytesForLabels(-1, 1), 4);
  EXPECT_EQ(LabelImage(2, 2, 2, 2).BytesPerLabel(), 2);
  EXPECT_EQ(LabelImage(2, 2, 2, 4).BytesPerLabel(), 4);
  EXPECT_EQ(LabelImage(2, 2, 2, 3).BytesPerLabel(), 1); // not a width: the narrowest
}

TEST(LabelImage, ImagesAreEqualByTheirLabelsWhateverTheirWidths)
{
  LabelImage narrow(3, 3, 1), wide(3, 3, 1, 4);
  narrow(1, 1, 0) = 9;
  wide(1, 1, 0) = 9;
  EXPECT_EQ(narrow, wide);
  wide(2, 1, 0) = 1;
  EXPECT_NE(narrow, wide);
  LabelImage other(3, 1, 3);
  other(1, 0, 1) = 9;
  EXPECT_NE(narrow, other); // same labels, other dimensions
}

TEST(LabelImage, AWriteThroughAReferenceReadsBack)
{
  LabelImage image(3, 2, 1);
  auto voxel = image(2, 1, 0); // a reference into the image, not a copy
  voxel = 300;
  EXPECT_EQ(image.At(2, 1, 0), 300);
  image(0, 0, 0) = image(2, 1, 0);
  EXPECT_EQ(image.At(0, 0, 0), 300);
  const LabelImage& view = image;
  EXPECT_EQ(view(0, 0, 0), 300);
}

TEST(LabelImage, ASlabHoldsItsSlicesOnlyAndRefusesTheOthers)
{
  for (int dimension : { 2, 3 })
  {
    const int nz = dimension == 3 ? 9 : 1, ny = dimension == 3 ? 4 : 9;
    LabelImage whole(5, ny, nz);
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < 5; ++i)
          whole(i, j, k) = 300 + i + 7 * j + 31 * k; // two bytes
    const LabelImage slab = LabelImage::Slab(whole, 3, 6);
    EXPECT_TRUE(slab.IsSlab());
    EXPECT_EQ(slab.Dimensions, whole.Dimensions);
    EXPECT_EQ(slab.BytesPerLabel(), 2);
    EXPECT_EQ(slab.SlabFirst(), 3);
    EXPECT_EQ(slab.SlabEnd(), 6);
    EXPECT_EQ(slab.NumberOfVoxels(), whole.NumberOfVoxels() / 3);
    for (int k = -1; k <= nz; ++k)
      for (int j = -1; j <= ny; ++j)
        for (int i = -1; i <= 5; ++i)
        {
          const int along = dimension == 3 ? k : j;
          if (!whole.Contains(i, j, k) || (along >= 3 && along < 6))
            EXPECT_EQ(slab.At(i, j, k), whole.At(i, j, k)) << i << " " << j << " " << k;
          else
            EXPECT_THROW(slab.At(i, j, k), std::logic_error) << i << " " << j << " " << k;
        }
    // Clamped to the image; a slab of a slab only within its slices.
    EXPECT_EQ(LabelImage::Slab(whole, -4, 40).NumberOfVoxels(), whole.NumberOfVoxels());
    EXPECT_EQ(LabelImage::Slab(slab, 4, 5).At(2, dimension == 3 ? 1 : 4, dimension == 3 ? 4 : 0),
      whole.At(2, dimension == 3 ? 1 : 4, dimension == 3 ? 4 : 0));
    EXPECT_THROW(LabelImage::Slab(slab, 2, 5), std::invalid_argument);
    EXPECT_FALSE(whole.IsSlab());

    // The hash of slices is the labels', however they are stored: a slab's equals the whole
    // image's, an empty slab filled in order equals the slab; one label changed changes it.
    EXPECT_EQ(slab.SliceHash(3, 6), whole.SliceHash(3, 6));
    EXPECT_EQ(slab.SliceHash(4, 5), whole.SliceHash(4, 5));
    EXPECT_NE(whole.SliceHash(3, 6), whole.SliceHash(3, 5));
    EXPECT_THROW(slab.SliceHash(2, 6), std::invalid_argument);
    LabelImage filled = LabelImage::EmptySlab(whole.Dimensions, 3, 6);
    for (std::size_t v = 0; v < filled.NumberOfVoxels(); ++v)
      filled.SetLabel(v, slab.Label(v));
    EXPECT_EQ(filled, slab);
    EXPECT_EQ(filled.SliceHash(3, 6), whole.SliceHash(3, 6));
    LabelImage narrow(5, ny, nz);
    for (std::size_t v = 0; v < narrow.NumberOfVoxels(); ++v)
      narrow.SetLabel(v, whole.Label(v) % 200); // one byte a label
    LabelImage changed = narrow;
    changed.SetLabel(changed.NumberOfVoxels() - 1, 255);
    EXPECT_EQ(LabelImage::Slab(narrow, 0, 9).SliceHash(0, 9), narrow.SliceHash(0, 9));
    EXPECT_NE(changed.SliceHash(0, 9), narrow.SliceHash(0, 9));
    EXPECT_THROW(LabelImage::EmptySlab(whole.Dimensions, 5, 10), std::invalid_argument);
  }
}

} // namespace
} // namespace labelmesher
