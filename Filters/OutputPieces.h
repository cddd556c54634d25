// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_OutputPieces_h
#define labelmesher_OutputPieces_h

/**
 * @file OutputPieces.h
 * A mesh cut into the pieces its processes meshed (cell array "Process"), and
 * a piece as bytes to send to its process: vtkLabelMesher hands each process
 * its piece when a parallel pipeline asks every process for one (pvbatch,
 * ParaView's server), and a .pvtu is written one piece per process
 * (IO/PvtuWriter.h). Not installed.
 */

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace labelmesher
{

/// The piece of every cell of `mesh`: its value in the cell array "Process"
/// (0 for every cell without that array). Throws std::invalid_argument naming
/// the first cell whose value is not a whole number in [0, pieces), or an array
/// that is not one value a cell.
std::vector<int> PieceOfCells(vtkUnstructuredGrid* mesh, int pieces);

/// The cells of each of `pieces` pieces, by `pieceOfCell` (one entry a cell);
/// an entry outside [0, pieces) is in none.
std::vector<std::vector<vtkIdType>> CellsOfPieces(const std::vector<int>& pieceOfCell, int pieces);

/// The cells `cells` of `mesh`, with the points they use (in the order cells
/// first use them), every point and cell array, and the mesh's field data
/// (each piece reads alone; the piece's own field data object, holding the
/// same arrays).
vtkSmartPointer<vtkUnstructuredGrid> MeshPiece(vtkUnstructuredGrid* mesh, const std::vector<vtkIdType>& cells);

/// `mesh` as bytes (VTK's legacy format, binary: every value exact; "" when
/// VTK's writer fails), and back. MeshFromBytes returns false for bytes that
/// are not a whole mesh (cut, damaged).
std::string MeshBytes(vtkUnstructuredGrid* mesh);
bool MeshFromBytes(const std::string& bytes, vtkUnstructuredGrid* mesh);

} // namespace labelmesher

#endif
