// SPDX-License-Identifier: GPL-2.0-or-later
// Medit .mesh writer (format: the libMeshb specification, ASCII keywords).
#include "MeditWriter.h"

#include "ExportMesh.h"
#include "SafeFile.h"
#include "TextOut.h"

#include <algorithm>
#include <array>
#include <limits>

namespace labelmesher
{
namespace io
{

std::int64_t MeditInterfaceReference(const ExportMesh& mesh, std::size_t index)
{
  const std::int64_t base = static_cast<std::int64_t>(mesh.LargestLabel()) + 1;
  const auto& pair = mesh.Interfaces[index];
  const std::int64_t coded = pair.first * base + pair.second;
  if (base * base <= std::numeric_limits<std::int32_t>::max())
  {
    return coded;
  }
  return static_cast<std::int64_t>(index) + 1;
}

void WriteMedit(const ExportMesh& mesh, std::ostream& out)
{
  if (mesh.Order == 3)
    throw WriteError("Medit .mesh has no cubic triangle: write the curved mesh as .msh, .vtu or .vtk");
  TextOut text(out);
  const bool planar = mesh.Dimension == 2 && mesh.FlatAxis >= 0;
  const std::vector<std::size_t> axes = WrittenAxes(mesh);
  text.Text("MeshVersionFormatted 2\n");
  text.Text("# LabelMesher mesh; element references are image labels:\n");
  for (std::int32_t label : mesh.Materials)
  {
    text.Text("#   ").Int(label).Text(" = ").Text(mesh.Table.NameOf(label)).Char('\n');
  }
  text.Text("# interface references:\n");
  for (std::size_t i = 0; i < mesh.Interfaces.size(); ++i)
  {
    text.Text("#   ").Int(MeditInterfaceReference(mesh, i)).Text(" = ").Text(mesh.Table.NameOf(mesh.Interfaces[i].first))
      .Text(" | ").Text(mesh.Table.NameOf(mesh.Interfaces[i].second)).Char('\n');
  }
  text.Text("Dimension ").Int(planar ? 2 : 3).Char('\n');
  text.Text("Vertices\n").Int(static_cast<std::int64_t>(mesh.Points.size())).Char('\n');
  for (const auto& p : mesh.Points)
  {
    for (std::size_t a : axes)
    {
      text.Real(p[a]).Char(' ');
    }
    text.Text("0\n");
  }

  const auto nodes = static_cast<std::size_t>(mesh.NodesPerCell());
  // Quadratic tetrahedra: TetrahedraP2, whose default node order (no TetrahedraP2Ordering
  // keyword) is VTK's: corners, then the mid-nodes of edges 01, 12, 20, 03, 13, 23 (libMeshb's
  // example test_libmeshb_HO.c, Gmsh's MElement::writeMESH and its reader, which swap its own
  // last two edges to it; CLI.export_quadratic reads our file back through Gmsh).
  const char* keyword = mesh.Dimension == 3 ? (mesh.Order == 2 ? "TetrahedraP2\n" : "Tetrahedra\n")
                                            : (mesh.Order == 2 ? "TrianglesP2\n" : "Triangles\n");
  text.Text(keyword).Int(static_cast<std::int64_t>(mesh.NumberOfCells())).Char('\n');
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    std::array<std::int64_t, 10> cell{};
    std::copy_n(mesh.Cells.begin() + static_cast<std::ptrdiff_t>(c * nodes), nodes, cell.begin());
    if (planar && PlanarArea(mesh, cell.data()) < 0.0)
    {
      FlipTriangle(mesh, cell.data());
    }
    for (std::size_t k = 0; k < nodes; ++k)
    {
      text.Int(cell[k] + 1).Char(' ');
    }
    text.Int(mesh.CellMaterial[c]).Char('\n');
  }

  const auto faceNodes = static_cast<std::size_t>(mesh.NodesPerFace());
  if (mesh.NumberOfFaces() > 0)
  {
    // TrianglesP2: corners, then the mid-nodes of edges 12, 23, 31 (VTK's order, as Gmsh reads it);
    // EdgesP2: ends, then the mid-node.
    const char* faces = mesh.Dimension == 3 ? (mesh.Order == 2 ? "TrianglesP2\n" : "Triangles\n")
                                            : (mesh.Order == 2 ? "EdgesP2\n" : "Edges\n");
    text.Text(faces).Int(static_cast<std::int64_t>(mesh.NumberOfFaces())).Char('\n');
    for (std::size_t i = 0; i < mesh.Interfaces.size(); ++i)
    {
      const std::int64_t reference = MeditInterfaceReference(mesh, i);
      for (std::size_t f = mesh.InterfaceFaces[i].Begin; f < mesh.InterfaceFaces[i].End; ++f)
      {
        for (std::size_t k = 0; k < faceNodes; ++k)
        {
          text.Int(mesh.Faces[f * faceNodes + k] + 1).Char(' ');
        }
        text.Int(reference).Char('\n');
      }
    }
  }
  text.Text("End\n");
}

} // namespace io
} // namespace labelmesher
