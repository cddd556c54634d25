// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ImageOnMesh_h
#define labelmesher_ImageOnMesh_h

/**
 * @file ImageOnMesh.h
 * A 2D label image placed in the plane of a mesh: the affine map from pixel
 * indices to mesh coordinates and back. The curver fits and measures its
 * curves against the image in index space, where distance bounds are in
 * voxels (MeshChecks.h), while the mesh keeps its own coordinates; Bézier
 * curves are affine invariant, so control points map exactly.
 */

#include "Curving/CubicTriangle.h"
#include "Support/LabelImage.h"

#include <array>
#include <stdexcept>

namespace labelmesher
{

struct ImageOnMesh
{
  const LabelImage* Image = nullptr;
  /// Pixel (i, j) → x = m[0] + m[1] i + m[2] j, y = m[3] + m[4] i + m[5] j.
  std::array<double, 6> IndexToMesh{ 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 };

  Point2 ToMesh(const Point2& index) const
  {
    const auto& m = IndexToMesh;
    return { m[0] + m[1] * index[0] + m[2] * index[1], m[3] + m[4] * index[0] + m[5] * index[1] };
  }
  Point2 ToIndex(const Point2& p) const
  {
    const auto& m = IndexToMesh;
    const double det = m[1] * m[5] - m[2] * m[4];
    if (det == 0.0)
      throw std::invalid_argument("the image's pixel-to-mesh map is singular");
    const double x = p[0] - m[0], y = p[1] - m[3];
    return { (m[5] * x - m[2] * y) / det, (m[1] * y - m[4] * x) / det };
  }
};

} // namespace labelmesher

#endif
