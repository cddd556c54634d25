// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MPIPartExchange_h
#define labelmesher_MPIPartExchange_h

/**
 * @file MPIPartExchange.h
 * The streamed pipeline's parts between the processes of MPI_COMM_WORLD, on
 * a duplicate of it made once (Streaming/PartExchange.h): what `mpirun -np N labelmesher mesh` runs on.
 * Application plumbing, in library LabelMesherMPIStartup with MPI's start-up.
 */

#include <memory>
#include <string>
#include <vector>

namespace labelmesher
{

class PartExchange;

/// This process's rank in MPI_COMM_WORLD and the world's size (0 and 1 when
/// MPI is not running, not yet or no longer (finalized), or libsc has no MPI).
int WorldRank();
int WorldSize();

/// True when this process was started by an MPI launcher with more than one
/// process (Open MPI's OMPI_COMM_WORLD_SIZE or MPICH's PMI_SIZE > 1): the
/// application then starts MPI and shares the run out. Read from the
/// environment, before MPI starts.
bool LaunchedOnSeveralProcesses();

/// This process's rank and the number of processes as its launcher set them
/// in the environment (0 and 1 when none did), readable before MPI starts.
int LaunchedRank();
int LaunchedProcesses();

/// Collective over the world's processes: every process passes what stopped it ("":
/// nothing) and all get the same answer, "" when none failed, else the lowest
/// failing rank's reason ("process R of N: " before it unless R is 0). So that
/// no process waits for one that has given up. One process: `failure` itself.
std::string FirstFailure(const std::string& failure);

/// Collective over the world's processes: whether `value` (what decides the mesh:
/// the image and the parameters, say) is rank 0's. One process: true.
bool SameAsRankZero(const std::string& value);

/// Rank 0 of the world's processes: offers process `rank` its piece of the
/// output, or none (null), and sends its bytes if that process made room for
/// them; true when it did. Point to point: that process must be in
/// ReceivePieceFromRankZero. Throws std::runtime_error when MPI fails.
bool SendPieceTo(int rank, const std::string* bytes);

/// A process other than rank 0: its piece of the output from rank 0 into
/// `bytes`; false when rank 0 sent none, or when this process has no memory
/// for it (then `problem` says so, rank 0 is told, and no bytes travel).
bool ReceivePieceFromRankZero(std::string& bytes, std::string& problem);

/// An exchange between the world's processes when there are several, else
/// null (one process needs none).
std::unique_ptr<PartExchange> WorldPartExchange();

} // namespace labelmesher

#endif
