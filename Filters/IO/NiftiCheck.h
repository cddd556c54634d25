// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_NiftiCheck_h
#define labelmesher_io_NiftiCheck_h

/**
 * @file NiftiCheck.h
 * Checks a NIfTI header's geometry before ITK sees it: ITK 5.2 builds the
 * image's direction from the qform or sform through VNL, which aborts the
 * program on a non-finite matrix element (found by fuzzing the NIfTI reader).
 * The check reads the header (NIfTI-1 or NIfTI-2, either byte order, plain or
 * gzip-compressed) and requires finite voxel sizes and transform parameters
 * within +-1e9 for each transform the header says is in use (ITK's
 * single-precision SVD of the transform never ends on entries near FLT_MAX).
 */

#include <string>

namespace labelmesher
{
namespace io
{

/// Throws InputError naming `path` and the first non-finite field; a header it cannot recognise
/// is left to ITK, which refuses it with its own message.
void CheckNiftiGeometry(const std::string& path);

} // namespace io
} // namespace labelmesher

#endif
