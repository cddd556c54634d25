// SPDX-License-Identifier: GPL-2.0-or-later
// A piece copies its cells and points by hand: vtkExtractCells does the same, but its module
// brings VTK's parallel DIY and MPI libraries into every program that writes a mesh (their
// address space alone made a run under `ulimit -v` 100 MiB abort in ITK's thread pool instead
// of being refused in one line).
#include "OutputPieces.h"

#include "LabelMesherArrayNames.h"
#include "VTKMessages.h"

#include "vtkCellData.h"
#include "vtkCharArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkUnstructuredGridWriter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <sstream>
#include <string>

namespace labelmesher
{

std::vector<int> PieceOfCells(vtkUnstructuredGrid* mesh, int pieces)
{
  std::vector<int> piece(static_cast<std::size_t>(mesh->GetNumberOfCells()), 0);
  vtkDataArray* process = mesh->GetCellData()->GetArray(arrays::Process);
  if (process == nullptr)
    return piece;
  if (process->GetNumberOfTuples() != mesh->GetNumberOfCells() || process->GetNumberOfComponents() != 1)
    throw std::invalid_argument("its cell array Process is not one value a cell");
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    const double value = process->GetComponent(c, 0);
    if (!(value >= 0 && value < pieces && value == std::floor(value)))
    {
      std::ostringstream reason;
      reason.precision(17);
      reason << "cell " << c << " has Process " << value << ", not a process rank below " << pieces;
      throw std::invalid_argument(reason.str());
    }
    piece[static_cast<std::size_t>(c)] = static_cast<int>(value);
  }
  return piece;
}

std::vector<std::vector<vtkIdType>> CellsOfPieces(const std::vector<int>& pieceOfCell, int pieces)
{
  std::vector<std::vector<vtkIdType>> cells(static_cast<std::size_t>(std::max(pieces, 0)));
  for (std::size_t c = 0; c < pieceOfCell.size(); ++c)
    if (pieceOfCell[c] >= 0 && pieceOfCell[c] < pieces)
      cells[static_cast<std::size_t>(pieceOfCell[c])].push_back(static_cast<vtkIdType>(c));
  return cells;
}

vtkSmartPointer<vtkUnstructuredGrid> MeshPiece(vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>& cells)
{
  auto piece = vtkSmartPointer<vtkUnstructuredGrid>::New();
  std::vector<vtkIdType> pointOf(static_cast<std::size_t>(mesh->GetNumberOfPoints()), -1);
  std::vector<vtkIdType> usedPoints;
  vtkNew<vtkIdList> ids;
  for (const vtkIdType c : cells)
  {
    mesh->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      vtkIdType& id = pointOf[static_cast<std::size_t>(ids->GetId(k))];
      if (id < 0)
      {
        id = static_cast<vtkIdType>(usedPoints.size());
        usedPoints.push_back(ids->GetId(k));
      }
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints() ? mesh->GetPoints()->GetDataType() : VTK_DOUBLE);
  points->SetNumberOfPoints(static_cast<vtkIdType>(usedPoints.size()));
  piece->GetPointData()->CopyAllocate(mesh->GetPointData(), static_cast<vtkIdType>(usedPoints.size()));
  for (std::size_t p = 0; p < usedPoints.size(); ++p)
  {
    points->SetPoint(static_cast<vtkIdType>(p), mesh->GetPoint(usedPoints[p]));
    piece->GetPointData()->CopyData(mesh->GetPointData(), usedPoints[p], static_cast<vtkIdType>(p));
  }
  piece->SetPoints(points);
  piece->Allocate(static_cast<vtkIdType>(cells.size()));
  piece->GetCellData()->CopyAllocate(mesh->GetCellData(), static_cast<vtkIdType>(cells.size()));
  for (std::size_t c = 0; c < cells.size(); ++c)
  {
    mesh->GetCellPoints(cells[c], ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      ids->SetId(k, pointOf[static_cast<std::size_t>(ids->GetId(k))]);
    piece->InsertNextCell(mesh->GetCellType(cells[c]), ids);
    piece->GetCellData()->CopyData(mesh->GetCellData(), cells[c], static_cast<vtkIdType>(c));
  }
  piece->GetFieldData()->ShallowCopy(mesh->GetFieldData()); // the material table, the run's fields
  return piece;
}

std::string MeshBytes(vtkUnstructuredGrid* mesh)
{
  vtkNew<vtkUnstructuredGridWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileTypeToBinary();
  writer->WriteToOutputStringOn();
  const VTKMessages errors(writer, vtkCommand::ErrorEvent);
  if (!writer->Write() || !errors.First().empty())
    return {};
  return writer->GetOutputStdString();
}

bool MeshFromBytes(const std::string& bytes, vtkUnstructuredGrid* mesh)
{
  // The bytes as the reader's input array, not copied (its length is a vtkIdType: the string
  // input's is an int).
  vtkNew<vtkCharArray> input;
  input->SetArray(const_cast<char*>(bytes.data()), static_cast<vtkIdType>(bytes.size()), /*save=*/1);
  vtkNew<vtkUnstructuredGridReader> reader;
  reader->ReadFromInputStringOn();
  reader->SetInputArray(input);
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
  // Cut or damaged bytes make the reader complain but not always fail: any complaint refuses.
  const VTKMessages errors(reader, vtkCommand::ErrorEvent);
  const VTKMessages executiveErrors(reader->GetExecutive(), vtkCommand::ErrorEvent);
  reader->Update();
  vtkUnstructuredGrid* read = reader->GetOutput();
  if (bytes.empty() || reader->GetErrorCode() != 0 || read == nullptr || !errors.First().empty() ||
    !executiveErrors.First().empty())
    return false;
  mesh->ShallowCopy(read);
  return true;
}

} // namespace labelmesher
