// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LabelImage_h
#define labelmesher_LabelImage_h

/**
 * @file LabelImage.h
 * The label image as the mesher sees it: a dense grid of integer labels in
 * *index space*, with no VTK or ITK types.
 *
 * Geometry convention (VTK's): voxel (i, j, k) is centred at (i, j, k); its faces
 * lie at half-integer positions. The image boundary B (dissertation section 2.1)
 * is the union of voxel faces shared by voxels of different labels, including
 * faces between a foreground voxel and the outside of the image (the outside is
 * background, label 0). A 2D image has dims[2] == 1 and lives in the plane z = 0.
 *
 * Storage is as narrow as the labels allow: 1 byte per voxel while every label
 * is in [0, 255], 2 bytes up to 65,535, 4 bytes beyond (or for a negative
 * label, which the mesher then refuses). Most label maps have fewer than 256
 * labels, and the image is the run's largest structure at scale (a 1024^3
 * image is 1 GiB at one byte, 4 GiB at four). Writing a label that does not
 * fit widens the storage once; readers see int32 labels either way.
 *
 * A slab (LabelImage::Slab) holds only the voxels whose last coordinate (z in
 * 3D, y in 2D) lies in a range: what a process of a run shared out over
 * several needs for its parts (Streaming/StreamedPipeline.h). Its Dimensions
 * are the whole image's; reading a voxel of the image it does not hold throws.
 *
 * Physical placement (origin, spacing, direction) is applied by the VTK adapter.
 */

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace labelmesher
{

class LabelImage
{
public:
  std::array<int, 3> Dimensions{ 0, 0, 0 }; ///< voxels along x, y, z (z == 1 in 2D)

  LabelImage() = default;
  /// Every voxel background (0); `bytesPerLabel` (1, 2 or 4) sets the storage to
  /// start with, e.g. from BytesForLabels when the largest label is known.
  LabelImage(int nx, int ny, int nz, int bytesPerLabel = 1)
    : Dimensions{ nx, ny, nz }
    , Voxels(static_cast<std::size_t>(nx) * ny * nz)
    , Width(bytesPerLabel == 2 || bytesPerLabel == 4 ? bytesPerLabel : 1)
  {
    Allocate();
  }

  /// The slices [first, end) of `whole` along its last axis, copied (both
  /// clamped to the image).
  static LabelImage Slab(const LabelImage& whole, int first, int end)
  {
    const int slices = whole.Dimensions[static_cast<std::size_t>(whole.SlabAxis())];
    first = std::clamp(first, 0, slices);
    end = std::clamp(end, first, slices);
    if (first < whole.First || end > whole.SlabEnd())
      throw std::invalid_argument("a slab of an image must lie in the slices it holds");
    LabelImage slab = EmptySlab(whole.Dimensions, first, end, whole.Width);
    for (std::size_t v = 0; v < slab.Voxels; ++v)
      slab.SetLabel(v, whole.Label(slab.Offset + v - whole.Offset));
    return slab;
  }

  /// The slices [first, end) along the last axis of an image of `dimensions`,
  /// every voxel background, to be filled through SetLabel in storage order
  /// (x fastest, from slice `first`): a slab read from a file piece by piece.
  static LabelImage EmptySlab(const std::array<int, 3>& dimensions, int first, int end, int bytesPerLabel = 1)
  {
    LabelImage slab(0, 0, 0, bytesPerLabel);
    slab.Dimensions = dimensions;
    const int slices = dimensions[static_cast<std::size_t>(slab.SlabAxis())];
    if (first < 0 || end < first || end > slices)
      throw std::invalid_argument("a slab must lie in its image's slices");
    slab.First = first;
    slab.End = end;
    const std::size_t slice = slab.SliceVoxels();
    slab.Offset = slice * static_cast<std::size_t>(first);
    slab.Voxels = slice * static_cast<std::size_t>(end - first);
    slab.Allocate();
    return slab;
  }

  /// Voxels in one slice across SlabAxis.
  std::size_t SliceVoxels() const
  {
    return SlabAxis() == 2 ? std::size_t(Dimensions[0]) * Dimensions[1] : std::size_t(Dimensions[0]);
  }

  /// A hash (FNV-1a over the labels as 32-bit values, whatever their storage) of
  /// the slices [first, end), which must be held: the same for a slab and for
  /// the whole image it was taken from.
  std::uint64_t SliceHash(int first, int end) const
  {
    if (first < First || end > SlabEnd() || end < first)
      throw std::invalid_argument("a hash of slices this image does not hold was asked for");
    std::uint64_t hash = 1469598103934665603ull;
    const std::size_t from = SliceVoxels() * static_cast<std::size_t>(first) - Offset;
    const std::size_t to = SliceVoxels() * static_cast<std::size_t>(end) - Offset;
    for (std::size_t v = from; v < to; ++v)
    {
      const auto label = static_cast<std::uint32_t>(Label(v));
      for (int b = 0; b < 4; ++b)
        hash = (hash ^ ((label >> (8 * b)) & 0xffu)) * 1099511628211ull;
    }
    return hash;
  }

  /// The axis a slab is cut along: the last one (z in 3D, y in 2D).
  int SlabAxis() const { return Dimension() - 1; }
  /// The slices held along SlabAxis: [SlabFirst, SlabEnd) (the whole image unless a slab).
  int SlabFirst() const { return First; }
  int SlabEnd() const { return std::min(End, Dimensions[static_cast<std::size_t>(SlabAxis())]); }
  bool IsSlab() const { return End != kWhole; }
  /// Voxel (i, j, k) of the image is held (any voxel but those beyond a slab).
  bool Holds(int i, int j, int k) const
  {
    (void)i;
    const int c = Dimensions[2] == 1 ? j : k;
    return c >= First && c < End;
  }

  /// The narrowest storage that holds every label in [smallest, largest].
  static int BytesForLabels(std::int64_t smallest, std::int64_t largest)
  {
    if (smallest < 0 || largest > 65535)
      return 4;
    return largest > 255 ? 2 : 1;
  }

  int Dimension() const { return Dimensions[2] == 1 ? 2 : 3; }
  /// The number of labels stored (the product of the dimensions unless
  /// Dimensions was changed after construction).
  std::size_t NumberOfVoxels() const { return Voxels; }
  int BytesPerLabel() const { return Width; }
  bool Contains(int i, int j, int k) const
  {
    return i >= 0 && j >= 0 && k >= 0 && i < Dimensions[0] && j < Dimensions[1] &&
      k < Dimensions[2];
  }
  /// Where voxel (i, j, k), which must be held, is stored.
  std::size_t Index(int i, int j, int k) const
  {
    return (static_cast<std::size_t>(k) * Dimensions[1] + j) * Dimensions[0] + i - Offset;
  }

  /// Label of the voxel at `index` (x fastest).
  std::int32_t Label(std::size_t index) const
  {
    switch (Width)
    {
      case 1:
        return Labels8[index];
      case 2:
        return Labels16[index];
      default:
        return Labels32[index];
    }
  }
  /// Label of voxel (i, j, k); voxels outside the image are background (0).
  /// Throws std::logic_error for a voxel of the image a slab does not hold.
  std::int32_t At(int i, int j, int k) const
  {
    if (!Contains(i, j, k))
      return 0;
    if (!Holds(i, j, k))
      throw std::logic_error("a voxel beyond this process's slab of the image was read");
    return Label(Index(i, j, k));
  }

  void SetLabel(std::size_t index, std::int32_t label)
  {
    const int needed = label >= 0 && label <= 255 ? 1 : BytesForLabels(label, label);
    if (needed > Width)
      Widen(needed);
    switch (Width)
    {
      case 1:
        Labels8[index] = static_cast<std::uint8_t>(label);
        break;
      case 2:
        Labels16[index] = static_cast<std::uint16_t>(label);
        break;
      default:
        Labels32[index] = label;
    }
  }
  void Set(int i, int j, int k, std::int32_t label) { SetLabel(Index(i, j, k), label); }
  void Fill(std::int32_t label)
  {
    for (std::size_t v = 0; v < Voxels; ++v)
      SetLabel(v, label);
  }

  /// A writable label: `image(i, j, k) = 3`, `image(i, j, k) == 3`.
  class Reference
  {
  public:
    Reference(LabelImage& image, std::size_t index)
      : Image(image)
      , At(index)
    {
    }
    operator std::int32_t() const { return Image.Label(At); }
    Reference& operator=(std::int32_t label)
    {
      Image.SetLabel(At, label);
      return *this;
    }
    Reference& operator=(const Reference& other) { return *this = static_cast<std::int32_t>(other); }

  private:
    LabelImage& Image;
    std::size_t At;
  };
  Reference operator()(int i, int j, int k) { return Reference(*this, Index(i, j, k)); }
  std::int32_t operator()(int i, int j, int k) const { return Label(Index(i, j, k)); }

  /// Calls `visit(labels)` with the stored labels as a pointer to their own
  /// type (std::uint8_t, std::uint16_t or std::int32_t), so that a generic
  /// lambda runs a whole-image loop without a width test per voxel.
  template <typename Visit>
  decltype(auto) WithLabels(Visit&& visit) const
  {
    switch (Width)
    {
      case 1:
        return visit(static_cast<const std::uint8_t*>(Labels8.data()));
      case 2:
        return visit(static_cast<const std::uint16_t*>(Labels16.data()));
      default:
        return visit(static_cast<const std::int32_t*>(Labels32.data()));
    }
  }

  /// Every label, widened (for tests and small images).
  std::vector<std::int32_t> LabelsAsInt32() const
  {
    std::vector<std::int32_t> out(Voxels);
    for (std::size_t v = 0; v < Voxels; ++v)
      out[v] = Label(v);
    return out;
  }

  friend bool operator==(const LabelImage& a, const LabelImage& b)
  {
    if (a.Dimensions != b.Dimensions || a.Voxels != b.Voxels || a.First != b.First || a.End != b.End)
      return false;
    if (a.Width == b.Width)
      return a.Labels8 == b.Labels8 && a.Labels16 == b.Labels16 && a.Labels32 == b.Labels32;
    for (std::size_t v = 0; v < a.Voxels; ++v)
      if (a.Label(v) != b.Label(v))
        return false;
    return true;
  }
  friend bool operator!=(const LabelImage& a, const LabelImage& b) { return !(a == b); }

private:
  void Allocate()
  {
    Labels8.assign(Width == 1 ? Voxels : 0, 0);
    Labels16.assign(Width == 2 ? Voxels : 0, 0);
    Labels32.assign(Width == 4 ? Voxels : 0, 0);
  }
  void Widen(int width)
  {
    LabelImage wider(0, 0, 0, width);
    wider.Voxels = Voxels; // a slab's storage only: First, End and Offset stay
    wider.Allocate();
    for (std::size_t v = 0; v < Voxels; ++v)
      wider.SetLabel(v, Label(v));
    Labels8.swap(wider.Labels8);
    Labels16.swap(wider.Labels16);
    Labels32.swap(wider.Labels32);
    Width = width;
  }

  static constexpr int kWhole = std::numeric_limits<int>::max();
  std::size_t Voxels = 0;
  // A slab holds slices [First, End) along SlabAxis(), stored from Offset
  // (the index of its first voxel in the whole image); End is kWhole otherwise.
  int First = 0, End = kWhole;
  std::size_t Offset = 0;
  int Width = 1; ///< bytes per label: 1, 2 or 4; the one vector of that width holds the labels
  std::vector<std::uint8_t> Labels8;
  std::vector<std::uint16_t> Labels16;
  std::vector<std::int32_t> Labels32;
};

} // namespace labelmesher

#endif
