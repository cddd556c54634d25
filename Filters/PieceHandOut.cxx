// SPDX-License-Identifier: GPL-2.0-or-later
// Rank 0 cuts the mesh and sends the pieces (MPIPartExchange.h moves the bytes); every process
// then agrees on the first failure, so that none waits for a piece that will not come and none
// keeps a piece of a mesh another process lost. No exception leaves a step before that
// agreement: a process that left it would leave the others waiting in it for ever.
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

/// Runs `step` unless `problem` already holds one; what it throws becomes `problem`.
template <class Step>
void Attempt(std::string& problem, const std::string& what, Step&& step)
{
  if (!problem.empty())
    return;
  try
  {
    step();
  }
  catch (const std::bad_alloc&)
  {
    problem = "no memory to " + what;
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  catch (...)
  {
    problem = "could not " + what;
  }
}

/// Rank 0: the cells of each process's piece (none: nothing to hand out, rank 0 keeps the
/// whole). Without the array Process one process meshed the whole (one part).
std::vector<std::vector<vtkIdType>> CutByProcess(vtkUnstructuredGrid* mesh, int ranks, std::string& problem)
{
  std::vector<std::vector<vtkIdType>> cellsOf;
  if (mesh->GetNumberOfCells() == 0)
    problem = "process 0 made no mesh (it says why)";
  Attempt(problem, "cut the mesh into the processes' pieces", [&] {
    if (mesh->GetCellData()->GetArray(arrays::Process) != nullptr)
      cellsOf = CellsOfPieces(PieceOfCells(mesh, ranks), ranks);
  });
  return cellsOf;
}

/// Rank 0: sends every other process its piece, or none once anything failed (each waits for
/// something); a process that made no room for its piece says why itself, and the pieces after
/// it are not made.
void SendPieces(vtkUnstructuredGrid* mesh, const std::vector<std::vector<vtkIdType>>& cellsOf, int ranks,
  std::string& problem)
{
  bool refused = false;
  for (int r = 1; r < ranks; ++r)
  {
    std::string bytes;
    const bool sends = !cellsOf.empty() && !refused;
    Attempt(problem, "make process " + std::to_string(r) + "'s piece", [&] {
      if (sends)
      {
        bytes = MeshBytes(MeshPiece(mesh, cellsOf[static_cast<std::size_t>(r)]));
        if (bytes.empty())
          problem = "VTK's writer could not turn process " + std::to_string(r) + "'s piece into bytes";
      }
    });
    const std::string* piece = sends && problem.empty() ? &bytes : nullptr;
    if (!SendPieceTo(r, piece) && piece)
      refused = true;
  }
}

/// A process other than rank 0: its piece into `mesh`. Returns what went wrong ("" when nothing).
std::string ReceivePiece(vtkUnstructuredGrid* mesh)
{
  std::string bytes, problem;
  const bool came = ReceivePieceFromRankZero(bytes, problem);
  Attempt(problem, "read its piece back as a mesh", [&] {
    if (came && !MeshFromBytes(bytes, mesh))
      problem = "its piece of the output did not read back as a mesh";
  });
  return problem;
}

} // namespace

std::string HandOutPieces(vtkUnstructuredGrid* mesh)
{
  std::string problem;
  if (WorldRank() == 0)
  {
    const std::vector<std::vector<vtkIdType>> cellsOf = CutByProcess(mesh, WorldSize(), problem);
    SendPieces(mesh, cellsOf, WorldSize(), problem);
    Attempt(problem, "make its own piece", [&] {
      if (!cellsOf.empty())
        mesh->ShallowCopy(MeshPiece(mesh, cellsOf[0]));
    });
  }
  else
  {
    problem = ReceivePiece(mesh);
  }
  const std::string failure = FirstFailure(problem.empty() ? problem : "handing out the output's pieces: " + problem);
  if (!failure.empty())
    mesh->Initialize();
  return failure;
}

} // namespace labelmesher
