// SPDX-License-Identifier: GPL-2.0-or-later
// The image's geometry (extent, spacing, origin, direction) in full precision.
#include "ImageFingerprint.h"

#include "vtkImageData.h"
#include "vtkMatrix3x3.h"

#include <sstream>

namespace labelmesher
{

std::string ImageFingerprint(vtkImageData* image)
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
  return out.str();
}

} // namespace labelmesher
