// SPDX-License-Identifier: GPL-2.0-or-later
// Rank 0 cuts the mesh and sends the pieces (MPIPartExchange.h moves the bytes); every process
// then agrees on the first failure, so that none waits for a piece that will not come and none
// keeps a piece of a mesh another process lost.
#include "PieceHandOut.h"

#include "LabelMesherArrayNames.h"
#include "MPIPartExchange.h"
#include "OutputPieces.h"

#include "vtkCellData.h"
#include "vtkUnstructuredGrid.h"

#include <exception>
#include <new>
#include <vector>

namespace labelmesher
{
namespace
{

/// Rank 0: sends every other process its piece of `mesh` and keeps its own. Returns what went
/// wrong ("" when nothing); every process is sent something (a piece, or none) whatever fails,
/// since each waits for it.
std::string SendPiecesFromRankZero(vtkUnstructuredGrid* mesh, int ranks)
{
  std::string problem;
  std::vector<std::vector<vtkIdType>> cellsOf; // empty: nothing to hand out
  try
  {
    // Without the array one process meshed the whole (one part): rank 0 keeps it, uncopied.
    if (mesh->GetCellData()->GetArray(arrays::Process) != nullptr)
      cellsOf = CellsOfPieces(PieceOfCells(mesh, ranks), ranks);
  }
  catch (const std::bad_alloc&)
  {
    problem = "no memory to cut the mesh into the processes' pieces";
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  for (int r = 1; r < ranks; ++r)
  {
    std::string bytes;
    const bool sends = problem.empty() && !cellsOf.empty();
    if (sends)
    {
      try
      {
        bytes = MeshBytes(MeshPiece(mesh, cellsOf[static_cast<std::size_t>(r)]));
        if (bytes.empty())
          problem = "VTK's writer could not turn process " + std::to_string(r) + "'s piece into bytes";
      }
      catch (const std::bad_alloc&)
      {
        problem = "no memory to make process " + std::to_string(r) + "'s piece";
      }
    }
    // A process that made no room for its piece says why itself (FirstFailure).
    SendPieceTo(r, sends && problem.empty() ? &bytes : nullptr);
  }
  if (problem.empty() && !cellsOf.empty())
  {
    try
    {
      mesh->ShallowCopy(MeshPiece(mesh, cellsOf[0]));
    }
    catch (const std::bad_alloc&)
    {
      problem = "no memory to make its own piece";
    }
  }
  return problem;
}

/// A process other than rank 0: its piece into `mesh`. Returns what went wrong ("" when nothing).
std::string ReceivePiece(vtkUnstructuredGrid* mesh)
{
  std::string bytes, problem;
  if (ReceivePieceFromRankZero(bytes, problem) && !MeshFromBytes(bytes, mesh))
    problem = "its piece of the output did not read back as a mesh";
  return problem;
}

} // namespace

std::string HandOutPieces(vtkUnstructuredGrid* mesh)
{
  const std::string problem = WorldRank() == 0 ? SendPiecesFromRankZero(mesh, WorldSize()) : ReceivePiece(mesh);
  const std::string failure = FirstFailure(problem.empty() ? problem : "handing out the output's pieces: " + problem);
  if (!failure.empty())
    mesh->Initialize();
  return failure;
}

} // namespace labelmesher
