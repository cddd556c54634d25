// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_PartExchange_h
#define labelmesher_PartExchange_h

/**
 * @file PartExchange.h
 * How the parts of the block-streamed pipeline (StreamedPipeline.h) reach the
 * process that joins them: each process meshes the parts it owns and every
 * process other than rank 0 hands its parts, as bytes (MeshPart.h), to rank 0,
 * in order. The core knows processes only through this: the MPI one is the
 * application's (Filters/MPIPartExchange.h); tests run the ranks in one process.
 */

#include <vector>

namespace labelmesher
{

class PartExchange
{
public:
  virtual ~PartExchange() = default;
  /// This process, in [0, Ranks()).
  virtual int Rank() const = 0;
  virtual int Ranks() const = 0;
  /// From a rank other than 0: the next message to rank 0.
  virtual void Send(const std::vector<char>& message) = 0;
  /// On rank 0: the next message from `rank` (messages of one rank arrive in the order sent).
  virtual std::vector<char> Receive(int rank) = 0;
};

} // namespace labelmesher

#endif
