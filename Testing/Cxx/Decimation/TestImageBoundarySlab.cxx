// SPDX-License-Identifier: GPL-2.0-or-later
// The image boundary of a slab (what a process of a shared-out run holds) is the whole image's
// in its interior: the same faces, in the same order, and a query there returns the same pieces
// in the same order (their order reaches the fidelity test's sums); a query that reaches the
// slab's edge throws instead of answering with faces missing. On random 2D and 3D images, tall
// along the slab axis so that a slab is a fraction of them.
#include "Decimation/ImageBoundary.h"
#include "RandomLabelImages.h"
#include "Support/LabelImage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <stdexcept>
#include <vector>

namespace labelmesher
{
namespace
{

bool SameFace(const ImageBoundary::Face& a, const ImageBoundary::Face& b)
{
  return a.Voxel == b.Voxel && a.Axis == b.Axis && a.Low == b.Low && a.High == b.High;
}

bool SamePieces(const std::vector<ConvexPiece>& a, const std::vector<ConvexPiece>& b)
{
  if (a.size() != b.size())
    return false;
  for (std::size_t p = 0; p < a.size(); ++p)
  {
    if (a[p].Count != b[p].Count)
      return false;
    for (int c = 0; c < a[p].Count; ++c)
      if (a[p].Points[static_cast<std::size_t>(c)] != b[p].Points[static_cast<std::size_t>(c)])
        return false;
  }
  return true;
}

TEST(ImageBoundarySlab, IsTheWholeImagesBoundaryInItsInterior)
{
  for (std::uint64_t seed = 951000; seed < 951012; ++seed)
  {
    const int dimension = seed % 2 == 0 ? 2 : 3;
    const auto random = testing::GenerateRandomLabelImageWithDescription(seed, dimension);
    const LabelImage image = testing::StackedAlongLastAxis(random.Image, 4);
    const int axis = image.SlabAxis(), slices = image.Dimensions[static_cast<std::size_t>(axis)];
    const ImageBoundary whole(image);
    std::set<std::pair<std::int32_t, std::int32_t>> pairs;
    for (const ImageBoundary::Face& f : whole.Faces())
      pairs.insert({ f.Low, f.High });
    std::mt19937_64 draw(seed);
    for (int trial = 0; trial < 4; ++trial)
    {
      const int first = std::uniform_int_distribution<int>(0, slices / 2)(draw);
      const int end = trial == 0 ? slices : std::uniform_int_distribution<int>(first + 1, slices)(draw);
      const LabelImage slab = LabelImage::Slab(image, first, end);
      const ImageBoundary part(slab);
      // The faces whose two voxels the slab holds, in the whole image's order.
      std::vector<ImageBoundary::Face> expected;
      for (const ImageBoundary::Face& f : whole.Faces())
      {
        const int low = f.Voxel[static_cast<std::size_t>(axis)], high = low + (f.Axis == axis ? 1 : 0);
        const auto held = [&](int c) { return c < 0 || c >= slices || (c >= first && c < end); };
        if (held(low) && held(high))
          expected.push_back(f);
      }
      ASSERT_EQ(part.Faces().size(), expected.size()) << random.Describe() << "slab " << first << " " << end;
      for (std::size_t f = 0; f < expected.size(); ++f)
        ASSERT_TRUE(SameFace(part.Faces()[f], expected[f])) << "face " << f << " of slab " << first << " " << end;

      // Queries around the slab's cells: within SlabMargin(h) of its edges, the same pieces.
      const double h = std::uniform_real_distribution<double>(0.0, 3.0)(draw);
      const int margin = ImageBoundary::SlabMargin(h);
      const int low = first == 0 ? -1 : first + margin, high = end == slices ? slices : end - margin;
      for (int query = 0; query < 40 && low < high; ++query)
      {
        Point3 lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
        for (int a = 0; a < dimension; ++a)
        {
          const int n = image.Dimensions[static_cast<std::size_t>(a)];
          const double from = a == axis ? low : -1, to = a == axis ? high - 1 : n;
          const double x = std::uniform_real_distribution<double>(from, to)(draw);
          const double y = std::uniform_real_distribution<double>(x, std::min(to, x + 3.0))(draw);
          lo[static_cast<std::size_t>(a)] = x - h;
          hi[static_cast<std::size_t>(a)] = y + h;
        }
        for (const auto& [labelLow, labelHigh] : pairs)
        {
          std::vector<ConvexPiece> fromWhole, fromSlab;
          whole.Pieces(lo, hi, labelLow, labelHigh, fromWhole);
          part.Pieces(lo, hi, labelLow, labelHigh, fromSlab);
          EXPECT_TRUE(SamePieces(fromWhole, fromSlab)) << "slab " << first << " " << end << " query " << query;
        }
      }
      // Near either edge of the slab, a query is answered as on the whole
      // image or refused, never answered in part; far enough inside, answered.
      for (int side = 0; side < 2; ++side)
      {
        if ((side == 0 && first == 0) || (side == 1 && end == slices))
          continue;
        for (double step = -3.0; step <= 16.0; step += 0.25)
        {
          const double at = side == 0 ? first + step : end - 1 - step;
          Point3 lo{ -1, -1, 0 }, hi{ double(image.Dimensions[0]), double(image.Dimensions[1]), 0 };
          lo[static_cast<std::size_t>(axis)] = at;
          hi[static_cast<std::size_t>(axis)] = at + 0.25;
          for (const auto& [labelLow, labelHigh] : pairs)
          {
            std::vector<ConvexPiece> fromWhole, fromSlab;
            whole.Pieces(lo, hi, labelLow, labelHigh, fromWhole);
            bool refused = false;
            try
            {
              part.Pieces(lo, hi, labelLow, labelHigh, fromSlab);
            }
            catch (const std::logic_error&)
            {
              refused = true;
            }
            if (!refused)
              EXPECT_TRUE(SamePieces(fromWhole, fromSlab)) << "slab " << first << " " << end << " at " << at;
            const double inside = std::min(first == 0 ? 1e9 : at - first, end == slices ? 1e9 : end - 1 - (at + 0.25));
            EXPECT_FALSE(refused && inside >= ImageBoundary::SlabMargin(0.0)) << "slab " << first << " " << end << " at " << at;
            // Beyond the slab but within the image: refused (beyond the image, no face is
            // there, and the empty answer is exact).
            const bool inImage = at + 0.25 >= -0.5 && at <= slices - 0.5;
            EXPECT_FALSE(!refused && step < 0 && inImage) << "a query beyond the slab was answered: " << at;
          }
        }
      }
    }
  }
}

TEST(ImageBoundarySlab, AnswersABoxBeyondTheImageWhateverItsSlices)
{
  // A process's parts may hold cells far beyond the image along another axis than the slab's,
  // in slices its slab does not hold: no face lies there, and the empty answer is exact.
  const auto random = testing::GenerateRandomLabelImageWithDescription(951020, 3);
  const LabelImage image = testing::StackedAlongLastAxis(random.Image, 4);
  const int slices = image.Dimensions[2];
  const LabelImage slab = LabelImage::Slab(image, slices / 2, slices);
  const ImageBoundary part(slab);
  const ImageBoundary whole(image);
  const ImageBoundary::Face& any = whole.Faces().front();
  const double beyondX = image.Dimensions[0] + 0.25;
  std::vector<ConvexPiece> pieces;
  EXPECT_NO_THROW(part.Pieces({ beyondX, 0, 0 }, { beyondX + 3, 2, 2 }, any.Low, any.High, pieces));
  EXPECT_TRUE(pieces.empty());
  EXPECT_NO_THROW(part.Pieces({ 0, -9, 0 }, { 3, -0.75, 2 }, any.Low, any.High, pieces));
  EXPECT_TRUE(pieces.empty());
  // Within the image's extent along every axis but beyond the slab: refused.
  EXPECT_THROW(part.Pieces({ 0, 0, 0 }, { 3, 2, 2 }, any.Low, any.High, pieces), std::logic_error);
  // Touching the image's last faces (x = n - 0.5) is within it.
  EXPECT_THROW(part.Pieces({ beyondX - 0.75, 0, 0 }, { beyondX + 3, 2, 2 }, any.Low, any.High, pieces), std::logic_error);
}

} // namespace
} // namespace labelmesher
