// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_SegmentationReader_h
#define labelmesher_io_SegmentationReader_h

/**
 * @file SegmentationReader.h
 * Reads a 3D Slicer segmentation (.seg.nrrd) into one label image with the
 * segments' names and colours. The file is a NRRD whose header carries
 * `Segment<i>_Name`, `_Color`, `_LabelValue`, `_Layer`, ... per segment; it
 * is 3D when no segments overlap, else 4D with one 3D volume (layer) per entry
 * of its first, `list` axis. Layers are merged into one image; segments that
 * overlap are an error, since a mesh has one material per voxel. Label values
 * are kept when they tell the segments apart, else the segments are
 * renumbered 1..N in file order (a Note says so).
 */

#include "ImageReader.h"

#include <string>

namespace labelmesher
{
namespace io
{

/// True when the name ends in `.seg.nrrd` (any case).
bool IsSegmentationFile(const std::string& path);

/// Throws InputError. The scalars are a vtkIntArray named "Labels".
LabeledImage ReadSegmentation(const std::string& path);

} // namespace io
} // namespace labelmesher

#endif
