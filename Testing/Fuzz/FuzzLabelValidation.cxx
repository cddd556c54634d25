// SPDX-License-Identifier: GPL-2.0-or-later
// libFuzzer target: the filters' label-image validation (ConvertLabelImage,
// LabelImageConversion.h) on images decoded from the bytes:
//   byte 0: scalar type (one of 11), bytes 1-3: dimensions (0..8 each), byte 4: components (1..2),
//   bytes 5-28: spacing as three raw doubles (NaN, inf, 0, negative all reachable), then the
//   values' raw bytes (missing ones are 0).
// An accepted image must be what the validation promises (one integer component, labels in
// [0, 2^31), some foreground, finite non-zero spacing) and convert to the same labels; a refused
// one must come with a one-line reason.
#include "LabelImageConversion.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <string>

namespace
{
[[noreturn]] void Finding(const std::string& what)
{
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

constexpr int kTypes[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT, VTK_UNSIGNED_SHORT, VTK_INT,
  VTK_UNSIGNED_INT, VTK_LONG_LONG, VTK_UNSIGNED_LONG_LONG, VTK_FLOAT, VTK_DOUBLE };
constexpr std::size_t kHeader = 5 + 3 * sizeof(double);
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if (size < kHeader)
    return 0;
  const int type = kTypes[data[0] % (sizeof(kTypes) / sizeof(kTypes[0]))];
  const int dims[3] = { data[1] % 9, data[2] % 9, data[3] % 9 };
  const int components = 1 + data[4] % 2;
  double spacing[3];
  std::memcpy(spacing, data + 5, sizeof(spacing));

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims);
  image->SetSpacing(spacing);
  auto scalars = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  scalars->SetName("Labels");
  scalars->SetNumberOfComponents(components);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2]);
  const std::size_t bytes = static_cast<std::size_t>(scalars->GetNumberOfValues()) * scalars->GetDataTypeSize();
  if (bytes > 0) // an empty array has no buffer at all
  {
    std::memset(scalars->GetVoidPointer(0), 0, bytes);
    std::memcpy(scalars->GetVoidPointer(0), data + kHeader, std::min(bytes, size - kHeader));
  }
  image->GetPointData()->SetScalars(scalars);

  // Anisotropic spacing is resampled to cubes of the smallest: an image that grows past 10^7
  // voxels that way is legitimately large, not a validation question (and would exhaust the
  // fuzzer's memory); past kMaximumResampledVoxels the validation must refuse it.
  const double resampled = labelmesher::ResampledVoxels(dims, spacing);
  const bool tooLarge = resampled > labelmesher::kMaximumResampledVoxels;
  if (resampled > 1e7 && !tooLarge)
    return 0;
  labelmesher::LabelImage converted;
  labelmesher::ImagePlacement placement;
  std::string error;
  const bool accepted = labelmesher::ConvertLabelImage(image, scalars, converted, placement, error);
  if (!accepted)
  {
    if (error.empty() || error.find('\n') != std::string::npos)
      Finding("refused without a one-line reason: '" + error + "'");
    return 0;
  }
  if (tooLarge)
    Finding("accepted an image whose resampling needs " + std::to_string(resampled) + " voxels");
  if (components != 1 || type == VTK_FLOAT || type == VTK_DOUBLE)
    Finding("accepted a label array of " + std::to_string(components) + " components, type " + std::to_string(type));
  for (double s : spacing)
    if (!std::isfinite(s) || s == 0.0)
      Finding("accepted a spacing of " + std::to_string(s));
  // The same set of labels: a conversion may reorder the axes (a 2D image's plane) and resample
  // anisotropic voxels to finer cubes (repeating voxels: counts change), but must not change,
  // drop or invent a label.
  std::map<double, std::size_t> given, kept;
  for (vtkIdType v = 0; v < scalars->GetNumberOfTuples(); ++v)
  {
    const double label = scalars->GetComponent(v, 0);
    if (label < 0 || label >= 2147483648.0)
      Finding("accepted a label of " + std::to_string(label));
    ++given[label];
  }
  for (std::int32_t label : converted.LabelsAsInt32())
    ++kept[static_cast<double>(label)];
  const auto sameLabels = [](const std::map<double, std::size_t>& a, const std::map<double, std::size_t>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const auto& x, const auto& y) { return x.first == y.first; });
  };
  if (!sameLabels(given, kept))
    Finding("the converted image holds other labels than the input");
  if (kept.size() == 1 && kept.begin()->first == 0.0)
    Finding("accepted an image of background only");
  return 0;
}
