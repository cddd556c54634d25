// SPDX-License-Identifier: GPL-2.0-or-later
//
// MPIPieceExchange: run under `mpirun -np N` (N >= 2) by ctest. Rank 0 sends every other process
// pieces of the output as vtkLabelMesher hands them out (MPIPartExchange.h: SendPieceTo,
// ReceivePieceFromRankZero): one larger than a message (70 MiB and a few bytes: two messages
// and a part), none, and an empty one, in that order; each process checks every byte. All
// agree on the first failure (FirstFailure); rank 0 prints one line and the exit status is
// 0 only when every process got what was sent.
#include "MPIPartExchange.h"
#include "MPIStartup.h"

#include <cstdint>
#include <cstdio>
#include <string>

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

/// What went wrong on this process ("" when nothing).
std::string Exchange(int rank, int ranks)
{
  const std::size_t large = (std::size_t(70) << 20) + 3;
  if (rank == 0)
  {
    for (int r = 1; r < ranks; ++r)
    {
      const std::string piece = PieceFor(r, large);
      labelmesher::SendPieceTo(r, &piece);
      labelmesher::SendPieceTo(r, nullptr);
      const std::string empty;
      labelmesher::SendPieceTo(r, &empty);
    }
    return {};
  }
  std::string bytes, problem;
  if (!labelmesher::ReceivePieceFromRankZero(bytes, problem) || !problem.empty())
    return "the large piece did not come: " + problem;
  if (bytes != PieceFor(rank, large))
    return "the large piece came with " + std::to_string(bytes.size()) + " bytes, or other bytes";
  if (labelmesher::ReceivePieceFromRankZero(bytes, problem) || !problem.empty())
    return "a piece came where rank 0 sent none";
  if (!labelmesher::ReceivePieceFromRankZero(bytes, problem) || !bytes.empty() || !problem.empty())
    return "the empty piece did not come empty";
  return {};
}

} // namespace

int main()
{
  labelmesher::StartMPI();
  const int rank = labelmesher::WorldRank(), ranks = labelmesher::WorldSize();
  if (ranks < 2)
  {
    std::fprintf(stderr, "MPIPieceExchange: run it under mpirun with at least two processes\n");
    return 2;
  }
  std::string problem;
  try
  {
    problem = Exchange(rank, ranks);
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  const std::string failure = labelmesher::FirstFailure(problem);
  if (rank == 0)
    std::printf("%s\n", failure.empty() ? "OK: every process got its pieces, byte for byte" : failure.c_str());
  return failure.empty() ? 0 : 1;
}
