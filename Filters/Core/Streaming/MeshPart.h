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
#include "Octree/LeafBox.h"
#include "Support/StageClock.h"

#include <array>
#include <cstddef>
#include <cstdint>
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

/// What rank 0 sends every other process before any part is meshed: the run
/// of the octree's leaves its parts cover and the slab of the image they need.
struct PartAssignment
{
  bool Failed = false; ///< rank 0 could not make the assignments: Reason says why, nothing else is set
  std::string Reason;
  std::array<int, 3> ImageDimensions{ 0, 0, 0 }; ///< of the whole image
  std::int32_t Depth = 0;                         ///< of the octree
  std::vector<OctreeLeaf> Leaves;                 ///< of its parts, in Morton order
  /// Where each of its parts starts in Leaves, then Leaves.size(); {0}: no part.
  std::vector<std::uint64_t> Starts{ 0 };
  std::uint64_t EndKey = 0; ///< the Morton key just past the last leaf (the next part's, or the octree's end)
  std::uint64_t LeavesBefore = 0, OctreeLeaves = 0; ///< leaves before the run, and in the octree (for progress)
  std::int32_t SlabFirst = 0, SlabEnd = 0;          ///< the slices of the image it needs (LabelImage::Slab)
  /// LabelImage::SliceHash of those slices in rank 0's image: a process that read its slab itself
  /// checks that it holds the same labels.
  std::uint64_t SlabHash = 0;
};

std::vector<char> PackPartAssignment(const PartAssignment& assignment);
PartAssignment UnpackPartAssignment(const std::vector<char>& bytes);

} // namespace labelmesher

#endif
