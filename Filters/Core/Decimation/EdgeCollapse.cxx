// SPDX-License-Identifier: GPL-2.0-or-later
#include "Decimation/EdgeCollapse.h"

#include <algorithm>

namespace labelmesher
{

bool EdgeCollapse::CollectFaces(const EditableMesh& mesh, const std::vector<const std::array<VertexId, 4>*>& cells,
  const std::vector<std::int32_t>& labels, VertexId touchA, VertexId touchB, std::vector<InterfaceFace>& out)
{
  // Every face of these cells that touches touchA or touchB has its other
  // cell among them too (that cell shares the vertex), or none: then it lies
  // on the box. Sorting the uses pairs the two sides of each face.
  const int d = mesh.Dimension;
  Uses.clear();
  for (std::size_t c = 0; c < cells.size(); ++c)
  {
    const auto& cell = *cells[c];
    for (int skip = 0; skip <= d; ++skip)
    {
      FaceUse use{ { -1, -1, -1 }, labels[c] };
      int n = 0;
      bool touches = false;
      for (int i = 0; i <= d; ++i)
        if (i != skip)
        {
          use.Vertices[n++] = cell[i];
          touches = touches || cell[i] == touchA || cell[i] == touchB;
        }
      if (!touches)
        continue;
      std::sort(use.Vertices.begin(), use.Vertices.begin() + n);
      Uses.push_back(use);
    }
  }
  std::sort(Uses.begin(), Uses.end());
  out.clear();
  for (std::size_t u = 0; u < Uses.size();)
  {
    std::size_t w = u + 1;
    while (w < Uses.size() && Uses[w].Vertices == Uses[u].Vertices)
      ++w;
    if (w - u > 2)
      return false;
    std::int32_t other;
    if (w - u == 2)
      other = Uses[u + 1].Label;
    else
    {
      const int plane = mesh.OutsidePlane(Uses[u].Vertices);
      if (plane < 0)
        return false;
      other = EditableMesh::OutsideLabel(plane);
    }
    if (other != Uses[u].Label)
      out.push_back(InterfaceFace{ Uses[u].Vertices, std::min(other, Uses[u].Label), std::max(other, Uses[u].Label) });
    u = w;
  }
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
