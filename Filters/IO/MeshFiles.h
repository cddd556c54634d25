// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_MeshFiles_h
#define labelmesher_io_MeshFiles_h

/**
 * @file MeshFiles.h
 * The I/O layer's front door: the file formats a mesh can be written in,
 * chosen by the file's extension, and MeshFileWriter, which writes one run's
 * mesh, interface surface and material table to any number of them, each
 * through SafeFile (whole or not at all).
 *
 * | extension | format                                   | holds                  |
 * |-----------|------------------------------------------|------------------------|
 * | .vtu      | VTK XML unstructured grid                | cells, all arrays      |
 * | .pvtu     | the same in pieces, one per process      | cells, all arrays      |
 * | .vtk      | VTK legacy, binary                       | cells, all arrays      |
 * | .msh      | Gmsh MSH 4.1 (or 2.2) ASCII              | cells, interfaces      |
 * | .inp      | Abaqus input                             | cells, interface nodes |
 * | .mesh     | Medit, MeshVersionFormatted 2            | cells, interfaces      |
 * | .vtp      | VTK XML polydata                         | interfaces             |
 * | .stl      | binary STL (3D)                          | interfaces             |
 * | .obj      | Wavefront OBJ                            | interfaces             |
 */

#include "ExportMesh.h"
#include "MaterialTable.h"

#include "vtkSmartPointer.h"

#include <optional>
#include <string>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace labelmesher
{
namespace io
{

enum class MeshFormat
{
  Vtu,
  Pvtu, ///< summary and .vtu pieces (PvtuWriter.h)
  LegacyVtk,
  Gmsh,
  Abaqus,
  Medit,
  Vtp,
  Stl,
  Obj
};

/// The format of `path`'s extension (case-insensitive), if it is one.
std::optional<MeshFormat> FormatOfPath(const std::string& path);
/// ".vtu, .pvtu, .vtk, .msh, .inp, .mesh, .vtp, .stl, .obj"
std::string KnownExtensions();
/// Throws WriteError unless a mesh can be written as `path` (SafeFile's
/// CheckOutputPath, and for .pvtu PvtuWriter's CheckPvtuPath): call before
/// long work, so that a bad path fails first.
void CheckMeshOutputPath(const std::string& path);
/// True for the formats that hold curved (cubic) cells: .vtu, .pvtu, .vtk (Bezier cells) and .msh
/// (Gmsh's 10-node triangles, the same cells through their Lagrange nodes).
bool HoldsCurvedCells(MeshFormat format);
/// Formats that hold quadratic cells (VTK_QUADRATIC_TETRA, VTK_QUADRATIC_TRIANGLE): .vtu, .pvtu, .vtk,
/// .msh (10-node tetrahedra, 6-node triangles), .inp (C3D10, CPS6), .mesh (Medit's TetrahedraP2
/// and TrianglesP2, in VTK's node order; Debian's meshio cannot read them, Gmsh reads the 3D
/// ones: CLI.export_quadratic, CLI.export_quadratic_2d).
bool HoldsQuadraticCells(MeshFormat format);

struct WriteOptions
{
  bool GmshVersion22 = false;   ///< MSH 2.2 instead of 4.1
  bool StlPerInterface = false; ///< .stl: one file per interface, NAME_a_b.stl
};

class MeshFileWriter
{
public:
  /// `interfaces` may be null (then the FE formats have no interface faces and
  /// the surface formats cannot be written). The table also goes into the VTK
  /// files' field data.
  MeshFileWriter(vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, const MaterialTable& table,
    const WriteOptions& options);
  /// Writes `path` in the format of its extension; returns the files written
  /// (several for --stl-per-interface). Throws WriteError.
  std::vector<std::string> Write(const std::string& path);

private:
  const ExportMesh& Flat();
  vtkSmartPointer<vtkUnstructuredGrid> Mesh;
  vtkSmartPointer<vtkPolyData> Interfaces;
  MaterialTable Table;
  WriteOptions Options;
  std::optional<ExportMesh> Flattened; ///< made on first use, shared by the formats
};

} // namespace io
} // namespace labelmesher

#endif
