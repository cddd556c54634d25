// SPDX-License-Identifier: GPL-2.0-or-later
// Sub-meshes of chosen materials, with the unused points dropped.
#include "Mesh/MeshSelection.h"

#include <algorithm>
#include <utility>

namespace labelmesher
{

SimplexMesh SelectMaterials(const SimplexMesh& mesh, bool includeBackground)
{
  SimplexMesh kept;
  kept.Dimension = mesh.Dimension;
  const int nv = mesh.VerticesPerCell();
  std::vector<std::int64_t> newId(mesh.Points.size(), -1);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    if (mesh.Materials[c] == 0 && !includeBackground)
    {
      continue;
    }
    const std::int64_t* cell = mesh.Cell(c);
    for (int v = 0; v < nv; ++v)
    {
      std::int64_t& id = newId[static_cast<std::size_t>(cell[v])];
      if (id < 0)
      {
        id = static_cast<std::int64_t>(kept.Points.size());
        kept.Points.push_back(mesh.Points[static_cast<std::size_t>(cell[v])]);
      }
      kept.Connectivity.push_back(id);
    }
    kept.Materials.push_back(mesh.Materials[c]);
  }
  return kept;
}

SimplexMesh SelectMaterials(SimplexMesh&& mesh, bool includeBackground)
{
  const bool keepsAll =
    includeBackground || std::find(mesh.Materials.begin(), mesh.Materials.end(), 0) == mesh.Materials.end();
  if (!keepsAll)
    return SelectMaterials(static_cast<const SimplexMesh&>(mesh), includeBackground);
  // Points are kept in first-use order, as the copy above numbers them, so that
  // both give the same mesh.
  const SimplexMesh& all = mesh;
  std::vector<std::int64_t> newId(all.Points.size(), -1);
  std::int64_t next = 0;
  bool inOrder = true;
  for (std::int64_t& id : mesh.Connectivity)
  {
    std::int64_t& renumbered = newId[static_cast<std::size_t>(id)];
    if (renumbered < 0)
      renumbered = next++;
    inOrder = inOrder && renumbered == id;
    id = renumbered;
  }
  if (!inOrder || static_cast<std::size_t>(next) != mesh.Points.size())
  {
    std::vector<Point3> points(static_cast<std::size_t>(next));
    for (std::size_t p = 0; p < newId.size(); ++p)
      if (newId[p] >= 0)
        points[static_cast<std::size_t>(newId[p])] = mesh.Points[p];
    mesh.Points = std::move(points);
  }
  return std::move(mesh);
}

} // namespace labelmesher
