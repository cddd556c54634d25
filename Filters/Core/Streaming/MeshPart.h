// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MeshPart_h
#define labelmesher_MeshPart_h

/**
 * @file MeshPart.h
 * What one part of the block-streamed pipeline leaves (StreamedPipeline.h):
 * its blocks decimated and joined, borders towards the other parts frozen, and
 * the vertices to offer again once the parts are joined. A part is the unit a
 * process takes under MPI, so it also travels as bytes (PartExchange.h).
 */

#include "Decimation/DecimationParameters.h"
#include "Mesh/SimplexMesh.h"
#include "Support/StageClock.h"

#include <cstddef>
#include <string>
#include <vector>

namespace labelmesher
{

struct MeshPart
{
  SimplexMesh Mesh;                   ///< the part's cells, points on the doubled lattice / 2
  std::vector<std::uint8_t> Offered;  ///< per vertex of Mesh: offered again in the later passes
  std::vector<std::uint8_t> Border;   ///< per vertex of Mesh: may be shared with another part
  DecimationCounts Counts;            ///< of its blocks and border passes
  std::size_t Blocks = 0, LargestBlockCells = 0, ForegroundCellsBefore = 0, BorderPasses = 0,
              LargestAssembledCells = 0;
  std::vector<StageTiming> Timings;   ///< stage times of its blocks, added up per stage
};

/// A message between processes: a part, or why the sender failed.
struct PartMessage
{
  bool Failed = false;
  std::string Reason; ///< with Failed: one line
  MeshPart Part;
};

/// The message as bytes, and back. Unpack throws std::runtime_error on bytes
/// that are not a whole message.
std::vector<char> PackPartMessage(const PartMessage& message);
PartMessage UnpackPartMessage(const std::vector<char>& bytes);

} // namespace labelmesher

#endif
