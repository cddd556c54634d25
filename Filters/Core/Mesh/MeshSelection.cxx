// SPDX-License-Identifier: GPL-2.0-or-later
// Sub-meshes of chosen materials, with the unused points dropped.
#include "Mesh/MeshSelection.h"

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

} // namespace labelmesher
