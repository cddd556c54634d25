// SPDX-License-Identifier: GPL-2.0-or-later
#include "ThinFeatureImages.h"

#include <algorithm>
#include <array>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{
namespace
{

struct Box
{
  std::array<int, 3> Lo{ 0, 0, 0 }, Hi{ 0, 0, 0 }; ///< inclusive voxel ranges
};

class Painter
{
public:
  Painter(RandomLabelImage& result, int dimension, int size)
    : Result(result)
    , Dimension(dimension)
    , Size(size)
  {
  }

  /// Paints `box` (clamped to the image) with `label`; false when nothing of it is inside.
  bool Paint(Box box, std::int32_t label, const char* what)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int limit = a < this->Dimension ? this->Size - 1 : 0;
      box.Lo[a] = std::max(box.Lo[a], 0);
      box.Hi[a] = std::min(box.Hi[a], limit);
      if (box.Lo[a] > box.Hi[a])
        return false;
    }
    for (int k = box.Lo[2]; k <= box.Hi[2]; ++k)
      for (int j = box.Lo[1]; j <= box.Hi[1]; ++j)
        for (int i = box.Lo[0]; i <= box.Hi[0]; ++i)
          this->Result.Image(i, j, k) = label;
    std::ostringstream text;
    text << what << " label=" << label;
    for (int a = 0; a < this->Dimension; ++a)
      text << (a == 0 ? " [" : "x[") << box.Lo[a] << "," << box.Hi[a] << "]";
    this->Result.Features.push_back({ RandomFeature::Box, text.str() });
    return true;
  }

private:
  RandomLabelImage& Result;
  int Dimension, Size;
};

/// A coordinate on a leaf side (a multiple of `grid`), or one voxel before or beyond it.
int NearLeafSide(SeededRandom& random, int grid, int size)
{
  return grid * int(random.Int(0, std::max(0, size / grid))) + int(random.Int(-1, 1));
}

/// A piece whose faces sit on (or one voxel off) the sides of leaves of a random level.
Box LeafAlignedPiece(SeededRandom& random, int dimension, int size)
{
  const int grid = 1 << int(random.Int(1, 3)); // 2, 4 or 8 voxels
  Box box;
  for (int a = 0; a < dimension; ++a)
  {
    box.Lo[a] = NearLeafSide(random, grid, size);
    box.Hi[a] = box.Lo[a] + grid * int(random.Int(1, 2)) - 1 + int(random.Int(-1, 1));
  }
  return box;
}

/// A thin feature parallel to side `side` (0: low, 1: high) of `piece` along `axis`, one voxel
/// beyond the gap; `gap` receives that one-voxel layer.
Box ThinFeatureBeside(SeededRandom& random, const Box& piece, int dimension, int axis, int side, Box& gap)
{
  Box feature;
  const int gapAt = side == 0 ? piece.Lo[axis] - 1 : piece.Hi[axis] + 1;
  const int featureAt = side == 0 ? gapAt - 1 : gapAt + 1;
  // Across the other axes: a random range around the piece's (overlapping it, or sticking out);
  // one of them may shrink to one voxel (a line in 3D, a single voxel in 2D).
  const int thinAxis = random.Chance(0.4) ? int(random.Int(0, dimension - 1)) : -1;
  for (int b = 0; b < dimension; ++b)
  {
    if (b == axis)
    {
      feature.Lo[b] = feature.Hi[b] = featureAt;
      continue;
    }
    feature.Lo[b] = int(random.Int(piece.Lo[b] - 2, piece.Hi[b]));
    feature.Hi[b] = b == thinAxis ? feature.Lo[b] : int(random.Int(feature.Lo[b], piece.Hi[b] + 2));
  }
  gap = feature;
  gap.Lo[axis] = gap.Hi[axis] = gapAt;
  return feature;
}

