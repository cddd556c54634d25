// SPDX-License-Identifier: GPL-2.0-or-later
// The filters' conversion of a vtkImageData into the core's LabelImage keeps the
// labels in the narrowest storage their values allow, whatever the array's type,
// through permutation (a single slice) and resampling (anisotropic spacing).
#include "LabelImageConversion.h"

#include "ImageFingerprint.h"

#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <gtest/gtest.h>

#include <functional>
#include <iterator>
#include <string>
#include <utility>

namespace labelmesher
{
namespace
{

/// An nx x ny x nz image of `Array` whose voxel v holds `label(v)`.
template <typename Array, typename Label>
vtkSmartPointer<vtkImageData> Image(int nx, int ny, int nz, Label label, double spacing[3] = nullptr)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  if (spacing)
    image->SetSpacing(spacing);
  vtkNew<Array> values;
  values->SetName("labels");
  values->SetNumberOfTuples(static_cast<vtkIdType>(nx) * ny * nz);
  for (vtkIdType v = 0; v < values->GetNumberOfTuples(); ++v)
    values->SetValue(v, label(v));
  image->GetPointData()->SetScalars(values);
  return image;
}

LabelImage Convert(vtkImageData* input)
{
  LabelImage image;
  ImagePlacement placement;
  std::string error;
  EXPECT_TRUE(ConvertLabelImage(input, input->GetPointData()->GetScalars(), image, placement, error)) << error;
  return image;
}

TEST(LabelImageConversion, StorageFollowsTheLabelsNotTheArrayType)
{
  const auto bytes = Image<vtkUnsignedCharArray>(4, 3, 2, [](vtkIdType v) { return v % 5; });
  EXPECT_EQ(Convert(bytes).BytesPerLabel(), 1);
  const auto smallInts = Image<vtkIntArray>(4, 3, 2, [](vtkIdType v) { return static_cast<int>(v % 7) * 40; });
  const LabelImage small = Convert(smallInts);
  EXPECT_EQ(small.BytesPerLabel(), 1);
  EXPECT_EQ(small.At(3, 2, 1), (23 % 7) * 40);
  const auto shorts = Image<vtkUnsignedShortArray>(4, 3, 2, [](vtkIdType v) { return v == 5 ? 1000 : 1; });
  const LabelImage medium = Convert(shorts);
  EXPECT_EQ(medium.BytesPerLabel(), 2);
  EXPECT_EQ(medium.At(1, 1, 0), 1000);
  EXPECT_EQ(medium.At(0, 0, 0), 1);
  const auto ints = Image<vtkIntArray>(4, 3, 2, [](vtkIdType v) { return v == 23 ? 100000 : static_cast<int>(v); });
  const LabelImage large = Convert(ints);
  EXPECT_EQ(large.BytesPerLabel(), 4);
  EXPECT_EQ(large.At(3, 2, 1), 100000);
  EXPECT_EQ(large.At(2, 2, 1), 22);
}

TEST(LabelImageConversion, ResamplingAndPermutationKeepLabelsAndWidth)
{
  // x-z slice, labels up to 300: permuted into the x-y plane.
  const auto slice = Image<vtkIntArray>(3, 1, 4, [](vtkIdType v) { return static_cast<int>(v) * 25; });
  const LabelImage flat = Convert(slice);
  ASSERT_EQ(flat.Dimensions, (std::array<int, 3>{ 3, 4, 1 }));
  EXPECT_EQ(flat.BytesPerLabel(), 2);
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(flat.At(i, k, 0), (k * 3 + i) * 25);

  // z spacing twice x and y: every slice doubled.
  double spacing[3] = { 1.0, 1.0, 2.0 };
  const auto thick = Image<vtkUnsignedCharArray>(2, 2, 3, [](vtkIdType v) { return 10 + v; }, spacing);
  const LabelImage cubes = Convert(thick);
  ASSERT_EQ(cubes.Dimensions, (std::array<int, 3>{ 2, 2, 6 }));
  EXPECT_EQ(cubes.BytesPerLabel(), 1);
  for (int k = 0; k < 6; ++k)
    EXPECT_EQ(cubes.At(1, 0, k), 10 + 1 + 4 * (k / 2)) << k;
}

TEST(LabelImageConversion, ASlabIsTheConvertedImagesSlicesWhenItConvertsAsIs)
{
  // What a process that reads its slab relies on: the image kept as it is has its slices, read
  // as a piece of the image (with any extent's offset), as the whole image's conversion does.
  double isotropic[3] = { 0.5, 0.5, 0.5 };
  const auto whole = Image<vtkUnsignedShortArray>(6, 5, 8, [](vtkIdType v) { return (v * 7) % 400; }, isotropic);
  int dims[3] = { 6, 5, 8 };
  EXPECT_TRUE(ConvertsAsIs(dims, isotropic));
  const int wholeExtent[6] = { 10, 15, -2, 2, 3, 10 }; // an extent that does not start at 0
  whole->SetExtent(const_cast<int*>(wholeExtent));
  const LabelImage converted = Convert(whole);
  for (const auto& [first, end] : { std::pair<int, int>{ 0, 8 }, { 2, 5 }, { 7, 8 } })
  {
    // The piece of exactly those slices, and the whole image as a piece holding more.
    vtkNew<vtkImageData> piece;
    int extent[6] = { 10, 15, -2, 2, 3 + first, 3 + end - 1 };
    piece->SetExtent(extent);
    vtkNew<vtkUnsignedShortArray> values;
    values->SetNumberOfTuples(piece->GetNumberOfPoints());
    for (vtkIdType v = 0; v < values->GetNumberOfTuples(); ++v)
      values->SetValue(v, static_cast<unsigned short>(whole->GetPointData()->GetScalars()->GetComponent(v + first * 30, 0)));
    piece->GetPointData()->SetScalars(values);
    for (vtkImageData* given : { static_cast<vtkImageData*>(piece), whole.GetPointer() })
    {
      LabelImage slab;
      std::string error;
      ASSERT_TRUE(ConvertLabelSlab(given, given->GetPointData()->GetScalars(), wholeExtent, first, end, slab, error))
        << error;
      EXPECT_EQ(slab, LabelImage::Slab(converted, first, end)) << first << " " << end;
    }
    // A piece short of the slab's slices, or of a row, is refused.
    LabelImage slab;
    std::string error;
    EXPECT_FALSE(ConvertLabelSlab(piece, values, wholeExtent, first > 0 ? first - 1 : first, first > 0 ? end : end + 1,
      slab, error));
    EXPECT_NE(error.find("expected"), std::string::npos) << error;
  }
  // Resampled or permuted: not as is.
  double anisotropic[3] = { 0.5, 0.5, 1.0 };
  EXPECT_FALSE(ConvertsAsIs(dims, anisotropic));
  int acrossY[3] = { 6, 1, 8 };
  EXPECT_FALSE(ConvertsAsIs(acrossY, isotropic));
  int acrossZ[3] = { 6, 5, 1 };
  double flat[3] = { 0.5, 0.5, 3.0 };
  EXPECT_TRUE(ConvertsAsIs(acrossZ, flat));
}

TEST(ImageFingerprint, ChangesWithEveryThingThatPlacesTheMesh)
{
  // The processes of a distributed run compare fingerprints: two images that
  // would place the mesh differently must not share one (their labels are
  // compared slab by slab, TestStreamedPipeline).
  const auto reference = Image<vtkUnsignedCharArray>(4, 3, 2, [](vtkIdType v) { return v % 3; });
  const std::string print = ImageFingerprint(reference);
  const auto same = Image<vtkUnsignedCharArray>(4, 3, 2, [](vtkIdType v) { return v % 3; });
  EXPECT_EQ(ImageFingerprint(same), print);

  const std::function<void(vtkImageData*)> changes[] = {
    [](vtkImageData* i) { i->SetOrigin(0, 0, 1e-9); },
    [](vtkImageData* i) { i->SetSpacing(1, 1, 2); },
    [](vtkImageData* i) { i->SetExtent(1, 4, 0, 2, 0, 1); },
    [](vtkImageData* i) { i->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1); },
  };
  for (std::size_t k = 0; k < std::size(changes); ++k)
  {
    const auto changed = Image<vtkUnsignedCharArray>(4, 3, 2, [](vtkIdType v) { return v % 3; });
    changes[k](changed);
    EXPECT_NE(ImageFingerprint(changed), print) << "change " << k;
  }
}

} // namespace
} // namespace labelmesher
