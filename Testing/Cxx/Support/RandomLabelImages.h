// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_RandomLabelImages_h
#define labelmesher_testing_RandomLabelImages_h

/**
 * @file RandomLabelImages.h
 * Seeded, reproducible random multi-label images for property tests.
 *
 * Reproducibility: the only source of randomness is std::mt19937_64, whose
 * output sequence the C++ standard fixes. The mapping from its 64-bit words to
 * integers and reals is our own (SeededRandom below), not
 * std::uniform_*_distribution, whose results differ between standard
 * libraries. So a seed names the same image on every platform and compiler
 * (up to the floating-point evaluation of the shape predicates, which uses only
 * +, -, *, / and std::sqrt/sin/cos on doubles; the tests pin a checksum).
 *
 * What an image may contain (each drawn at random per seed, see
 * RandomImageOptions): 2-4 non-zero labels, possibly with sparse ids
 * (e.g. {3, 7, 200}); random blobs (unions of balls / rotated ellipsoids);
 * touching materials (a blob split by a plane into two labels); one-voxel-thick
 * sheets and lines; cavities (a closed hole inside a blob, empty or filled with
 * another label); tunnels (a solid torus, or a blob with a hole drilled
 * through; in 2D a ring); labels touching the image border; isolated
 * one-voxel speckles.
 *
 * Geometry follows LabelImage.h: voxel (i, j, k) is centred at (i, j, k); a
 * 2D image has Dimensions[2] == 1.
 */

#include "Support/LabelImage.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

/// Portable random numbers from std::mt19937_64 with our own mappings.
class SeededRandom
{
public:
  explicit SeededRandom(std::uint64_t seed)
    : Engine(seed)
  {
  }
  /// Next raw 64-bit word (the standard fixes this sequence).
  std::uint64_t Next() { return Engine(); }
  /// Integer in [lo, hi] (inclusive), unbiased (rejection sampling).
  std::int64_t Int(std::int64_t lo, std::int64_t hi);
  /// Real in [0, 1): the top 53 bits of a word.
  double Unit() { return static_cast<double>(Next() >> 11) * (1.0 / 9007199254740992.0); }
  /// Real in [lo, hi).
  double Real(double lo, double hi) { return lo + (hi - lo) * Unit(); }
  /// true with probability p.
  bool Chance(double p) { return Unit() < p; }

private:
  std::mt19937_64 Engine;
};

/// The kinds of structure a random image may contain.
enum class RandomFeature
{
  Blob,            ///< union of balls / ellipsoids of one label
  TouchingMaterials, ///< a blob cut by a plane into two labels (a shared interface)
  Sheet,           ///< one-voxel-thick plate (3D); in 2D a one-pixel-thick line
  Line,            ///< one-voxel-thick line segment (axis-aligned or digital diagonal)
  Cavity,          ///< an enclosed hole inside a blob (background or another label)
  Tunnel,          ///< a solid torus or a blob with a hole drilled through (2D: a ring)
  BorderContact,   ///< a blob or slab cut by the image border
  Speckle,         ///< isolated single voxels of random labels
  Box,             ///< an axis-aligned box (GenerateRandomBoxImage only)
};
const char* ToString(RandomFeature feature);

struct RandomImageOptions
{
  /// Number of distinct non-zero labels the image uses (both inclusive).
  int MinLabels = 2;
  int MaxLabels = 4;
  /// Side lengths. Most images are drawn near the lower end (property tests run
  /// thousands of them); 1 in ~20 reaches the upper half of the range.
  int MinSize3D = 8;
  int MaxSize3D = 40;
  int MinSize2D = 8;
  int MaxSize2D = 96;
  /// Probability that label ids are drawn sparse from [1, MaxLabelId] instead of 1..n.
  double SparseLabelProbability = 0.5;
  std::int32_t MaxLabelId = 255;
  /// Features allowed; each image draws a random non-empty subset of these
  /// (each with probability FeatureProbability), always at least one blob or
  /// touching pair so that the image has foreground.
  std::vector<RandomFeature> Features{ RandomFeature::Blob, RandomFeature::TouchingMaterials,
    RandomFeature::Sheet, RandomFeature::Line, RandomFeature::Cavity, RandomFeature::Tunnel,
    RandomFeature::BorderContact, RandomFeature::Speckle };
  double FeatureProbability = 0.45;
};

/// One painted primitive, for failure messages.
struct RandomFeatureRecord
{
  RandomFeature Kind;
  std::string Text; ///< e.g. "sheet label=7 axis=z at k=5 over [2,9]x[1,6]"
};

struct RandomLabelImage
{
  std::uint64_t Seed = 0;
  LabelImage Image;
  std::vector<std::int32_t> LabelIds;         ///< the ids drawn (sorted); all present in Image
  std::vector<RandomFeatureRecord> Features;  ///< in painting order (later ones overwrite)
  /// Multi-line human-readable summary: seed, size, labels and voxel counts,
  /// features. Print it in a failing property test.
  std::string Describe() const;
  bool Has(RandomFeature feature) const;
};

/// The image for `seed` (dimension 2 or 3) together with what it contains.
RandomLabelImage GenerateRandomLabelImageWithDescription(
  std::uint64_t seed, int dimension, const RandomImageOptions& options = {});

/// The image for `seed` (dimension 2 or 3).
LabelImage GenerateRandomLabelImage(
  std::uint64_t seed, int dimension, const RandomImageOptions& options = {});

/// A `size`-voxel square (2D) or cube (3D) holding 3 to 10 axis-aligned boxes
/// painted over each other, each a random label of {1, 4} (two labels) or
/// background (never all of it), one voxel thick along each axis with
/// probability 0.4 (plates, lines, single voxels): flat
/// interfaces that meet along edges and at corners, one-voxel gaps, and pieces
/// of one label touching a leaf from outside at a single lattice point. Such
/// contacts are rare in GenerateRandomLabelImage's smooth shapes. Seeded like
/// it (SeededRandom); the description names the boxes.
RandomLabelImage GenerateRandomBoxImage(std::uint64_t seed, int dimension, int size);

/// Describe() of the image for `seed`: what a failing seed contains.
std::string DescribeRandomLabelImage(
  std::uint64_t seed, int dimension, const RandomImageOptions& options = {});

/// FNV-1a hash of dimensions and labels: a cheap fingerprint for reproducibility checks.
std::uint64_t LabelImageChecksum(const LabelImage& image);

/// true if some voxel of a non-zero label has, along some axis, both opposite
/// neighbours (outside the image counts as label 0) with labels different from
/// its own: a one-voxel-thick structure.
bool HasOneVoxelThickStructure(const LabelImage& image);

/// true if some voxel on the image border has a non-zero label.
bool HasForegroundOnBorder(const LabelImage& image);

/// Distinct non-zero labels present, sorted.
std::vector<std::int32_t> PresentLabels(const LabelImage& image);

/// `image` repeated `copies` times along its last axis (z in 3D, y in 2D):
/// tall enough that a process's slab (LabelImage::Slab) is a fraction of it.
LabelImage StackedAlongLastAxis(const LabelImage& image, int copies);

} // namespace testing
} // namespace labelmesher

#endif
