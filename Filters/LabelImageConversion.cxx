// SPDX-License-Identifier: GPL-2.0-or-later
// Converts vtkImageData label images to the core's validated LabelImage, with the map back to physical space.
#include "LabelImageConversion.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace labelmesher
{

Point3 ImagePlacement::ToPhysical(const Point3& p) const
{
  double local[3];
  for (int a = 0; a < 3; ++a)
  {
    local[this->ImageAxis[a]] = this->Start[a] + p[a] * this->Step[a];
  }
  Point3 x;
  for (int r = 0; r < 3; ++r)
  {
    x[r] = this->Origin[r] + this->Direction[3 * r] * local[0] +
      this->Direction[3 * r + 1] * local[1] + this->Direction[3 * r + 2] * local[2];
  }
  return x;
}

bool ImagePlacement::ToIndex(const Point3& x, Point3& index) const
{
  double inverse[9];
  std::copy(this->Direction, this->Direction + 9, inverse);
  if (vtkMatrix3x3::Determinant(inverse) == 0.0)
  {
    return false;
  }
  vtkMatrix3x3::Invert(this->Direction, inverse);
  double local[3];
  for (int r = 0; r < 3; ++r)
  {
    local[r] = inverse[3 * r] * (x[0] - this->Origin[0]) + inverse[3 * r + 1] * (x[1] - this->Origin[1]) +
      inverse[3 * r + 2] * (x[2] - this->Origin[2]);
  }
  for (int a = 0; a < 3; ++a)
  {
    index[a] = (local[this->ImageAxis[a]] - this->Start[a]) / this->Step[a];
  }
  return true;
}

bool ImagePlacement::ReversesOrientation() const
{
  double m[9]; // columns: physical image of each LabelImage axis
  for (int a = 0; a < 3; ++a)
  {
    for (int r = 0; r < 3; ++r)
    {
      m[3 * r + a] = this->Direction[3 * r + this->ImageAxis[a]] * this->Step[a];
    }
  }
  const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
    m[2] * (m[3] * m[7] - m[4] * m[6]);
  return det < 0;
}

namespace
{


// ---- pass 1: gather -------------------------------------------------------
struct GatherLabels
{
  LabelImage& Labels; ///< the values in the input's order, as narrow as they allow
  vtkIdType Begin = 0; ///< the first value gathered
  std::string Error;
  bool HasForeground = false;

  template <typename ArrayT>
  void operator()(ArrayT* array)
  {
    const auto values = vtk::DataArrayValueRange<1>(
      array, this->Begin, this->Begin + static_cast<vtkIdType>(this->Labels.NumberOfVoxels()));
    std::size_t n = 0;
    for (const auto v : values)
    {
      const long double value = static_cast<long double>(v);
      if (!this->Check(value))
      {
        return;
      }
      Labels.SetLabel(n++, static_cast<std::int32_t>(v));
    }
  }

  // Values of types the dispatcher does not cover (e.g. implicit arrays).
  void Fallback(vtkDataArray* array)
  {
    for (std::size_t n = 0; n < this->Labels.NumberOfVoxels(); ++n)
    {
      const double value = array->GetComponent(this->Begin + static_cast<vtkIdType>(n), 0);
      if (!this->Check(value))
      {
        return;
      }
      Labels.SetLabel(n, static_cast<std::int32_t>(value));
    }
  }

  bool Check(long double value)
  {
    if (value < 0)
    {
      this->Error = "negative label " + std::to_string(static_cast<long long>(value)) +
        " (labels must be >= 0, 0 = background)";
      return false;
    }
    if (value > std::numeric_limits<std::int32_t>::max())
    {
      this->Error = "label " + std::to_string(static_cast<unsigned long long>(value)) +
        " does not fit a 32-bit signed integer";
      return false;
    }
    this->HasForeground = this->HasForeground || value > 0;
    return true;
  }
};

} // namespace

double ResampledVoxels(const int dims[3], const double spacing[3])
{
  int normal = -1;
  for (int a = 2; a >= 0 && normal < 0; --a)
  {
    normal = dims[a] == 1 ? a : -1;
  }
  double h = std::numeric_limits<double>::max();
  for (int a = 0; a < 3; ++a)
  {
    h = a == normal ? h : std::min(h, std::abs(spacing[a]));
  }
  double voxels = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    voxels *= a == normal ? 1.0 : std::max(1.0, std::round(dims[a] * std::abs(spacing[a]) / h));
  }
  return voxels;
}

