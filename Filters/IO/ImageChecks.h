// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_ImageChecks_h
#define labelmesher_io_ImageChecks_h

/**
 * @file ImageChecks.h
 * The checks every input image goes through, whichever reader reads it
 * (ImageReader.cxx, SegmentationReader.cxx): the path is a regular file, the
 * geometry ITK reports is finite with positive spacing, ITK's errors fit one line.
 * The text headers' checks and the truncation check are in TextHeader.h.
 * Internal to the readers; each throws InputError.
 */

#include "ImageReader.h"
#include "StringUtilities.h"

#include "itkImageIOBase.h"
#include "itkMacro.h"

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

namespace labelmesher
{
namespace io
{
namespace detail
{

/// "(i, j, k)" of the flat point index `flat` in an image of `dims`.
inline std::string VoxelText(std::size_t flat, const int dims[3], const int start[3] = nullptr)
{
  const std::size_t nx = dims[0], ny = dims[1];
  const int zero[3] = { 0, 0, 0 };
  const int* at = start ? start : zero;
  std::ostringstream s;
  s << "(" << at[0] + flat % nx << ", " << at[1] + (flat / nx) % ny << ", " << at[2] + flat / (nx * ny) << ")";
  return s.str();
}

/// The readers' own messages for a missing path are less clear than this.
inline void CheckInputFile(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    throw InputError("cannot read '" + path + "': no such file");
  }
  if (!std::filesystem::is_regular_file(path, ec))
  {
    throw InputError("cannot read '" + path + "': not a regular file");
  }
}

inline void CheckSpacing(const double spacing[3], const std::string& path)
{
  for (int a = 0; a < 3; ++a)
  {
    if (!std::isfinite(spacing[a]) || spacing[a] <= 0.0)
    {
      std::ostringstream s;
      s << "'" << path << "' has spacing " << spacing[a] << " along axis " << a
        << ": expected a positive, finite value";
      throw InputError(s.str());
    }
  }
}

/// An empty vtkImageData with the dimensions, spacing, origin and direction of
/// the ITK image `image` (itk::Image or itk::VectorImage, 3D).
template <typename TImage>
vtkSmartPointer<vtkImageData> GeometryFromITK(TImage* image, const std::string& path)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->SetDimensions(static_cast<int>(size[0]), static_cast<int>(size[1]), static_cast<int>(size[2]));
  double spacing[3], origin[3], direction[9];
  for (int r = 0; r < 3; ++r)
  {
    spacing[r] = image->GetSpacing()[r];
    origin[r] = image->GetOrigin()[r];
    for (int c = 0; c < 3; ++c)
    {
      direction[3 * r + c] = image->GetDirection()[r][c];
      if (!std::isfinite(direction[3 * r + c]))
      {
        throw InputError("'" + path + "' has a non-finite direction matrix");
      }
    }
    if (!std::isfinite(origin[r]))
    {
      throw InputError("'" + path + "' has a non-finite origin");
    }
  }
  CheckSpacing(spacing, path);
  output->SetSpacing(spacing);
  output->SetOrigin(origin);
  output->SetDirectionMatrix(direction);
  return output;
}

/// An ITK exception as InputError: ITK's descriptions may span lines.
/// The spacing the file's header gives, checked before ITK builds an image
/// (ITK refuses a zero spacing with an exception naming an object address).
/// A negative one is fine here: ITK turns it into a flipped direction.
inline void CheckHeaderSpacing(itk::ImageIOBase* io, const std::string& path)
{
  double spacing[3] = { 1.0, 1.0, 1.0 };
  for (unsigned int d = 0; d < std::min(3u, io->GetNumberOfDimensions()); ++d)
  {
    spacing[d] = std::abs(io->GetSpacing(d));
  }
  CheckSpacing(spacing, path);
}

inline InputError ITKReadError(const std::string& path, const itk::ExceptionObject& e)
{
  std::string what = e.GetDescription();
  what.erase(std::remove(what.begin(), what.end(), '\n'), what.end());
  // ITK's "itk::ERROR: Class(0x55...): " prefix names an object, not the problem.
  const std::size_t prefix = what.find("): ");
  if ((what.rfind("ITK ERROR: ", 0) == 0 || what.rfind("itk::ERROR: ", 0) == 0) && prefix != std::string::npos)
  {
    what = what.substr(prefix + 3);
  }
  // NrrdIO chains its callers' complaints ("... [nrrd] nrrdLoad: trouble ... [nrrd] fn: reason");
  // the last link says what is wrong with the file.
  const std::size_t last = what.rfind("[nrrd] ");
  if (last != std::string::npos)
  {
    std::string reason = what.substr(last + 7);
    const std::size_t colon = reason.find(": ");
    reason = colon == std::string::npos ? reason : reason.substr(colon + 2);
    return InputError("cannot read '" + path + "': not a valid NRRD file (" + reason + ")");
  }
  return InputError("cannot read '" + path + "': " + what);
}

} // namespace detail
} // namespace io
} // namespace labelmesher

#endif
