// SPDX-License-Identifier: GPL-2.0-or-later
//
// MPIPieceExchange: run under `mpirun -np 3` by ctest. How the output's pieces reach their
// processes when a parallel pipeline (pvbatch) asks each process for its own piece:
// - the bytes (MPIPartExchange.h: SendPieceTo, ReceivePieceFromRankZero): a piece larger than a
//   message (70 MiB and a few bytes: two messages and a part), none, an empty one, and one a
//   process has no memory for (it says so and no bytes travel; not under a sanitizer, whose
//   allocator meets an address-space limit otherwise);
// - the meshes (PieceHandOut.h): each process's cells, points, arrays and field data; every cell
//   on rank 0 without a Process array; a Process value beyond the processes, no mesh on rank 0,
//   and a process with no memory for its piece: every mesh emptied, the same reason on every
//   process;
// - vtkLabelMesher refusing processes whose pipelines ask for different outputs (one its piece,
//   another the whole mesh).
// Each check is collective; all agree on the first failure (FirstFailure); rank 0 prints one line
// a check and the exit status is 0 only when every check passed on every process.
#include "LabelMesherArrayNames.h"
#include "MPIPartExchange.h"
#include "MPIStartup.h"
#include "PieceHandOut.h"
#include "VTKMessages.h"
#include "vtkLabelMesher.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <sc.h> // mpi.h: MPI_Abort

// A sanitizer's allocator (or shadow memory) does not meet an address-space limit as malloc does.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define LABELMESHER_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer) ||     \
  __has_feature(leak_sanitizer)
#define LABELMESHER_SANITIZED 1
#endif
#endif

namespace
{

/// A piece for process `rank` of `size` bytes: a pattern that differs by rank and position.
std::string PieceFor(int rank, std::size_t size)
{
  std::string bytes(size, '\0');
  for (std::size_t i = 0; i < size; ++i)
    bytes[i] = static_cast<char>((i * 131 + static_cast<std::size_t>(rank) * 7 + i / 4099) & 0xff);
  return bytes;
}

/// While it lives, this process may map at most `extra` bytes more than it has mapped now (when
/// Applied(): the kernel took the limit). Kept for one exchange alone: Open MPI's own
/// allocations meanwhile (small messages only) fit in `extra`.
class AddressSpaceLimit
{
public:
  explicit AddressSpaceLimit(std::size_t extra)
  {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0;
    if (getrlimit(RLIMIT_AS, &this->Before) != 0 || !(statm >> pages))
      return;
    rlimit limit = this->Before;
    limit.rlim_cur = pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE)) + extra;
    this->Limited = limit.rlim_cur <= limit.rlim_max && setrlimit(RLIMIT_AS, &limit) == 0;
  }
  ~AddressSpaceLimit()
  {
    if (this->Limited)
      setrlimit(RLIMIT_AS, &this->Before);
  }
  AddressSpaceLimit(const AddressSpaceLimit&) = delete;
  AddressSpaceLimit& operator=(const AddressSpaceLimit&) = delete;
  bool Applied() const { return this->Limited; }

private:
  rlimit Before{};
  bool Limited = false;
};

constexpr bool kSanitized =
#ifdef LABELMESHER_SANITIZED
  true;
#else
  false;
#endif

std::string ExchangeBytes(int rank, int ranks)
{
  const std::size_t large = (std::size_t(70) << 20) + 3;
  if (rank == 0)
  {
    // Every process is sent all it waits for, whatever goes wrong: the first problem is kept.
    std::string problem;
    const auto expect = [&problem](bool as, const std::string& otherwise) {
      if (!as && problem.empty())
        problem = otherwise;
    };
    for (int r = 1; r < ranks; ++r)
    {
      const std::string piece = PieceFor(r, large), empty, process = "process " + std::to_string(r);
      expect(labelmesher::SendPieceTo(r, &piece), process + " did not take its large piece");
      expect(!labelmesher::SendPieceTo(r, nullptr), process + " took a piece where none was sent");
      expect(labelmesher::SendPieceTo(r, &empty), process + " did not take its empty piece");
      if (!kSanitized)
        expect(!labelmesher::SendPieceTo(r, &piece), process + " took a piece it had no memory for");
    }
    return problem;
  }
  // Every message is taken, whatever goes wrong, so that rank 0 never waits: the first problem
  // is kept.
  std::string bytes, problem, failure;
  const auto expect = [&failure, &problem](bool as, const std::string& otherwise) {
    if (!as && failure.empty())
      failure = otherwise + (problem.empty() ? "" : " (" + problem + ")");
  };
  expect(labelmesher::ReceivePieceFromRankZero(bytes, problem) && problem.empty(), "the large piece did not come");
  expect(bytes == PieceFor(rank, large),
    "the large piece came with " + std::to_string(bytes.size()) + " bytes, or other bytes");
  expect(
    !labelmesher::ReceivePieceFromRankZero(bytes, problem) && problem.empty(), "a piece came where rank 0 sent none");
  expect(labelmesher::ReceivePieceFromRankZero(bytes, problem) && bytes.empty() && problem.empty(),
    "the empty piece did not come empty");
  if (!kSanitized)
  {
    bool came = false;
    std::string unheld; // not `bytes`, whose capacity would hold the piece without allocating
    {
      const AddressSpaceLimit limit(std::size_t(16) << 20);
      came = labelmesher::ReceivePieceFromRankZero(unheld, problem);
      expect(limit.Applied(), "the address space could not be limited");
    }
    expect(!came &&
        problem.find("it had no memory for its piece of the output (" + std::to_string(large) + " bytes)") !=
          std::string::npos,
      "a piece too large to hold was not refused in words");
  }
  return failure;
}