namespace
{

/// Builds the LabelImage (x fastest) from the gathered labels of an image with
/// point dimensions `dims`, permuting a single-slice image into the x-y plane and
/// resampling to isotropic voxels of the smallest (in-plane) spacing.
LabelImage PlaceLabels(LabelImage&& labels, const int dims[3],
  const int extent[6], const double spacing[3], ImagePlacement& placement)
{
  // 2D when one axis has a single slice; the last such axis is the normal.
  int normal = -1;
  for (int a = 2; a >= 0 && normal < 0; --a)
  {
    if (dims[a] == 1)
    {
      normal = a;
    }
  }
  if (normal >= 0)
  {
    int next = 0;
    for (int a = 0; a < 3; ++a)
    {
      if (a != normal)
      {
        placement.ImageAxis[next++] = a;
      }
    }
    placement.ImageAxis[2] = normal;
  }
  const int meshedAxes = normal >= 0 ? 2 : 3;

  double h = std::numeric_limits<double>::max();
  for (int a = 0; a < meshedAxes; ++a)
  {
    h = std::min(h, std::abs(spacing[placement.ImageAxis[a]]));
  }
  placement.VoxelSize = h;

  int newDims[3];
  std::vector<std::vector<int>> source(3); // source index along each LabelImage axis
  for (int a = 0; a < 3; ++a)
  {
    const int axis = placement.ImageAxis[a];
    const int n = dims[axis];
    const double s = spacing[axis];
    const double sign = s < 0 ? -1.0 : 1.0;
    const bool resample = a < meshedAxes && std::abs(std::abs(s) - h) > 1e-9 * h;
    if (!resample)
    {
      newDims[a] = n;
      placement.Start[a] = extent[2 * axis] * s;
      placement.Step[a] = s;
      source[a].resize(n);
      for (int i = 0; i < n; ++i)
      {
        source[a][i] = i;
      }
      continue;
    }
    // Keep the physical span of the voxels, [-s/2, (n - 1/2) s], and tile it
    // with voxels of size h; voxel j samples the old voxel under its centre.
    const double ratio = std::abs(s) / h;
    newDims[a] = std::max(1, static_cast<int>(std::lround(n * ratio))); // bounded: ResampledVoxels
    placement.Start[a] = extent[2 * axis] * s + sign * 0.5 * (h - std::abs(s));
    placement.Step[a] = sign * h;
    source[a].resize(newDims[a]);
    for (int j = 0; j < newDims[a]; ++j)
    {
      source[a][j] = std::min(n - 1, static_cast<int>(std::floor((j + 0.5) / ratio)));
    }
  }

  bool identity = true; // neither permuted nor resampled: the gathered labels are the image
  for (int a = 0; a < 3; ++a)
  {
    identity = identity && placement.ImageAxis[a] == a && newDims[a] == dims[a];
    for (int i = 0; identity && i < newDims[a]; ++i)
      identity = source[a][i] == i;
  }
  if (identity)
    return std::move(labels);
  LabelImage image(newDims[0], newDims[1], newDims[2], labels.BytesPerLabel());
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(dims[0]),
    static_cast<std::size_t>(dims[0]) * dims[1] };
  const std::size_t sx = stride[placement.ImageAxis[0]];
  const std::size_t sy = stride[placement.ImageAxis[1]];
  const std::size_t sz = stride[placement.ImageAxis[2]];
  std::size_t out = 0;
  for (int k = 0; k < newDims[2]; ++k)
  {
    for (int j = 0; j < newDims[1]; ++j)
    {
      const std::size_t row = source[2][k] * sz + source[1][j] * sy;
      for (int i = 0; i < newDims[0]; ++i)
      {
        image.SetLabel(out++, labels.Label(row + source[0][i] * sx));
      }
    }
  }
  return image;
}

} // namespace

namespace
{

/// The label array's checks, shared by whole images and slabs; "" when it holds labels.
std::string LabelArrayProblem(vtkImageData* input, vtkDataArray* scalars)
{
  if (!scalars)
  {
    return "Input image has no point scalars: expected integer labels";
  }
  if (scalars->GetDataType() == VTK_FLOAT || scalars->GetDataType() == VTK_DOUBLE)
  {
    return std::string("Input scalars '") + (scalars->GetName() ? scalars->GetName() : "") + "' are of type " +
      scalars->GetDataTypeAsString() + ": expected integer labels";
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    return "Input scalars have " + std::to_string(scalars->GetNumberOfComponents()) +
      " components: expected one label per voxel";
  }
  if (scalars->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return "Input scalars have " + std::to_string(scalars->GetNumberOfTuples()) + " values for " +
      std::to_string(input->GetNumberOfPoints()) + " points: expected point-associated labels";
  }
  return {};
}

/// Gathers `scalars` from value `begin` on into `labels` in storage order; the reason when a
/// label is refused.
std::string GatherInto(vtkDataArray* scalars, vtkIdType begin, LabelImage& labels, bool& hasForeground)
{
  GatherLabels gather{ labels, begin, {} };
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Integrals>::Execute(scalars, gather))
  {
    gather.Fallback(scalars);
  }
  hasForeground = gather.HasForeground;
  return gather.Error.empty() ? std::string() : "Invalid label image: " + gather.Error;
}

} // namespace

