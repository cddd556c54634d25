// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_ExportMesh_h
#define labelmesher_io_ExportMesh_h

/**
 * @file ExportMesh.h
 * What every finite-element writer needs, taken once from the filters'
 * outputs: physical points, the cells grouped by material, the interface faces
 * (the mesher's or decimator's port 1) on the same points grouped by the pair
 * of materials they separate, and the material table. The writers only format.
 */

#include "MaterialTable.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace labelmesher
{
namespace io
{

struct ExportMesh
{
  /// A run of consecutive entries (in Cells or Faces) with one key.
  struct Group
  {
    std::size_t Begin = 0, End = 0;
  };
  using Pair = std::pair<std::int32_t, std::int32_t>; ///< smaller label first

  int Dimension = 3; ///< 3: tetrahedra, interface triangles; 2: triangles, interface segments
  /// 1: linear cells; 3 (2D only): cubic triangles, ten Lagrange nodes each in VTK's (and Gmsh's)
  /// order, corners, then two per edge (0-1, 1-2, 2-0) from its first corner, then the centre;
  /// 2: quadratic tetrahedra, ten nodes in VTK's order (corners, then the mid-nodes of
  /// edges 0-1, 1-2, 2-0, 0-3, 1-3, 2-3: Abaqus C3D10's; Gmsh swaps the last two), or quadratic
  /// triangles, six nodes (corners, then the mid-nodes of edges 0-1, 1-2, 2-0: VTK's, Gmsh's,
  /// Abaqus CPS6's and Medit TrianglesP2's order).
  int Order = 1;
  std::vector<std::array<double, 3>> Points;
  /// Cells: NodesPerCell() point indices each, sorted by material.
  std::vector<std::int64_t> Cells;
  std::vector<std::int32_t> CellMaterial;
  std::vector<std::int32_t> Materials; ///< sorted labels of the cells
  std::vector<Group> MaterialCells;    ///< one per Materials entry
  /// Interface faces: NodesPerFace() point indices each, sorted by pair.
  std::vector<std::int64_t> Faces;
  std::vector<Pair> Interfaces;         ///< sorted pairs
  std::vector<Group> InterfaceFaces;    ///< one per Interfaces entry
  MaterialTable Table;
  /// For a 2D mesh whose points all share one coordinate: that axis (writers
  /// of planar formats drop it); otherwise -1.
  int FlatAxis = -1;

  int NodesPerCell() const
  {
    if (this->Order == 2)
      return this->Dimension == 3 ? 10 : 6;
    return this->Order == 3 ? 10 : this->Dimension + 1;
  }
  /// Interface faces: segments (2D), triangles, or of a quadratic mesh 6-node triangles (corners,
  /// then the mid-nodes of edges 0-1, 1-2, 2-0) and 3-node segments (ends, then the mid-node).
  int NodesPerFace() const
  {
    if (this->Order == 2)
      return this->Dimension == 3 ? 6 : 3;
    return this->Dimension;
  }
  std::size_t NumberOfCells() const { return this->CellMaterial.size(); }
  std::size_t NumberOfFaces() const { return this->Faces.size() / static_cast<std::size_t>(this->NodesPerFace()); }
  /// The largest material label (0 when there are no cells).
  std::int32_t LargestLabel() const { return this->Materials.empty() ? 0 : this->Materials.back(); }
};

/// The coordinate axes planar formats write: the two besides FlatAxis for a
/// flat 2D mesh, else all three.
std::vector<std::size_t> WrittenAxes(const ExportMesh& mesh);
/// Twice the signed area of triangle `cell` (three point indices) in the two
/// written axes of a flat 2D mesh: formats that want counter-clockwise
/// triangles flip those with a negative area.
double PlanarArea(const ExportMesh& mesh, const std::int64_t* cell);
/// Reverses a triangle's orientation in place (NodesPerCell() nodes): corners 1 and 2, and for a
/// quadratic one the mid-nodes of edges 0-1 and 2-0 with them.
void FlipTriangle(const ExportMesh& mesh, std::int64_t* cell);

/// Gathers `mesh` (VTK_TETRA, VTK_TRIANGLE, VTK_BEZIER_TRIANGLE (cubic), VTK_QUADRATIC_TETRA or
/// VTK_QUADRATIC_TRIANGLE cells, one type, with cell array Material)
/// and `interfaces` (triangles or lines with cell array Materials; may be null:
/// no faces) whose points must be points of `mesh`. For quadratic cells the interfaces are
/// taken from the cells instead, as 6-node triangles or 3-node segments (`interfaces` is not
/// used). Throws WriteError when they are not (other cells, mixed types, an interface point off
/// the mesh).
ExportMesh MakeExportMesh(vtkUnstructuredGrid* mesh, vtkPolyData* interfaces, const MaterialTable& table);

} // namespace io
} // namespace labelmesher

#endif
