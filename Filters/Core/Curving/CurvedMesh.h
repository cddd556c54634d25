// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CurvedMesh_h
#define labelmesher_CurvedMesh_h

/**
 * @file CurvedMesh.h
 * A mesh of cubic Bézier triangles with shared control points: a mesh vertex
 * is one control point, each mesh edge owns two (shared by the cells on both
 * sides), each cell one interior point. Cells list their ten control point ids
 * in VTK_BEZIER_TRIANGLE order (see CubicTriangle.h).
 */

#include "Curving/CubicTriangle.h"
#include "Mesh/SimplexMesh.h"

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace labelmesher
{

struct CurvedMesh
{
  std::vector<Point2> ControlPoints;
  std::vector<std::array<std::int64_t, 10>> Cells;
  std::vector<std::int32_t> Materials;
  /// Number of leading control points that are mesh vertices (ids equal the linear mesh's point ids).
  std::int64_t NumberOfVertices = 0;
  /// For every mesh edge (a < b): its two control point ids, the first nearer a.
  std::map<std::pair<std::int64_t, std::int64_t>, std::array<std::int64_t, 2>> EdgeControlPoints;

  CubicTriangle Cell(std::size_t c) const;
  /// The two control points of edge a→b, ordered from a to b.
  std::array<std::int64_t, 2> EdgePoints(std::int64_t a, std::int64_t b) const;
};

/// The straight-sided cubic mesh of a 2D triangle mesh (x, y of its points; cells counter-clockwise).
CurvedMesh MakeStraightCurvedMesh(const SimplexMesh& mesh);

} // namespace labelmesher

#endif
