// SPDX-License-Identifier: GPL-2.0-or-later
// The image's geometry (extent, spacing, origin, direction) in full precision and one pass of
// FNV-1a over its labels' bytes.
#include "ImageFingerprint.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"

#include <cstdint>
#include <sstream>

namespace labelmesher
{

std::string ImageFingerprint(vtkImageData* image, vtkDataArray* labels)
{
  std::ostringstream out;
  out.precision(17);
  if (image == nullptr)
    return out.str();
  int extent[6];
  image->GetExtent(extent);
  for (int e : extent)
    out << e << ' ';
  for (int a = 0; a < 3; ++a)
    out << image->GetSpacing()[a] << ' ' << image->GetOrigin()[a] << ' ';
  for (int i = 0; i < 9; ++i) // the direction places the points as much as the origin does
    out << image->GetDirectionMatrix()->GetData()[i] << ' ';
  if (labels != nullptr)
  {
    const auto* bytes = static_cast<const unsigned char*>(labels->GetVoidPointer(0));
    const std::size_t size =
      static_cast<std::size_t>(labels->GetNumberOfValues()) * static_cast<std::size_t>(labels->GetDataTypeSize());
    std::uint64_t hash = 14695981039346656037ULL;
    for (std::size_t i = 0; i < size; ++i)
      hash = (hash ^ bytes[i]) * 1099511628211ULL;
    out << labels->GetDataType() << ' ' << hash << ' ';
  }
  return out.str();
}

} // namespace labelmesher
