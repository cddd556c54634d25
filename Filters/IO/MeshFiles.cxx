// SPDX-License-Identifier: GPL-2.0-or-later
// Format by extension and the dispatch of one run's outputs to the writers.
#include "MeshFiles.h"

#include "AbaqusWriter.h"
#include "GmshWriter.h"
#include "MeditWriter.h"
#include "PvtuWriter.h"
#include "SafeFile.h"
#include "SurfaceWriters.h"
#include "VtkFileWriters.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cctype>
#include <functional>

namespace labelmesher
{
namespace io
{
namespace
{

struct Extension
{
  const char* Suffix;
  MeshFormat Format;
};
constexpr Extension Extensions[] = { { ".vtu", MeshFormat::Vtu }, { ".pvtu", MeshFormat::Pvtu }, { ".vtk", MeshFormat::LegacyVtk },
  { ".msh", MeshFormat::Gmsh }, { ".inp", MeshFormat::Abaqus }, { ".mesh", MeshFormat::Medit },
  { ".vtp", MeshFormat::Vtp }, { ".stl", MeshFormat::Stl }, { ".obj", MeshFormat::Obj } };

std::string Lowered(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

void WriteWhole(const std::string& path, const std::function<void(std::ostream&)>& write)
{
  SafeFile file(path);
  try
  {
    write(file.Stream());
  }
  catch (const WriteError& e)
  {
    file.Fail(e.what());
  }
  file.Commit();
}

/// `base.stl` -> `base_NAME_A_NAME_B.stl`, names reduced to file-name-safe characters.
std::string InterfaceFileName(const std::string& path, const ExportMesh& mesh, std::size_t i)
{
  auto safe = [](std::string s) {
    for (char& c : s)
    {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.')
      {
        c = '_';
      }
    }
    return s;
  };
  const std::string stem = path.substr(0, path.size() - 4);
  return stem + "_" + safe(mesh.Table.NameOf(mesh.Interfaces[i].first)) + "_" +
    safe(mesh.Table.NameOf(mesh.Interfaces[i].second)) + path.substr(path.size() - 4);
}

} // namespace

std::optional<MeshFormat> FormatOfPath(const std::string& path)
{
  const std::string lower = Lowered(path);
  for (const Extension& e : Extensions)
  {
    const std::string suffix = e.Suffix;
    if (lower.size() > suffix.size() && lower.compare(lower.size() - suffix.size(), suffix.size(), suffix) == 0)
    {
      return e.Format;
    }
  }
  return std::nullopt;
}

std::string KnownExtensions()
{
  std::string list;
  for (const Extension& e : Extensions)
  {
    list += (list.empty() ? "" : ", ") + std::string(e.Suffix);
  }
  return list;
}

void CheckMeshOutputPath(const std::string& path)
{
  if (FormatOfPath(path) == MeshFormat::Pvtu)
  {
    CheckPvtuPath(path);
  }
  else
  {
    CheckOutputPath(path);
  }
}

bool HoldsCurvedCells(MeshFormat format)
{
  return format == MeshFormat::Vtu || format == MeshFormat::Pvtu || format == MeshFormat::LegacyVtk ||
    format == MeshFormat::Gmsh;
}

bool HoldsQuadraticCells(MeshFormat format)
{
  return HoldsCurvedCells(format) || format == MeshFormat::Abaqus || format == MeshFormat::Medit;
}

MeshFileWriter::MeshFileWriter(
  vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, const MaterialTable& table, const WriteOptions& options)
  : Table(table)
  , Options(options)
{
  // Every material of the mesh gets an entry, so the files name all of them.
  if (vtkDataArray* material = mesh->GetCellData()->GetArray("Material"))
  {
    for (vtkIdType c = 0; c < material->GetNumberOfTuples(); ++c)
    {
      const auto label = static_cast<std::int32_t>(material->GetComponent(c, 0));
      if (!this->Table.Find(label))
      {
        MaterialInfo info;
        info.Label = label;
        info.Name = this->Table.NameOf(label);
        this->Table.Set(info);
      }
    }
  }
  // The VTK files carry the table as field data; the filters' outputs stay untouched.
  this->Mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  this->Mesh->ShallowCopy(mesh);
  vtkNew<vtkFieldData> fd;
  fd->ShallowCopy(mesh->GetFieldData());
  StoreMaterialTable(fd, this->Table);
  this->Mesh->SetFieldData(fd);
  if (interfaces)
  {
    this->Interfaces = vtkSmartPointer<vtkPolyData>::New();
    this->Interfaces->ShallowCopy(interfaces);
    vtkNew<vtkFieldData> surfaceFd;
    StoreMaterialTable(surfaceFd, this->Table);
    this->Interfaces->SetFieldData(surfaceFd);
  }
}

const ExportMesh& MeshFileWriter::Flat()
{
  if (!this->Flattened)
  {
    this->Flattened = MakeExportMesh(this->Mesh, this->Interfaces, this->Table);
  }
  return *this->Flattened;
}

namespace
{
/// The surface formats hold straight triangles and segments: a curved mesh's interfaces (their
/// mid-nodes, control points) would be written as other faces.
void RefuseCurved(const ExportMesh& mesh, const std::string& path)
{
  if (mesh.Order != 1)
    throw WriteError("cannot write '" + path + "': .stl and .obj hold straight faces; write a curved or quadratic "
                     "mesh as .vtu, .vtk or .msh");
}
} // namespace

std::vector<std::string> MeshFileWriter::Write(const std::string& path)
{
  const std::optional<MeshFormat> format = FormatOfPath(path);
  if (!format)
  {
    throw WriteError("cannot write '" + path + "': unknown extension (known: " + KnownExtensions() + ")");
  }
  const bool surface = *format == MeshFormat::Vtp || *format == MeshFormat::Stl || *format == MeshFormat::Obj;
  if (surface && !this->Interfaces)
  {
    throw WriteError("cannot write '" + path + "': this run has no interface surface");
  }
  const auto flat = [&]() -> const ExportMesh& {
    try
    {
      return this->Flat();
    }
    catch (const WriteError& e)
    {
      throw WriteError("cannot write '" + path + "': " + e.what());
    }
  };
  switch (*format)
  {
    case MeshFormat::Vtu: WriteWhole(path, [&](std::ostream& out) { WriteVtu(this->Mesh, out); }); break;
    case MeshFormat::Pvtu: return WritePvtu(this->Mesh, path);
    case MeshFormat::LegacyVtk: WriteWhole(path, [&](std::ostream& out) { WriteLegacyVtk(this->Mesh, out); }); break;
    case MeshFormat::Vtp: WriteWhole(path, [&](std::ostream& out) { WriteVtp(this->Interfaces, out); }); break;
    case MeshFormat::Gmsh:
    {
      const ExportMesh& m = flat();
      WriteWhole(path, [&](std::ostream& out) { this->Options.GmshVersion22 ? WriteGmsh22(m, out) : WriteGmsh41(m, out); });
      break;
    }
    case MeshFormat::Abaqus:
    {
      const ExportMesh& m = flat();
      WriteWhole(path, [&](std::ostream& out) { WriteAbaqus(m, out); });
      break;
    }
    case MeshFormat::Medit:
    {
      const ExportMesh& m = flat();
      WriteWhole(path, [&](std::ostream& out) { WriteMedit(m, out); });
      break;
    }
    case MeshFormat::Obj:
    {
      const ExportMesh& m = flat();
      RefuseCurved(m, path);
      WriteWhole(path, [&](std::ostream& out) { WriteObj(m, out); });
      break;
    }
    case MeshFormat::Stl:
    {
      const ExportMesh& m = flat();
      RefuseCurved(m, path);
      if (m.Dimension != 3)
      {
        throw WriteError("cannot write '" + path + "': STL holds triangles, a 2D mesh's interfaces are segments (use .obj or .vtp)");
      }
      if (!this->Options.StlPerInterface)
      {
        WriteWhole(path, [&](std::ostream& out) { WriteStl(m, out); });
        break;
      }
      std::vector<std::string> written;
      for (std::size_t i = 0; i < m.Interfaces.size(); ++i)
      {
        const std::string name = InterfaceFileName(path, m, i);
        WriteWhole(name, [&](std::ostream& out) { WriteStl(m, out, static_cast<long>(i)); });
        written.push_back(name);
      }
      return written;
    }
  }
  return { path };
}

} // namespace io
} // namespace labelmesher