/// The whole mesh rank 0 cuts: `cells` tetrahedra, cell c on its own four points at x = c, its
/// cell array Material = 100 + c and Process = `process(c)` (no array when null), a point
/// array and the run's field data.
vtkSmartPointer<vtkUnstructuredGrid> WholeMesh(int cells, const std::function<int(int)>& process)
{
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  vtkNew<vtkIntArray> material, processes;
  material->SetName(labelmesher::arrays::Material);
  processes->SetName(labelmesher::arrays::Process);
  for (int c = 0; c < cells; ++c)
  {
    const double corner[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = points->InsertNextPoint(corner[k][0] + c, corner[k][1], corner[k][2] + 0.25 * k);
      height->InsertNextValue(corner[k][2] + 0.25 * k);
    }
    mesh->InsertNextCell(VTK_TETRA, 4, ids);
    material->InsertNextValue(100 + c);
    if (process)
      processes->InsertNextValue(process(c));
  }
  mesh->SetPoints(points);
  mesh->GetPointData()->AddArray(height);
  mesh->GetCellData()->AddArray(material);
  if (process)
    mesh->GetCellData()->AddArray(processes);
  vtkNew<vtkDoubleArray> run;
  run->SetName("ImageToMeshDistance");
  run->InsertNextValue(1.5);
  mesh->GetFieldData()->AddArray(run);
  return mesh;
}

/// "" when `piece` holds exactly the cells of `whole` whose process is `rank` (all of them when
/// `process` is null and rank is 0), each on its own points, with the field data.
std::string CheckPiece(
  vtkUnstructuredGrid* piece, int cells, const std::function<int(int)>& process, int rank)
{
  std::vector<int> expected;
  for (int c = 0; c < cells; ++c)
    if (process ? process(c) == rank : rank == 0)
      expected.push_back(c);
  if (piece->GetNumberOfCells() != static_cast<vtkIdType>(expected.size()) ||
    piece->GetNumberOfPoints() != 4 * piece->GetNumberOfCells())
    return "its piece has " + std::to_string(piece->GetNumberOfCells()) + " cells, not " +
      std::to_string(expected.size());
  if (expected.empty())
    return {};
  vtkDataArray* material = piece->GetCellData()->GetArray(labelmesher::arrays::Material);
  vtkDataArray* height = piece->GetPointData()->GetArray("Height");
  vtkDataArray* run = piece->GetFieldData()->GetArray("ImageToMeshDistance");
  vtkDataArray* processes = piece->GetCellData()->GetArray(labelmesher::arrays::Process);
  if (!material || !height || !run || run->GetComponent(0, 0) != 1.5 || (process && !processes))
    return "its piece lost an array";
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < piece->GetNumberOfCells(); ++c)
  {
    const int original = expected[static_cast<std::size_t>(c)];
    if (material->GetComponent(c, 0) != 100 + original || (processes && processes->GetComponent(c, 0) != rank))
      return "its cell " + std::to_string(c) + " is not the whole mesh's cell " + std::to_string(original);
    piece->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < 4; ++k)
    {
      double p[3];
      piece->GetPoint(ids->GetId(k), p);
      if (p[0] < original || p[0] > original + 1 || height->GetComponent(ids->GetId(k), 0) != p[2])
        return "its cell " + std::to_string(c) + " has another point";
    }
  }
  return {};
}

