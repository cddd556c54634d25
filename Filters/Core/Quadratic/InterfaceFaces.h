// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_InterfaceFaces_h
#define labelmesher_InterfaceFaces_h

/**
 * @file InterfaceFaces.h
 * The faces of a tetrahedral mesh that bound a material: between cells of two
 * materials, or of one cell (on the image's box), with the edges they use,
 * and which edges may be curved: those inside one smooth interface sheet.
 */

#include "Quadratic/QuadraticMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

struct MaterialFace
{
  std::array<std::int64_t, 3> Points; ///< (b − a) × (c − a) points from Below's cell to Above's
  std::array<std::int64_t, 3> Edges;  ///< edge ids of b-c, c-a, a-b (opposite each corner)
  std::int32_t Below = 0, Above = 0;  ///< materials on the two sides, Below < Above
  bool OnBox = false;                 ///< one cell (Below is its material, Above meaningless)
};

/// Every face bounding a material, in a fixed order (by their sorted corner ids).
/// The mesh must fill its bounding box (background cells included): throws
/// std::invalid_argument when its faces of one cell do not cover the box.
std::vector<MaterialFace> FindInterfaceFaces(const QuadraticMesh& mesh);

/// Per edge: true when the edge may be curved: it lies on exactly two
/// interface faces, both between the same two materials, on no face of the
/// box and not along the box (its ends on one box side, `box` the image's
/// extent [lo, hi] per axis), and the two faces' normals differ by less than
/// 90 degrees. Junction curves (three materials or more), box edges and folds
/// stay straight.
std::vector<char> CurvableEdges(const QuadraticMesh& mesh, const std::vector<MaterialFace>& faces,
  const std::array<double, 6>& box);

/// Unit normal of a face, from Below to Above.
Point3 FaceNormal(const QuadraticMesh& mesh, const MaterialFace& face);

} // namespace labelmesher

#endif
