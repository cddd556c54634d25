// SPDX-License-Identifier: GPL-2.0-or-later
// Gmsh MSH 4.1 and 2.2 ASCII writers (format: gmsh.info/doc/texinfo, "MSH file format").
#include "GmshWriter.h"

#include "ExportMesh.h"
#include "TextOut.h"

#include <algorithm>
#include <limits>

namespace labelmesher
{
namespace io
{
namespace
{

constexpr int GmshLine = 1, GmshTriangle = 2, GmshTetrahedron = 4, GmshQuadraticLine = 8, GmshQuadraticTriangle = 9,
              GmshQuadraticTetrahedron = 11, GmshCubicTriangle = 21;

int CellType(const ExportMesh& mesh)
{
  if (mesh.Order == 3)
    return GmshCubicTriangle; // 10 nodes in VTK's order
  if (mesh.Order == 2)
    return mesh.Dimension == 3 ? GmshQuadraticTetrahedron : GmshQuadraticTriangle; // a triangle's 6 in VTK's
  return mesh.Dimension == 3 ? GmshTetrahedron : GmshTriangle;
}

/// Gmsh's position k holds VTK's node order[k]: its 10-node tetrahedron has the mid-nodes of
/// edges 2-3 and 1-3 the other way round (VTK: 1-3, then 2-3). Null: the same order.
const int* NodeOrder(const ExportMesh& mesh)
{
  static constexpr int kTetra10[10] = { 0, 1, 2, 3, 4, 5, 6, 7, 9, 8 };
  return mesh.Order == 2 && mesh.Dimension == 3 ? kTetra10 : nullptr;
}
int FaceType(const ExportMesh& mesh)
{
  if (mesh.Order == 2) // 6 nodes in VTK's order; a segment's ends, then its mid-node
    return mesh.Dimension == 3 ? GmshQuadraticTriangle : GmshQuadraticLine;
  return mesh.Dimension == 3 ? GmshTriangle : GmshLine;
}

std::string QuotedName(std::string name)
{
  std::replace(name.begin(), name.end(), '"', '\'');
  return "\"" + name + "\"";
}

std::string InterfaceName(const ExportMesh& mesh, const ExportMesh::Pair& pair)
{
  return mesh.Table.NameOf(pair.first) + "|" + mesh.Table.NameOf(pair.second);
}

void WritePhysicalNames(const ExportMesh& mesh, TextOut& text)
{
  text.Text("$PhysicalNames\n").Int(static_cast<std::int64_t>(mesh.Materials.size() + mesh.Interfaces.size())).Char('\n');
  for (std::int32_t label : mesh.Materials)
  {
    text.Int(mesh.Dimension).Char(' ').Int(GmshPhysicalTag(mesh, label)).Char(' ')
      .Text(QuotedName(mesh.Table.NameOf(label))).Char('\n');
  }
  for (std::size_t i = 0; i < mesh.Interfaces.size(); ++i)
  {
    text.Int(mesh.Dimension - 1).Char(' ').Int(static_cast<std::int64_t>(i + 1)).Char(' ')
      .Text(QuotedName(InterfaceName(mesh, mesh.Interfaces[i]))).Char('\n');
  }
  text.Text("$EndPhysicalNames\n");
}

/// Bounding box of the points of `count` entries of `nodes` indices each.
void WriteBox(const ExportMesh& mesh, const std::vector<std::int64_t>& indices, ExportMesh::Group g, int nodes, TextOut& text)
{
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::max());
  hi.fill(std::numeric_limits<double>::lowest());
  for (std::size_t i = g.Begin * static_cast<std::size_t>(nodes); i < g.End * static_cast<std::size_t>(nodes); ++i)
  {
    const auto& p = mesh.Points[static_cast<std::size_t>(indices[i])];
    for (std::size_t a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  for (double v : lo)
  {
    text.Real(v).Char(' ');
  }
  for (double v : hi)
  {
    text.Real(v).Char(' ');
  }
}

void WriteElementLines(const std::vector<std::int64_t>& indices, ExportMesh::Group g, int nodes,
  std::int64_t& tag, const std::string& tagsBetween, TextOut& text, const int* order = nullptr)
{
  for (std::size_t e = g.Begin; e < g.End; ++e)
  {
    text.Int(tag++);
    if (!tagsBetween.empty())
    {
      text.Text(tagsBetween);
    }
    for (int k = 0; k < nodes; ++k)
    {
      const int node = order ? order[k] : k;
      text.Char(' ').Int(indices[e * static_cast<std::size_t>(nodes) + static_cast<std::size_t>(node)] + 1);
    }
    text.Char('\n');
  }
}

} // namespace

int GmshPhysicalTag(const ExportMesh& mesh, int label)
{
  return label > 0 ? label : mesh.LargestLabel() + 1;
}

void WriteGmsh41(const ExportMesh& mesh, std::ostream& out)
{
  TextOut text(out);
  text.Text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  WritePhysicalNames(mesh, text);

  const std::size_t nMaterials = mesh.Materials.size(), nInterfaces = mesh.Interfaces.size();
  // $Entities: points, curves, surfaces, volumes.
  std::array<std::size_t, 4> counts{ 0, 0, 0, 0 };
  counts[static_cast<std::size_t>(mesh.Dimension)] = nMaterials;
  counts[static_cast<std::size_t>(mesh.Dimension - 1)] = nInterfaces;
  text.Text("$Entities\n");
  for (int d = 0; d < 4; ++d)
  {
    text.Int(static_cast<std::int64_t>(counts[static_cast<std::size_t>(d)])).Char(d < 3 ? ' ' : '\n');
  }
  for (int d = 1; d <= 3; ++d)
  {
    const bool materials = d == mesh.Dimension;
    const std::size_t n = counts[static_cast<std::size_t>(d)];
    for (std::size_t i = 0; i < n; ++i)
    {
      text.Int(static_cast<std::int64_t>(i + 1)).Char(' ');
      if (materials)
      {
        WriteBox(mesh, mesh.Cells, mesh.MaterialCells[i], mesh.NodesPerCell(), text);
        text.Text("1 ").Int(GmshPhysicalTag(mesh, mesh.Materials[i]));
      }
      else
      {
        WriteBox(mesh, mesh.Faces, mesh.InterfaceFaces[i], mesh.NodesPerFace(), text);
        text.Text("1 ").Int(static_cast<std::int64_t>(i + 1));
      }
      text.Text(" 0\n"); // no bounding entities: the mesh is not a CAD model
    }
  }
  text.Text("$EndEntities\n");

  const auto nPoints = static_cast<std::int64_t>(mesh.Points.size());
  text.Text("$Nodes\n1 ").Int(nPoints).Text(" 1 ").Int(nPoints).Char('\n');
  text.Int(mesh.Dimension).Text(" 1 0 ").Int(nPoints).Char('\n');
  for (std::int64_t p = 1; p <= nPoints; ++p)
  {
    text.Int(p).Char('\n');
  }
  for (const auto& p : mesh.Points)
  {
    text.Real(p[0]).Char(' ').Real(p[1]).Char(' ').Real(p[2]).Char('\n');
  }
  text.Text("$EndNodes\n");

  const auto nElements = static_cast<std::int64_t>(mesh.NumberOfCells() + mesh.NumberOfFaces());
  text.Text("$Elements\n").Int(static_cast<std::int64_t>(nMaterials + nInterfaces)).Char(' ').Int(nElements)
    .Text(" 1 ").Int(nElements).Char('\n');
  std::int64_t tag = 1;
  for (std::size_t i = 0; i < nMaterials; ++i)
  {
    const auto g = mesh.MaterialCells[i];
    text.Int(mesh.Dimension).Char(' ').Int(static_cast<std::int64_t>(i + 1)).Char(' ').Int(CellType(mesh)).Char(' ')
      .Int(static_cast<std::int64_t>(g.End - g.Begin)).Char('\n');
    WriteElementLines(mesh.Cells, g, mesh.NodesPerCell(), tag, "", text, NodeOrder(mesh));
  }
  for (std::size_t i = 0; i < nInterfaces; ++i)
  {
    const auto g = mesh.InterfaceFaces[i];
    text.Int(mesh.Dimension - 1).Char(' ').Int(static_cast<std::int64_t>(i + 1)).Char(' ').Int(FaceType(mesh)).Char(' ')
      .Int(static_cast<std::int64_t>(g.End - g.Begin)).Char('\n');
    WriteElementLines(mesh.Faces, g, mesh.NodesPerFace(), tag, "", text);
  }
  text.Text("$EndElements\n");
}

void WriteGmsh22(const ExportMesh& mesh, std::ostream& out)
{
  TextOut text(out);
  text.Text("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
  WritePhysicalNames(mesh, text);
  text.Text("$Nodes\n").Int(static_cast<std::int64_t>(mesh.Points.size())).Char('\n');
  std::int64_t id = 1;
  for (const auto& p : mesh.Points)
  {
    text.Int(id++).Char(' ').Real(p[0]).Char(' ').Real(p[1]).Char(' ').Real(p[2]).Char('\n');
  }
  text.Text("$EndNodes\n");
  text.Text("$Elements\n").Int(static_cast<std::int64_t>(mesh.NumberOfCells() + mesh.NumberOfFaces())).Char('\n');
  std::int64_t tag = 1;
  // Element line: id type ntags physical elementary nodes...
  for (std::size_t i = 0; i < mesh.Materials.size(); ++i)
  {
    const std::string tags = " " + std::to_string(CellType(mesh)) + " 2 " +
      std::to_string(GmshPhysicalTag(mesh, mesh.Materials[i])) + " " + std::to_string(i + 1);
    WriteElementLines(mesh.Cells, mesh.MaterialCells[i], mesh.NodesPerCell(), tag, tags, text, NodeOrder(mesh));
  }
  for (std::size_t i = 0; i < mesh.Interfaces.size(); ++i)
  {
    const std::string tags = " " + std::to_string(FaceType(mesh)) + " 2 " + std::to_string(i + 1) + " " +
      std::to_string(i + 1);
    WriteElementLines(mesh.Faces, mesh.InterfaceFaces[i], mesh.NodesPerFace(), tag, tags, text);
  }
  text.Text("$EndElements\n");
}

} // namespace io
} // namespace labelmesher
