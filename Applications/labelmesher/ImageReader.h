// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_ImageReader_h
#define labelmesher_cli_ImageReader_h

/**
 * @file ImageReader.h
 * Reads a label image into vtkImageData, keeping origin, spacing and direction:
 * NRRD, NIfTI and MetaImage through ITK (VTK 9.1's NRRD reader misreads gzip
 * NRRD), VTI and PNG through VTK. Checks what the lenient readers let through:
 * more than one component (RGB/RGBA), NaN or non-integer values, labels beyond
 * 32 bits, non-positive or non-finite spacing, data shorter than the header says
 * (uncompressed files). Label values themselves (negative, all background) are
 * checked by vtkLabelOctreeMesher.
 */

#include "vtkSmartPointer.h"

#include <stdexcept>
#include <string>

class vtkImageData;

namespace labelmesher_cli
{

/// An input that cannot be meshed; the message is one line.
struct InputError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Throws InputError. The scalars are named "Labels".
vtkSmartPointer<vtkImageData> ReadLabelImage(const std::string& path);

} // namespace labelmesher_cli

#endif
