// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_LabelImageFile_h
#define labelmesher_testing_LabelImageFile_h

/**
 * @file LabelImageFile.h
 * Test- and benchmark-side input: reads a label image (NRRD, NIfTI, MetaImage, VTI, PNG) with
 * LabelMesher::IO's checked reader (Filters/IO/ImageReader.h, as every front end does) into the
 * core's index-space LabelImage. Spacing is reported but not applied: distances and h are in
 * voxel units, as the core sees them. Kept out of the core on purpose (the core has no I/O).
 */

#include "Support/LabelImage.h"

#include <array>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

struct LabelImageFile
{
  LabelImage Image;
  std::array<double, 3> Spacing{ 1, 1, 1 };
};

/// Throws std::runtime_error (one line) when the reader refuses the file or it has negative
/// labels. A 2D file is read as nz == 1.
LabelImageFile ReadLabelImageFile(const std::string& path);

/// The *.nrrd files of `directory`, sorted by name (empty if it does not exist).
std::vector<std::string> ListNrrdFiles(const std::string& directory);

} // namespace testing
} // namespace labelmesher

#endif
