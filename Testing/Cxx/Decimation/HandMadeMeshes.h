// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_HandMadeMeshes_h
#define labelmesher_testing_HandMadeMeshes_h

/**
 * @file HandMadeMeshes.h
 * Small 2D meshes drawn by hand for the unit tests of the decimator's checks, where the right
 * answer for a merge is known: index-space points (on the half-voxel lattice), counter-clockwise
 * triangles, one label each.
 */

#include "Mesh/SimplexMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{
namespace testing
{

/// Triangles from points (x, y) and vertex triples, with their labels.
inline SimplexMesh Triangles2D(const std::vector<std::array<double, 2>>& points,
  const std::vector<std::array<std::int64_t, 3>>& cells, const std::vector<std::int32_t>& labels)
{
  SimplexMesh mesh;
  mesh.Dimension = 2;
  for (const auto& p : points)
    mesh.Points.push_back({ p[0], p[1], 0.0 });
  for (const auto& c : cells)
    mesh.Connectivity.insert(mesh.Connectivity.end(), c.begin(), c.end());
  mesh.Materials = labels;
  return mesh;
}

} // namespace testing
} // namespace labelmesher

#endif
