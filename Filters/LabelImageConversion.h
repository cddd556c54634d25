// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef LabelImageConversion_h
#define LabelImageConversion_h

/**
 * @file LabelImageConversion.h
 * Module-private plumbing shared by the filters that read label images: a
 * vtkImageData of integer labels becomes the core's LabelImage (index space),
 * validated, with the map back to physical space.
 *
 * A single-slice image (2D) is permuted into the x-y plane; anisotropic spacing
 * is resampled nearest-neighbour to the smallest (in-plane) spacing, keeping the
 * physical extent of the voxels, so that angles and distances measured in index
 * space hold in physical space.
 */

#include "Support/LabelImage.h"
#include "Mesh/SimplexMesh.h"

#include <string>

class vtkDataArray;
class vtkImageData;

namespace labelmesher
{

/// LabelImage axis a corresponds to image axis ImageAxis[a]; its index p maps to
/// the image's local (pre-direction) coordinate Start[a] + p * Step[a].
struct ImagePlacement
{
  int ImageAxis[3] = { 0, 1, 2 };
  double Start[3] = { 0, 0, 0 };
  double Step[3] = { 1, 1, 1 };
  double Origin[3] = { 0, 0, 0 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double VoxelSize = 1.0;

  /// physical = origin + direction * local(index)
  Point3 ToPhysical(const Point3& p) const;
  /// The inverse: index-space coordinates of a physical point (the third is
  /// 0 for a 2D image). False when the direction matrix is singular.
  bool ToIndex(const Point3& physical, Point3& index) const;

  /// True when the index -> physical map reverses orientation (tetrahedra must
  /// then swap two vertices to stay positively oriented).
  bool ReversesOrientation() const;
};

/// The voxel count of the image ConvertLabelImage builds from point dimensions `dims` and
/// `spacing`: resampled to cubes of the smallest spacing along the meshed axes (a single-slice
/// axis is not meshed).
double ResampledVoxels(const int dims[3], const double spacing[3]);

/// The most voxels the isotropic resampling of an anisotropic image may create (2^31 - 1: the
/// labels alone would take 8 GiB); beyond it ConvertLabelImage refuses the image.
inline constexpr double kMaximumResampledVoxels = 2147483647.0;

/// Validates `input` and its label array `scalars` (integer type, one component,
/// point data, labels in [0, 2^31), finite non-zero spacing, non-empty extent,
/// some foreground, a resampled size within kMaximumResampledVoxels) and converts it. Returns false with a one-sentence reason
/// in `error` (no trailing period) when the image cannot be meshed.
bool ConvertLabelImage(vtkImageData* input, vtkDataArray* scalars, LabelImage& image,
  ImagePlacement& placement, std::string& error);

/// True when ConvertLabelImage keeps an image of point dimensions `dims` and `spacing` as it is:
/// neither permuted (a single slice lies across z) nor resampled (the meshed axes' spacings are
/// equal in size). Its LabelImage's slices along the last axis are then the image's own, so a
/// process can read just the slab it needs (ConvertLabelSlab).
bool ConvertsAsIs(const int dims[3], const double spacing[3]);

/// The slices [first, end) along the last axis (z, or y for a single z slice) of an image whose
/// whole extent is `wholeExtent` and which ConvertsAsIs, from `piece`: an extent of the image
/// holding at least those slices, whole. A LabelImage slab, its labels checked as
/// ConvertLabelImage checks them (foreground is not required of a slab). False with a
/// one-sentence reason in `error`.
bool ConvertLabelSlab(vtkImageData* piece, vtkDataArray* scalars, const int wholeExtent[6], int first, int end,
  LabelImage& slab, std::string& error);

} // namespace labelmesher

#endif