bool ConvertsAsIs(const int dims[3], const double spacing[3])
{
  if (dims[0] == 1 || dims[1] == 1)
  {
    return false; // a single slice across x or y is permuted (and a single row is not worth a slab)
  }
  const int meshed = dims[2] == 1 ? 2 : 3;
  double h = std::numeric_limits<double>::max();
  for (int a = 0; a < meshed; ++a)
  {
    if (!std::isfinite(spacing[a]) || spacing[a] == 0.0)
    {
      return false; // not meshed at all (ConvertLabelImage refuses it)
    }
    h = std::min(h, std::abs(spacing[a]));
  }
  for (int a = 0; a < meshed; ++a)
  {
    if (std::abs(std::abs(spacing[a]) - h) > 1e-9 * h) // PlaceLabels' test for resampling
    {
      return false;
    }
  }
  return true;
}

bool ConvertLabelSlab(vtkImageData* piece, vtkDataArray* scalars, const int wholeExtent[6], int first, int end,
  LabelImage& slab, std::string& error)
{
  const int dims[3] = { wholeExtent[1] - wholeExtent[0] + 1, wholeExtent[3] - wholeExtent[2] + 1,
    wholeExtent[5] - wholeExtent[4] + 1 };
  const int axis = dims[2] == 1 ? 1 : 2;
  // The piece may hold more slices than the slab (a producer that always gives the whole image),
  // never fewer, and only whole slices.
  int extent[6];
  piece->GetExtent(extent);
  error.clear();
  for (int a = 0; a < 3 && error.empty(); ++a)
  {
    const int low = a == axis ? wholeExtent[2 * a] + first : wholeExtent[2 * a];
    const int high = a == axis ? wholeExtent[2 * a] + end - 1 : wholeExtent[2 * a + 1];
    if (a == axis ? extent[2 * a] > low || extent[2 * a + 1] < high
                  : extent[2 * a] != low || extent[2 * a + 1] != high)
    {
      error = "The image's piece spans " + std::to_string(extent[2 * a]) + " to " + std::to_string(extent[2 * a + 1]) +
        " along axis " + std::to_string(a) + ": expected " + std::to_string(low) + " to " + std::to_string(high);
    }
  }
  if (error.empty())
  {
    error = LabelArrayProblem(piece, scalars);
  }
  if (!error.empty())
  {
    return false;
  }
  slab = LabelImage::EmptySlab({ dims[0], dims[1], dims[2] }, first, end);
  const vtkIdType skipped = static_cast<vtkIdType>(wholeExtent[2 * axis] + first - extent[2 * axis]) *
    static_cast<vtkIdType>(slab.SliceVoxels());
  bool hasForeground = false;
  error = GatherInto(scalars, skipped, slab, hasForeground);
  return error.empty();
}

bool ConvertLabelImage(vtkImageData* input, vtkDataArray* scalars, LabelImage& image,
  ImagePlacement& placement, std::string& error)
{
  int extent[6];
  input->GetExtent(extent);
  int dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
  }
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
  {
    error = "Input image has an empty extent: nothing to mesh";
    return false;
  }
  error = LabelArrayProblem(input, scalars);
  if (!error.empty())
  {
    return false;
  }
  const double* spacing = input->GetSpacing();
  for (int a = 0; a < 3; ++a)
  {
    if (!(std::isfinite(spacing[a]) && spacing[a] != 0.0))
    {
      error = "Input spacing along axis " + std::to_string(a) + " is " +
        std::to_string(spacing[a]) + ": expected a finite, non-zero value";
      return false;
    }
  }

  LabelImage labels(dims[0], dims[1], dims[2]); // widened as the values ask
  bool hasForeground = false;
  error = GatherInto(scalars, 0, labels, hasForeground);
  if (!error.empty())
  {
    return false;
  }
  if (!hasForeground)
  {
    error = "Input image has no foreground (every label is 0): nothing to mesh";
    return false;
  }

  // Resampling very anisotropic voxels to cubes of the smallest spacing can ask for more voxels
  // than memory holds (1 x 1 x 1e-6 mm; found by fuzzing): refuse it in one sentence instead.
  const double resampled = ResampledVoxels(dims, spacing);
  if (resampled > kMaximumResampledVoxels)
  {
    std::ostringstream s;
    s << "Spacing " << spacing[0] << " x " << spacing[1] << " x " << spacing[2]
      << " is too anisotropic: resampling to cubes of the smallest spacing would need " << resampled
      << " voxels (at most " << kMaximumResampledVoxels << ")";
    error = s.str();
    return false;
  }
  input->GetOrigin(placement.Origin);
  std::copy(input->GetDirectionMatrix()->GetData(), input->GetDirectionMatrix()->GetData() + 9,
    placement.Direction);
  image = PlaceLabels(std::move(labels), dims, extent, spacing, placement);
  return true;
}

} // namespace labelmesher