/// A small box touching `piece` only along an edge or at a corner, from outside.
Box CornerContact(SeededRandom& random, const Box& piece, int dimension)
{
  Box contact;
  const int touching = int(random.Int(2, dimension)); // axes on which it lies diagonally outside
  for (int a = 0; a < dimension; ++a)
  {
    const int extent = int(random.Int(0, 2));
    if (a < touching)
    {
      if (random.Chance(0.5))
      {
        contact.Hi[a] = piece.Lo[a] - 1;
        contact.Lo[a] = contact.Hi[a] - extent;
      }
      else
      {
        contact.Lo[a] = piece.Hi[a] + 1;
        contact.Hi[a] = contact.Lo[a] + extent;
      }
    }
    else
    {
      contact.Lo[a] = int(random.Int(piece.Lo[a], piece.Hi[a]));
      contact.Hi[a] = std::min(piece.Hi[a], contact.Lo[a] + extent);
    }
  }
  return contact;
}

} // namespace

RandomLabelImage GenerateThinFeatureImage(std::uint64_t seed, int dimension, int size)
{
  if ((dimension != 2 && dimension != 3) || size < 6)
    throw std::invalid_argument("GenerateThinFeatureImage: dimension must be 2 or 3, size at least 6");
  RandomLabelImage result;
  result.Seed = seed;
  SeededRandom random(seed * 0x9E3779B97F4A7C15ull + 0x7F4A7C15ull * static_cast<std::uint64_t>(dimension));
  result.Image = LabelImage(size, size, dimension == 3 ? size : 1);
  Painter painter(result, dimension, size);

  std::vector<std::pair<Box, std::int32_t>> pieces;
  const int count = int(random.Int(1, 3));
  for (int attempt = 0; pieces.size() < static_cast<std::size_t>(count) && attempt < 50; ++attempt)
  {
    const Box piece = LeafAlignedPiece(random, dimension, size);
    const std::int32_t label = random.Chance(0.3) ? 2 : 1;
    if (painter.Paint(piece, label, "piece"))
      pieces.emplace_back(piece, label);
  }
  if (pieces.empty())
  {
    const Box middle{ { size / 4, size / 4, dimension == 3 ? size / 4 : 0 },
      { size / 2, size / 2, dimension == 3 ? size / 2 : 0 } };
    painter.Paint(middle, 1, "piece");
    pieces.emplace_back(middle, 1);
  }

  const int thin = int(random.Int(1, 3));
  for (int f = 0; f < thin; ++f)
  {
    const auto& [piece, label] = pieces[static_cast<std::size_t>(random.Int(0, std::int64_t(pieces.size()) - 1))];
    const int axis = int(random.Int(0, dimension - 1));
    Box gap;
    const Box feature = ThinFeatureBeside(random, piece, dimension, axis, int(random.Int(0, 1)), gap);
    // The same label as the piece (the two must stay apart), or another one.
    const std::int32_t featureLabel = random.Chance(0.5) ? label : (label == 1 ? 3 : 1);
    if (painter.Paint(feature, featureLabel, "thin"))
      painter.Paint(gap, random.Chance(0.3) ? 5 : 0, "gap");
  }
  if (random.Chance(0.4))
  {
    // A few tries: beside a piece at the image border the contact may fall outside.
    for (int attempt = 0; attempt < 5; ++attempt)
    {
      const auto& [piece, label] = pieces[static_cast<std::size_t>(random.Int(0, std::int64_t(pieces.size()) - 1))];
      if (painter.Paint(CornerContact(random, piece, dimension), random.Chance(0.5) ? label : 3, "corner"))
        break;
    }
  }

  const std::vector<std::int32_t> labels = result.Image.LabelsAsInt32();
  if (std::none_of(labels.begin(), labels.end(), [](std::int32_t l) { return l != 0; }))
    painter.Paint(pieces.front().first, pieces.front().second, "piece (again)");
  result.LabelIds = PresentLabels(result.Image);
  return result;
}

} // namespace testing
} // namespace labelmesher
