// SPDX-License-Identifier: GPL-2.0-or-later
// A mesh cut into its processes' pieces, and a piece carried as bytes
// (OutputPieces.h): what vtkLabelMesher hands each process in a parallel
// pipeline, and what a .pvtu's pieces hold.
#include "OutputPieces.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace labelmesher
{
namespace
{

/// Three tetrahedra on five points (cell c uses points c, c+1, c+2, c+3... wrapped), a point
/// array, a cell array Material and the run's field data: a number and the material names.
vtkSmartPointer<vtkUnstructuredGrid> ThreeCells()
{
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double xyz[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.1 + 1e-15, 1.0 / 3.0, 7 } };
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (const auto& p : xyz)
  {
    points->InsertNextPoint(p);
    height->InsertNextValue(p[2]);
  }
  mesh->SetPoints(points);
  mesh->GetPointData()->AddArray(height);
  const vtkIdType cells[3][4] = { { 0, 1, 2, 3 }, { 1, 2, 3, 4 }, { 0, 2, 3, 4 } };
  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  for (int c = 0; c < 3; ++c)
  {
    mesh->InsertNextCell(VTK_TETRA, 4, cells[c]);
    material->InsertNextValue(10 + c);
  }
  mesh->GetCellData()->AddArray(material);
  vtkNew<vtkDoubleArray> angle;
  angle->SetName("MinimumAngle");
  angle->InsertNextValue(15.086250319449395);
  vtkNew<vtkStringArray> names;
  names->SetName("MaterialName");
  names->InsertNextValue("white matter");
  names->InsertNextValue("Ventrikel (Ä)");
  mesh->GetFieldData()->AddArray(angle);
  mesh->GetFieldData()->AddArray(names);
  return mesh;
}

/// The points of cell `c` of `mesh`, as coordinates.
std::vector<std::vector<double>> CellCorners(vtkUnstructuredGrid* mesh, vtkIdType c)
{
  vtkNew<vtkIdList> ids;
  mesh->GetCellPoints(c, ids);
  std::vector<std::vector<double>> corners;
  for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
  {
    const double* p = mesh->GetPoint(ids->GetId(k));
    corners.push_back({ p[0], p[1], p[2] });
  }
  return corners;
}

TEST(OutputPieces, APieceHoldsItsCellsTheirPointsAndEveryArray)
{
  const auto mesh = ThreeCells();
  const auto cellsOf = CellsOfPieces({ 1, 0, 1 }, 3);
  ASSERT_EQ(cellsOf.size(), 3u);
  EXPECT_EQ(cellsOf[0], (std::vector<vtkIdType>{ 1 }));
  EXPECT_EQ(cellsOf[1], (std::vector<vtkIdType>{ 0, 2 }));
  EXPECT_TRUE(cellsOf[2].empty());
  EXPECT_EQ(CellsOfPieces({ 1, -1, 5 }, 2), (std::vector<std::vector<vtkIdType>>{ {}, { 0 } })); // in none

  const auto piece = MeshPiece(mesh, cellsOf[1]);
  ASSERT_EQ(piece->GetNumberOfCells(), 2);
  EXPECT_EQ(piece->GetNumberOfPoints(), 5); // cells 0 and 2 use all five
  EXPECT_EQ(CellCorners(piece, 0), CellCorners(mesh, 0));
  EXPECT_EQ(CellCorners(piece, 1), CellCorners(mesh, 2));
  EXPECT_EQ(piece->GetCellData()->GetArray("Material")->GetTuple1(1), 12);
  const auto other = MeshPiece(mesh, cellsOf[0]);
  ASSERT_EQ(other->GetNumberOfCells(), 1);
  EXPECT_EQ(other->GetNumberOfPoints(), 4); // only the points cell 1 uses
  EXPECT_EQ(CellCorners(other, 0), CellCorners(mesh, 1));
  for (vtkIdType p = 0; p < other->GetNumberOfPoints(); ++p)
    EXPECT_EQ(other->GetPointData()->GetArray("Height")->GetTuple1(p), other->GetPoint(p)[2]);
  EXPECT_EQ(MeshPiece(mesh, cellsOf[2])->GetNumberOfCells(), 0);
  EXPECT_EQ(piece->GetFieldData()->GetNumberOfArrays(), 2); // each piece reads alone
  EXPECT_EQ(other->GetFieldData()->GetNumberOfArrays(), 2);
}

TEST(OutputPieces, AMeshReplacedByItsOwnPieceKeepsItsFields)
{
  // Rank 0 keeps its piece in place of the whole mesh: the piece's fields must not be the
  // mesh's own object, or copying the piece over the mesh would empty them.
  const auto mesh = ThreeCells();
  const auto own = MeshPiece(mesh, { 0, 2 });
  mesh->ShallowCopy(own);
  EXPECT_EQ(mesh->GetNumberOfCells(), 2);
  ASSERT_EQ(mesh->GetFieldData()->GetNumberOfArrays(), 2);
  EXPECT_EQ(mesh->GetFieldData()->GetArray("MinimumAngle")->GetTuple1(0), 15.086250319449395);
}

TEST(OutputPieces, BytesGiveBackTheSameMesh)
{
  const auto mesh = ThreeCells();
  const std::string bytes = MeshBytes(mesh);
  ASSERT_FALSE(bytes.empty());
  vtkNew<vtkUnstructuredGrid> back;
  ASSERT_TRUE(MeshFromBytes(bytes, back));
  ASSERT_EQ(back->GetNumberOfCells(), 3);
  ASSERT_EQ(back->GetNumberOfPoints(), 5);
  for (vtkIdType c = 0; c < 3; ++c)
  {
    EXPECT_EQ(back->GetCellType(c), VTK_TETRA);
    EXPECT_EQ(CellCorners(back, c), CellCorners(mesh, c)); // every coordinate exact
    EXPECT_EQ(back->GetCellData()->GetArray("Material")->GetTuple1(c), 10 + c);
  }
  EXPECT_EQ(back->GetPointData()->GetArray("Height")->GetTuple1(4), 7);
  EXPECT_EQ(back->GetFieldData()->GetArray("MinimumAngle")->GetTuple1(0), 15.086250319449395);
  auto* names = vtkStringArray::SafeDownCast(back->GetFieldData()->GetAbstractArray("MaterialName"));
  ASSERT_NE(names, nullptr);
  ASSERT_EQ(names->GetNumberOfValues(), 2);
  EXPECT_EQ(names->GetValue(0), "white matter");
  EXPECT_EQ(names->GetValue(1), "Ventrikel (Ä)");

  vtkNew<vtkUnstructuredGrid> empty;
  ASSERT_TRUE(MeshFromBytes(MeshBytes(empty), back));
  EXPECT_EQ(back->GetNumberOfCells(), 0);
}

TEST(OutputPieces, BytesThatAreNoMeshAreRefused)
{
  vtkNew<vtkUnstructuredGrid> mesh;
  EXPECT_FALSE(MeshFromBytes("not a mesh", mesh));
  EXPECT_FALSE(MeshFromBytes("", mesh));
  const std::string bytes = MeshBytes(ThreeCells());
  EXPECT_FALSE(MeshFromBytes(bytes.substr(0, bytes.size() / 2), mesh));
}

} // namespace
} // namespace labelmesher
