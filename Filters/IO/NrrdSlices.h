// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_NrrdSlices_h
#define labelmesher_io_NrrdSlices_h

/**
 * @file NrrdSlices.h
 * The voxels of a box of a NRRD image, raw or gzip-compressed, read slice by slice along z with
 * one slice held at a time: what ITK's NrrdIO cannot do (it reads and inflates the whole file),
 * for a process that needs only its slab of a large image (vtkLabelImageReader's extents).
 * A gzip stream is inflated from its start, the slices before the box discarded as they come;
 * several gzip members follow one another; a read that reaches the last slice inflates to the
 * stream's end, testing its check sum. A 2D image is one slice: held whole while its rows are
 * read. Internal to ImageReader.cxx; throws InputError.
 */

#include "TextHeader.h"

#include <cstddef>
#include <string>

namespace labelmesher
{
namespace io
{
namespace detail
{

/// True when ReadNrrdBox reads the voxels `header` describes: NRRD, raw or gzip, in one file,
/// without a byte or line skip (the rest goes through ITK).
bool ReadsNrrdBySlices(const TextHeader& header);

/// Writes the voxels of `extent` (VTK's order: x fastest; within an image of `dims` voxels) into
/// `out`, each `voxelBytes` long and in this machine's byte order (`bigEndian`: the file's is
/// big-endian). `out` holds the box's voxels. Throws InputError for an extent beyond the image,
/// voxels that end early or a broken gzip stream.
void ReadNrrdBox(const std::string& path, const TextHeader& header, const int dims[3], std::size_t voxelBytes,
  bool bigEndian, const int extent[6], char* out);

} // namespace detail
} // namespace io
} // namespace labelmesher

#endif
