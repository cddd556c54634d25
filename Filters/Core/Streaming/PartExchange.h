// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_PartExchange_h
#define labelmesher_PartExchange_h

/**
 * @file PartExchange.h
 * How the parts of the block-streamed pipeline (StreamedPipeline.h) reach the
 * process that joins them: rank 0 plans the parts and sends every other
 * process its assignment (its parts' leaves), each process meshes the parts it owns and every
 * process other than rank 0 hands its parts, as bytes (MeshPart.h), to rank 0,
 * in order; one that fails also sends a notice rank 0 looks for between its
 * own blocks, so that a failure ends the run early. The core knows processes
 * only through this: the MPI one is the application's
 * (Filters/MPIPartExchange.h); tests run the ranks in one process.
 */

#include <string>
#include <vector>

namespace labelmesher
{

/// A failure on process `rank` of `ranks` as the run reports it: "process R
/// of N: reason", or the reason alone from rank 0 (the process the user sees).
inline std::string ProcessFailure(int rank, int ranks, const std::string& reason)
{
  return rank == 0 ? reason : "process " + std::to_string(rank) + " of " + std::to_string(ranks) + ": " + reason;
}

class PartExchange
{
public:
  virtual ~PartExchange() = default;
  /// This process, in [0, Ranks()).
  virtual int Rank() const = 0;
  virtual int Ranks() const = 0;
  /// On rank 0: `rank`'s assignment, sent once, before any part. It may
  /// return before `rank` takes it.
  virtual void Assign(int rank, std::vector<char> assignment) = 0;
  /// From a rank other than 0: its assignment from rank 0 (waits for it).
  virtual std::vector<char> ReceiveAssignment() = 0;
  /// From a rank other than 0: the next message to rank 0. It may return
  /// before rank 0 takes it (so that the rank goes on meshing meanwhile).
  virtual void Send(std::vector<char> message) = 0;
  /// Returns once every message this process sent (parts, assignments) was taken.
  virtual void Flush() {}
  /// On rank 0: the next message from `rank` (messages of one rank arrive in the order sent).
  virtual std::vector<char> Receive(int rank) = 0;
  /// From a rank other than 0 that failed, before it sends its failure in
  /// place of its next part: a notice rank 0 sees as soon as it looks
  /// (PollNotice), not only once it reaches that part.
  virtual void Notify(const std::string& reason) = 0;
  /// On rank 0, without waiting: a rank whose notice has arrived, with its
  /// reason, or -1. Each notice is returned once.
  virtual int PollNotice(std::string& reason) = 0;
  /// On rank 0: waits for `rank`'s notice, which it sent (its failure arrived
  /// in place of a part) and PollNotice has not returned. Every notice must
  /// be taken: the rank waits until it is.
  virtual void TakeNotice(int rank) = 0;
  /// Every rank, at the same point: each passes what stopped it ("": nothing)
  /// and all get "" when none failed, else the lowest failing rank's reason
  /// (ProcessFailure).
  virtual std::string Agree(const std::string& failure) = 0;
};

} // namespace labelmesher

#endif
