// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_SimplexMesh_h
#define labelmesher_SimplexMesh_h

/**
 * @file SimplexMesh.h
 * The mesh store shared by the mesher, the decimator and the checks: points in
 * the label image's index space (see LabelImage.h) and simplices (triangles in
 * 2D with z = 0, tetrahedra in 3D), each carrying the image label of the
 * material it belongs to. Tetrahedra are positively oriented
 * (det[b-a, c-a, d-a] > 0); triangles are counter-clockwise.
 */

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

using Point3 = std::array<double, 3>;

struct SimplexMesh
{
  int Dimension = 3;                     ///< 2: triangles, 3: tetrahedra
  std::vector<Point3> Points;            ///< index-space coordinates
  std::vector<std::int64_t> Connectivity; ///< Dimension + 1 point ids per cell
  std::vector<std::int32_t> Materials;   ///< image label of every cell

  int VerticesPerCell() const { return Dimension + 1; }
  std::size_t NumberOfCells() const { return Materials.size(); }
  const std::int64_t* Cell(std::size_t c) const { return Connectivity.data() + c * VerticesPerCell(); }
};

} // namespace labelmesher

#endif