/// Hands out the pieces of a `cells`-cell mesh cut by `process`; "" when every process holds its
/// own, or the failure any process met when `failure` is expected in it (then every mesh must
/// be empty).
std::string HandOut(int rank, int cells, const std::function<int(int)>& process, const std::string& failure = {},
  std::size_t memoryOfRank2 = 0)
{
  vtkSmartPointer<vtkUnstructuredGrid> mesh =
    rank == 0 ? WholeMesh(cells, process) : vtkSmartPointer<vtkUnstructuredGrid>::New();
  std::string met;
  if (rank == 2 && memoryOfRank2 > 0)
  {
    const AddressSpaceLimit limit(memoryOfRank2);
    met = labelmesher::HandOutPieces(mesh);
    if (!limit.Applied())
      met = "the address space could not be limited";
  }
  else
  {
    met = labelmesher::HandOutPieces(mesh);
  }
  if (failure.empty())
    return met.empty() ? CheckPiece(mesh, cells, process, rank) : "the hand-out failed: " + met;
  if (met.find(failure) == std::string::npos)
    return "the hand-out did not fail with '" + failure + "' but with '" + met + "'";
  if (mesh->GetNumberOfCells() != 0 || mesh->GetNumberOfPoints() != 0)
    return "a failed hand-out left a piece";
  return {};
}

std::string HandOutMeshes(int rank, int ranks)
{
  const auto spread = [ranks](int c) { return (c * 7) % ranks; };
  std::string problem = HandOut(rank, 30, spread);
  if (problem.empty())
    problem = HandOut(rank, 30, nullptr);
  if (problem.empty())
    problem = HandOut(rank, 30, [ranks](int c) { return c == 17 ? ranks : c % ranks; },
      "handing out the output's pieces: cell 17 has Process " + std::to_string(ranks) +
        ", not a process rank below " + std::to_string(ranks));
  if (problem.empty())
    problem = HandOut(rank, 0, spread, "handing out the output's pieces: process 0 made no mesh");
  // About 180 bytes a cell as bytes (four points of three doubles, their heights, the cell):
  // process 2's piece of 600,000 cells, a third, is about 36 MB, far beyond 16 MiB.
  if (problem.empty() && !kSanitized && ranks >= 3)
    problem = HandOut(rank, 600000, spread,
      "process 2 of " + std::to_string(ranks) + ": handing out the output's pieces: it had no memory for its piece",
      std::size_t(16) << 20);
  return problem;
}

/// vtkLabelMesher on a small image, rank 0 asking for its piece and the others for the whole
/// mesh: refused before meshing, the same reason on every process, no cells.
std::string MismatchedRequests(int rank, int ranks)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(8, 8, 8);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* voxels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int i = 0; i < 512; ++i)
    voxels[i] = (i % 8 > 3) ? 1 : 0;
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetInputData(image);
  mesher->DistributedOn();
  const labelmesher::VTKMessages errors(mesher, vtkCommand::ErrorEvent);
  mesher->UpdatePiece(0, rank == 0 ? ranks : 1, 0); // rank 0: its piece (0 of N); the others: the whole
  const std::string expected = "process 1 of " + std::to_string(ranks) +
    ": its pipeline asked for the whole mesh where process 0's asked for each process's piece";
  if (errors.First().find(expected) == std::string::npos)
    return "not refused with '" + expected + "' but with '" + errors.First() + "'";
  if (mesher->GetOutput()->GetNumberOfCells() != 0)
    return "processes asking for different outputs were meshed";
  return {};
}

} // namespace

int main()
{
  alarm(100); // a check that leaves a process waiting ends the run before ctest's timeout
  labelmesher::StartMPI();
  const int rank = labelmesher::WorldRank(), ranks = labelmesher::WorldSize();
  if (ranks < 2)
  {
    std::fprintf(stderr, "MPIPieceExchange: run it under mpirun with at least two processes\n");
    return 2;
  }
  const std::pair<const char*, std::function<std::string(int, int)>> checks[] = {
    { "the pieces' bytes", ExchangeBytes },
    { "the meshes' pieces", HandOutMeshes },
    { "processes asking for different outputs", MismatchedRequests },
  };
  bool passed = true;
  for (const auto& [name, check] : checks)
  {
    std::string problem;
    try
    {
      problem = check(rank, ranks);
    }
    catch (const std::exception& e)
    {
      // Another process may be waiting for this one in the middle of an exchange: end the run.
      std::fprintf(stderr, "MPIPieceExchange: process %d: %s: %s\n", rank, name, e.what());
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    const std::string failure = labelmesher::FirstFailure(problem);
    if (rank == 0)
      std::printf("%s: %s\n", name, failure.empty() ? "OK" : failure.c_str());
    passed = passed && failure.empty();
  }
  return passed ? 0 : 1;
}
