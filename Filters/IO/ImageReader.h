// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_ImageReader_h
#define labelmesher_io_ImageReader_h

/**
 * @file ImageReader.h
 * Reads a label image into vtkImageData, keeping origin, spacing and direction:
 * NRRD, NIfTI and MetaImage through ITK (VTK 9.1's NRRD reader misreads gzip
 * NRRD), VTI and PNG through VTK. Checks what the lenient readers let through:
 * more than one component (RGB/RGBA), NaN or non-integer values, labels beyond
 * 32 bits, non-positive or non-finite spacing, data shorter than the header says
 * (uncompressed files). Label values themselves (negative, all background) are
 * checked by vtkLabelOctreeMesher.
 *
 * ReadLabeledImage adds the materials' names and colours where the file has
 * them: a 3D Slicer segmentation (.seg.nrrd, SegmentationReader.h).
 */

#include "MaterialTable.h"

#include "vtkSmartPointer.h"

#include <stdexcept>
#include <string>
#include <vector>

class vtkImageData;

namespace labelmesher
{
namespace io
{

/// An input that cannot be meshed; the message is one line.
struct InputError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Throws InputError. The scalars are named "Labels".
vtkSmartPointer<vtkImageData> ReadLabelImage(const std::string& path);

/// True when `path` is read by extent (ReadLabelImageInformation, then ReadLabelImageExtent):
/// NRRD, NIfTI and MetaImage, not a 3D Slicer segmentation, a VTI or a PNG.
bool ReadsByExtent(const std::string& path);

/// What ReadLabelImage reads but the voxels: the image's extent, spacing, origin and direction,
/// and an empty label array of the type it would hold, every check of the header made (those of
/// the values come with them). Throws InputError (std::invalid_argument unless ReadsByExtent).
vtkSmartPointer<vtkImageData> ReadLabelImageInformation(const std::string& path);

/// The voxels of `extent` (VTK's order, within the image's extent) alone, as ReadLabelImage
/// gives them and with its checks. Raw MetaImage and NIfTI are read only there; NrrdIO reads the
/// whole file first (ITK cannot stream NRRD), and the voxels beyond the extent are released
/// before this returns. Throws InputError.
vtkSmartPointer<vtkImageData> ReadLabelImageExtent(const std::string& path, const int extent[6]);

/// A label image with what its file says about the labels.
struct LabeledImage
{
  vtkSmartPointer<vtkImageData> Image;       ///< scalars named "Labels", as ReadLabelImage gives
  MaterialTable Materials; ///< empty for plain images (the CLI adds --labels)
  std::vector<std::string> Notes;            ///< one-line remarks for the user (e.g. labels renumbered)
};

/// Reads `path`: a .seg.nrrd through ReadSegmentation, anything else through
/// ReadLabelImage (empty table, no notes). Throws InputError.
LabeledImage ReadLabeledImage(const std::string& path);

} // namespace io
} // namespace labelmesher

#endif
