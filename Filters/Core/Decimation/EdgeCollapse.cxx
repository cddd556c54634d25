// SPDX-License-Identifier: GPL-2.0-or-later
// Plans and applies one vertex merge of section 3.1.3: the cells that change, vanish and stay.
#include "Decimation/EdgeCollapse.h"

#include "Mesh/CellFacets.h"

#include <algorithm>

namespace labelmesher
{

bool EdgeCollapse::CollectFaces(const EditableMesh& mesh, const std::vector<const std::array<VertexId, 4>*>& cells,
  const std::vector<std::int32_t>& labels, VertexId touchA, VertexId touchB, std::vector<InterfaceFace>& out)
{
  // Every face of these cells that touches touchA or touchB has its other
  // cell among them too (that cell shares the vertex), or none: then it lies
  // on the box. A small open-addressing table pairs the two sides of each face
  // (a generation per slot saves clearing it).
  const int d = mesh.Dimension;
  std::size_t size = 64;
  while (size < 4 * (d + 1) * cells.size())
    size *= 2;
  if (Table.size() < size)
  {
    Table.assign(size, FaceSlot{});
    Generation = 0;
  }
  if (++Generation == 0)
  {
    std::fill(Table.begin(), Table.end(), FaceSlot{});
    Generation = 1;
  }
  const std::size_t mask = size - 1;
  Used.clear();
  for (std::size_t c = 0; c < cells.size(); ++c)
  {
    const auto& cell = *cells[c];
    for (int opposite = 0; opposite <= d; ++opposite)
    {
      // The facet touches touchA or touchB unless its opposite vertex is the only one that does.
      bool touches = false;
      for (int i = 0; i <= d; ++i)
        touches = touches || (i != opposite && (cell[i] == touchA || cell[i] == touchB));
      if (!touches)
        continue;
      const std::array<VertexId, 3> face = SortedFacetOpposite(cell.data(), d, opposite);
      std::size_t h = (static_cast<std::size_t>(face[0]) * 73856093u) ^ (static_cast<std::size_t>(face[1]) * 19349663u) ^
        (static_cast<std::size_t>(face[2] + 1) * 83492791u);
      for (h &= mask;; h = (h + 1) & mask)
      {
        FaceSlot& slot = Table[h];
        if (slot.Generation != Generation)
        {
          slot = FaceSlot{ face, labels[c], 0, 1, Generation };
          Used.push_back(static_cast<std::uint32_t>(h));
          break;
        }
        if (slot.Vertices == face)
        {
          if (++slot.Count > 2)
            return false;
          slot.Other = labels[c];
          break;
        }
      }
    }
  }
  out.clear();
  for (std::uint32_t h : Used)
  {
    const FaceSlot& slot = Table[h];
    std::int32_t other = slot.Other;
    if (slot.Count == 1)
    {
      const int plane = mesh.OutsidePlane(slot.Vertices);
      if (plane < 0)
        return false;
      other = EditableMesh::OutsideLabel(plane);
    }
    if (other != slot.Label)
      out.push_back(InterfaceFace{ slot.Vertices, std::min(other, slot.Label), std::max(other, slot.Label) });
  }
  std::sort(out.begin(), out.end());
  return true;
}

bool EdgeCollapse::Plan(const EditableMesh& mesh, VertexId from, VertexId to)
{
  From = from;
  To = to;
  Removed.clear();
  Moved.clear();
  MovedCells.clear();
  for (CellId c : mesh.CellsOf[from])
  {
    if (mesh.Contains(c, to))
      Removed.push_back(c);
    else
    {
      Moved.push_back(c);
      auto cell = mesh.Cells[c];
      for (auto& v : cell)
        if (v == from)
          v = to;
      MovedCells.push_back(cell);
    }
  }
  if (Removed.empty())
    return false; // not neighbours
  return true;
}

bool EdgeCollapse::PlanInterfaces(const EditableMesh& mesh)
{
  const VertexId from = From, to = To;
  Kept.clear();
  for (CellId c : mesh.CellsOf[to])
    if (!mesh.Contains(c, from))
      Kept.push_back(c);

  // Before: the cells around either vertex.
  CellScratch.clear();
  LabelScratch.clear();
  for (const auto* list : { &Removed, &Moved, &Kept })
    for (CellId c : *list)
    {
      CellScratch.push_back(&mesh.Cells[c]);
      LabelScratch.push_back(mesh.Labels[c]);
    }
  if (!CollectFaces(mesh, CellScratch, LabelScratch, from, to, Before))
    return false;

  // After: the cells around To.
  CellScratch.clear();
  LabelScratch.clear();
  for (CellId c : Kept)
  {
    CellScratch.push_back(&mesh.Cells[c]);
    LabelScratch.push_back(mesh.Labels[c]);
  }
  for (std::size_t m = 0; m < Moved.size(); ++m)
  {
    CellScratch.push_back(&MovedCells[m]);
    LabelScratch.push_back(mesh.Labels[Moved[m]]);
  }
  return CollectFaces(mesh, CellScratch, LabelScratch, to, to, After);
}

void EdgeCollapse::Apply(EditableMesh& mesh) const
{
  for (CellId c : Removed)
  {
    mesh.CellAlive[c] = 0;
    for (int i = 0; i < mesh.VerticesPerCell(); ++i)
    {
      const VertexId v = mesh.Cells[c][i];
      if (v == From)
        continue;
      auto& list = mesh.CellsOf[v];
      list.erase(std::find(list.begin(), list.end(), c));
    }
  }
  auto& at = mesh.CellsOf[To];
  for (std::size_t m = 0; m < Moved.size(); ++m)
  {
    mesh.Cells[Moved[m]] = MovedCells[m];
    at.push_back(Moved[m]);
  }
  mesh.CellsOf[From].clear();
  mesh.CellsOf[From].shrink_to_fit();
}

} // namespace labelmesher
