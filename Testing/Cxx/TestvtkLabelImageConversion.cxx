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

TEST(ImageFingerprint, ChangesWithEveryThingThatPlacesOrLabelsTheMesh)
{
  // The processes of a distributed run compare fingerprints: two images that
  // would mesh differently must not share one.
  const auto reference = Image<vtkUnsignedCharArray>(4, 3, 2, [](vtkIdType v) { return v % 3; });
  const std::string print = ImageFingerprint(reference, reference->GetPointData()->GetScalars());
  const auto same = Image<vtkUnsignedCharArray>(4, 3, 2, [](vtkIdType v) { return v % 3; });
  EXPECT_EQ(ImageFingerprint(same, same->GetPointData()->GetScalars()), print);

  const std::function<void(vtkImageData*)> changes[] = {
    [](vtkImageData* i) { i->GetPointData()->GetScalars()->SetComponent(5, 0, 0); }, // was 2
    [](vtkImageData* i) { i->SetOrigin(0, 0, 1e-9); },
    [](vtkImageData* i) { i->SetSpacing(1, 1, 2); },
    [](vtkImageData* i) { i->SetExtent(1, 4, 0, 2, 0, 1); },
    [](vtkImageData* i) { i->SetDirectionMatrix(0, -1, 0, 1, 0, 0, 0, 0, 1); },
  };
  for (std::size_t k = 0; k < std::size(changes); ++k)
  {
    const auto changed = Image<vtkUnsignedCharArray>(4, 3, 2, [](vtkIdType v) { return v % 3; });
    changes[k](changed);
    EXPECT_NE(ImageFingerprint(changed, changed->GetPointData()->GetScalars()), print) << "change " << k;
  }
}

} // namespace
} // namespace labelmesher
