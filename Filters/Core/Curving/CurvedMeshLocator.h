// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CurvedMeshLocator_h
#define labelmesher_CurvedMeshLocator_h

/**
 * @file CurvedMeshLocator.h
 * Which cell of a curved mesh contains a point, and the accuracy measure of
 * dissertation section 5.2.3 (Table 8): the pixels whose label differs from the
 * material of the mesh at their centre.
 *
 * A cubic Bézier triangle lies in the convex hull of its control points, so
 * cells are binned by their control-point boxes on a uniform grid; the point is
 * then mapped back to barycentric coordinates by Newton's method, which is
 * well posed on valid cells (det J > 0).
 */

#include "Curving/CurvedMesh.h"
#include "Support/LabelImage.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace labelmesher
{

class CurvedMeshLocator
{
public:
  explicit CurvedMeshLocator(const CurvedMesh& mesh);

  /// A cell containing p (to within 1e-9 in barycentric coordinates), or -1.
  std::int64_t FindCell(const Point2& p) const;
  /// The material at p: that of the containing cell, 0 outside the mesh.
  std::int32_t MaterialAt(const Point2& p) const;

private:
  const CurvedMesh& Mesh;
  std::array<double, 2> Origin{ 0.0, 0.0 };
  double BinSize = 1.0;
  std::array<int, 2> Bins{ 1, 1 };
  std::vector<std::size_t> BinStart;
  std::vector<std::int64_t> BinCells;
};

struct PixelAccuracy
{
  std::size_t Pixels = 0;
  /// Pixels whose label differs from the mesh material at their centre.
  std::size_t Misclassified = 0;
  /// Per label: its pixels that the mesh gives another material ("tissue outside").
  std::map<std::int32_t, std::size_t> Missed;
  /// Per material: pixels the mesh gives it that carry another label ("background inside").
  std::map<std::int32_t, std::size_t> Claimed;
};

/// Compares a 2D label image with the mesh. `indexToMesh` maps pixel (i, j) to
/// mesh coordinates: x = m[0] + m[1] i + m[2] j, y = m[3] + m[4] i + m[5] j.
/// Mesh cells of material 0 count as outside.
PixelAccuracy MeasurePixelAccuracy(
  const CurvedMesh& mesh, const LabelImage& image, const std::array<double, 6>& indexToMesh);

} // namespace labelmesher

#endif
