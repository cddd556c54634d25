// SPDX-License-Identifier: GPL-2.0-or-later
// Abaqus .inp writer: nodes, one element set per material, one node set per interface.
#include "AbaqusWriter.h"

#include "ExportMesh.h"
#include "SafeFile.h"
#include "TextOut.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>

namespace labelmesher
{
namespace io
{
namespace
{

constexpr std::size_t MaximumNameLength = 80;

std::string Sanitize(const std::string& name)
{
  std::string s;
  for (unsigned char c : name)
  {
    s += std::isalnum(c) ? static_cast<char>(c) : '_';
  }
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0])))
  {
    s = "M_" + s;
  }
  return s.substr(0, MaximumNameLength);
}

std::string Upper(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

/// Sanitized names, unique case-insensitively: the first holder keeps the
/// plain name, a later one gets `_L<label>` (the label is unique).
std::vector<std::string> MaterialSetNames(const ExportMesh& mesh)
{
  std::vector<std::string> names;
  std::set<std::string> taken;
  for (std::int32_t label : mesh.Materials)
  {
    std::string name = Sanitize(mesh.Table.NameOf(label));
    if (!taken.insert(Upper(name)).second)
    {
      const std::string suffix = "_L" + std::to_string(label);
      name = name.substr(0, MaximumNameLength - suffix.size()) + suffix;
      taken.insert(Upper(name));
    }
    names.push_back(name);
  }
  return names;
}

const char* ElementType(const ExportMesh& mesh)
{
  if (mesh.Dimension == 3)
  {
    return mesh.Order == 2 ? "C3D10" : "C3D4"; // C3D10's node order is VTK's
  }
  if (mesh.Order == 2)
    return mesh.FlatAxis >= 0 ? "CPS6" : "STRI65"; // VTK's node order
  return mesh.FlatAxis >= 0 ? "CPS3" : "S3";
}

} // namespace

void WriteAbaqus(const ExportMesh& mesh, std::ostream& out)
{
  if (mesh.Order == 3)
    throw WriteError("Abaqus .inp has no cubic triangle: write the curved mesh as .msh, .vtu or .vtk");
  TextOut text(out);
  const std::vector<std::string> setNames = MaterialSetNames(mesh);
  text.Text("*HEADING\nLabelMesher mesh: ").Int(static_cast<std::int64_t>(mesh.Points.size())).Text(" nodes, ")
    .Int(static_cast<std::int64_t>(mesh.NumberOfCells())).Text(" elements, ")
    .Int(static_cast<std::int64_t>(mesh.Materials.size())).Text(" materials\n");
  for (std::size_t i = 0; i < mesh.Materials.size(); ++i)
  {
    text.Text("** material ").Text(setNames[i]).Text(": image label ").Int(mesh.Materials[i])
      .Text(", name ").Text(mesh.Table.NameOf(mesh.Materials[i])).Char('\n');
  }

  const std::vector<std::size_t> axes = WrittenAxes(mesh);
  text.Text("*NODE\n");
  std::int64_t id = 1;
  for (const auto& p : mesh.Points)
  {
    text.Int(id++);
    for (std::size_t a : axes)
    {
      text.Text(", ").Real(p[a]);
    }
    text.Char('\n');
  }

  std::int64_t element = 1;
  const auto nodes = static_cast<std::size_t>(mesh.NodesPerCell());
  for (std::size_t i = 0; i < mesh.Materials.size(); ++i)
  {
    text.Text("*ELEMENT, TYPE=").Text(ElementType(mesh)).Text(", ELSET=").Text(setNames[i]).Char('\n');
    const auto g = mesh.MaterialCells[i];
    for (std::size_t c = g.Begin; c < g.End; ++c)
    {
      std::array<std::int64_t, 10> cell{};
      std::copy_n(mesh.Cells.begin() + static_cast<std::ptrdiff_t>(c * nodes), nodes, cell.begin());
      if (mesh.Dimension == 2 && mesh.FlatAxis >= 0 && PlanarArea(mesh, cell.data()) < 0.0)
      {
        FlipTriangle(mesh, cell.data()); // CPS3 and CPS6 want counter-clockwise nodes
      }
      text.Int(element++);
      for (std::size_t k = 0; k < nodes; ++k)
      {
        text.Text(", ").Int(cell[k] + 1);
      }
      text.Char('\n');
    }
  }

  const auto faceNodes = static_cast<std::size_t>(mesh.NodesPerFace());
  std::set<std::string> nodeSets;
  for (std::size_t i = 0; i < mesh.Interfaces.size(); ++i)
  {
    const auto g = mesh.InterfaceFaces[i];
    std::vector<std::int64_t> ids(mesh.Faces.begin() + static_cast<std::ptrdiff_t>(g.Begin * faceNodes),
      mesh.Faces.begin() + static_cast<std::ptrdiff_t>(g.End * faceNodes));
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::string name = Sanitize(mesh.Table.NameOf(mesh.Interfaces[i].first) + "__" +
      mesh.Table.NameOf(mesh.Interfaces[i].second));
    if (!nodeSets.insert(Upper(name)).second)
    {
      const std::string suffix = "_I" + std::to_string(i + 1);
      name = name.substr(0, MaximumNameLength - suffix.size()) + suffix;
    }
    text.Text("*NSET, NSET=").Text(name).Char('\n');
    for (std::size_t k = 0; k < ids.size(); ++k)
    {
      text.Int(ids[k] + 1).Text(k + 1 == ids.size() || k % 16 == 15 ? "\n" : ", ");
    }
  }
}

} // namespace io
} // namespace labelmesher
