// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_SyntheticShapes_h
#define labelmesher_testing_SyntheticShapes_h

/**
 * @file SyntheticShapes.h
 * Analytic label images for tests and benchmarks. A voxel gets a shape's label
 * when its centre (i, j, k) (LabelImage.h convention) lies in the closed
 * shape. Shapes are centred in the image: the centre is ((nx-1)/2, (ny-1)/2,
 * (nz-1)/2) unless stated otherwise. All radii are in voxels.
 */

#include "Support/LabelImage.h"

#include <cstdint>
#include <vector>

namespace labelmesher
{
namespace testing
{

// ---- 2D (Dimensions[2] == 1) ------------------------------------------------

/// n x n image with a centred disc of `radius`.
LabelImage MakeDisc(int n, double radius, std::int32_t label = 1);

/// nx x ny image with a centred ellipse of semi-axes (rx, ry), rotated by
/// `angleDegrees` counter-clockwise.
LabelImage MakeEllipse(int nx, int ny, double rx, double ry, double angleDegrees = 0.0,
  std::int32_t label = 1);

/// nx x ny image with two equal discs of `radius` whose centres lie on the
/// horizontal mid-line, 2 * radius * overlap apart (overlap < 1 makes them
/// overlap): the left one gets `labelA`, the right one `labelB`, the lens they
/// share is split along the vertical mid-line, so the two materials touch along
/// a segment. Defaults: radius = ny / 4 - 1 (at least 2), overlap = 0.8.
LabelImage MakeTouchingBlobs2D(int nx, int ny, std::int32_t labelA = 1, std::int32_t labelB = 2,
  double radius = -1.0, double overlap = 0.8);

// ---- 3D ---------------------------------------------------------------------

/// n^3 image with a centred ball of `radius`.
LabelImage MakeSphere(int n, double radius, std::int32_t label = 1);

/// nx x ny x nz image with a centred axis-aligned ellipsoid of semi-axes (rx, ry, rz).
LabelImage MakeEllipsoid(int nx, int ny, int nz, double rx, double ry, double rz, std::int32_t label = 1);

/// n^3 image with a centred solid torus around the z axis: points whose
/// distance to the circle of radius `majorRadius` in the plane z = centre is
/// <= `minorRadius`. Genus 1: one tunnel.
LabelImage MakeTorus(int n, double majorRadius, double minorRadius, std::int32_t label = 1);

/// n^3 image with concentric balls: radii[0] is the outermost and gets
/// labels[0], each next one (smaller) overwrites with its own label. radii must
/// be decreasing and labels.size() == radii.size(). A 0 label makes a cavity.
LabelImage MakeNestedSpheres(int n, const std::vector<double>& radii, const std::vector<std::int32_t>& labels);

/**
 * The Cassini-oval volume: the synthetic benchmark of dissertation section
 * 5.1.1 ("Synthetic benchmark - three-dimensional Cassini surface", Fig. 23,
 * Table 2, Fig. 24), used there at 100..400 voxels a side with
 * h(I,M) = h(M,I) = 2.
 *
 * The dissertation gives no formula, no parameters and no label layout for it
 * (the figure is not reproduced in the text; it only says the data set is a
 * Cassini surface of a "diameter" of 100..400 voxels, whose materials touch
 * "face-to-face" at one place, which the ORD mesh must keep and LD breaks). So
 * this is our reconstruction from the standard definition, with parameters
 * chosen to exhibit that feature; record CassiniOptions with any figure.
 *
 * Definition: with foci F1,2 = centre -/+ (a, 0, 0), the closed solid
 *     |p - F1| * |p - F2| <= b^2
 * i.e. ((x^2 + y^2 + z^2 + a^2)^2 - 4 a^2 x^2 <= b^4 in centred coordinates:
 * the solid of revolution about the x axis of the Cassini oval with foci at
 * +-a and constant b^2. For b slightly above a it is one body with two lobes
 * joined by a thin neck of radius sqrt(b^2 - a^2) (b = a: the lemniscate, the
 * lobes meet in a point; b < a: two bodies). Its length along x is
 * 2 sqrt(a^2 + b^2), and `a` is chosen so that this length is n - 2 * Margin,
 * i.e. the "diameter" is the image side minus the margins.
 *
 * Labels: with SplitLobes the lobe with x < centre gets LabelA and the other
 * LabelB, so the two materials touch face-to-face across the neck (a disc of
 * radius sqrt(b^2 - a^2)); otherwise the whole solid is LabelA. The image is
 * n^3 voxels.
 */
struct CassiniOptions
{
  double ShapeRatio = 1.02; ///< b / a: > 1 joins the lobes by a neck of radius a*sqrt(ratio^2 - 1)
  double Margin = 4.0;      ///< background voxels between the solid's ends and the image border
  bool SplitLobes = true;   ///< two materials meeting at the neck, else one
  std::int32_t LabelA = 1;
  std::int32_t LabelB = 2;
};
LabelImage MakeCassiniVolume(int n, const CassiniOptions& options = {});

/// The focal half-distance a that MakeCassiniVolume uses for side n.
double CassiniFocalDistance(int n, const CassiniOptions& options = {});

} // namespace testing
} // namespace labelmesher

#endif
