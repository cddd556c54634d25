// SPDX-License-Identifier: GPL-2.0-or-later
// STL and OBJ writers of the interface surface. VTK's own writers open files by name only and
// write a single surface, so they can neither split by interface nor report a failed write to the
// end; these write to the checked stream of SafeFile.
#include "SurfaceWriters.h"

#include "ExportMesh.h"
#include "TextOut.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <cstdint>
#include <cstring>

namespace labelmesher
{
namespace io
{
namespace
{

void PutFloat(std::ostream& out, double v)
{
  const float f = static_cast<float>(v);
  char bytes[4];
  std::memcpy(bytes, &f, 4); // STL is little-endian, as is every platform we build on
  out.write(bytes, 4);
}

} // namespace

void WriteStl(const ExportMesh& mesh, std::ostream& out, long interface)
{
  char header[80] = {};
  std::strncpy(header, "LabelMesher interface surface", sizeof header - 1);
  out.write(header, 80);
  std::size_t first = 0, last = mesh.Interfaces.size();
  if (interface >= 0)
  {
    first = static_cast<std::size_t>(interface);
    last = first + 1;
  }
  std::uint32_t count = 0;
  for (std::size_t i = first; i < last; ++i)
  {
    count += static_cast<std::uint32_t>(mesh.InterfaceFaces[i].End - mesh.InterfaceFaces[i].Begin);
  }
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (std::size_t i = first; i < last; ++i)
  {
    const auto attribute = static_cast<std::uint16_t>(std::min<std::size_t>(i + 1, 65535));
    for (std::size_t f = mesh.InterfaceFaces[i].Begin; f < mesh.InterfaceFaces[i].End; ++f)
    {
      const auto& a = mesh.Points[static_cast<std::size_t>(mesh.Faces[3 * f])];
      const auto& b = mesh.Points[static_cast<std::size_t>(mesh.Faces[3 * f + 1])];
      const auto& c = mesh.Points[static_cast<std::size_t>(mesh.Faces[3 * f + 2])];
      double n[3] = { (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
        (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) };
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (double v : n)
      {
        PutFloat(out, length > 0 ? v / length : 0.0);
      }
      for (const auto* p : { &a, &b, &c })
      {
        for (double v : *p)
        {
          PutFloat(out, v);
        }
      }
      out.write(reinterpret_cast<const char*>(&attribute), 2);
    }
  }
}

void WriteObj(const ExportMesh& mesh, std::ostream& out)
{
  TextOut text(out);
  text.Text("# LabelMesher interface surface: one group per pair of materials\n");
  for (const auto& p : mesh.Points)
  {
    text.Text("v ").Real(p[0]).Char(' ').Real(p[1]).Char(' ').Real(p[2]).Char('\n');
  }
  const auto nodes = static_cast<std::size_t>(mesh.NodesPerFace());
  for (std::size_t i = 0; i < mesh.Interfaces.size(); ++i)
  {
    // OBJ separates group names by white space: keep each name one word.
    std::string group = mesh.Table.NameOf(mesh.Interfaces[i].first) + "|" + mesh.Table.NameOf(mesh.Interfaces[i].second);
    std::replace_if(group.begin(), group.end(), [](unsigned char c) { return std::isspace(c); }, '_');
    text.Text("g ").Text(group).Char('\n');
    for (std::size_t f = mesh.InterfaceFaces[i].Begin; f < mesh.InterfaceFaces[i].End; ++f)
    {
      text.Text(nodes == 3 ? "f" : "l");
      for (std::size_t k = 0; k < nodes; ++k)
      {
        text.Char(' ').Int(mesh.Faces[f * nodes + k] + 1);
      }
      text.Char('\n');
    }
  }
}

} // namespace io
} // namespace labelmesher
