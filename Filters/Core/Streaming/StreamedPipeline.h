// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_StreamedPipeline_h
#define labelmesher_StreamedPipeline_h

/**
 * @file StreamedPipeline.h
 * Mesher and decimator block by block, so that the whole initial mesh never
 * exists: the octree (Algorithm 2) is refined over the whole image, its
 * leaves in Morton order are cut into blocks of about BlockCells initial
 * cells (runs of p4est's order: the unit an MPI rank would take), and each
 * block is filled (Algorithm 3), decimated with its border frozen (Algorithm
 * 4, DecimationScope.h) and released; what is left of it joins the output.
 * Whenever the assembled blocks have grown enough, a border pass decimates
 * them from the vertices they froze at the borders between them, with the
 * frontier towards the leaves still to come frozen; last, the whole assembled
 * mesh is decimated once more. Peak memory is the output plus one block and
 * one frontier, not the initial mesh.
 *
 * Why every guarantee holds (the checks of each merge are today's, on a
 * piece of the mesh):
 *  - a block's border vertices never move, so the blocks stay one conforming
 *    mesh of the box; a merge's checks read only its two vertices' stars,
 *    which for a vertex off the border lie inside the block (the link
 *    condition and the strata are those of the whole mesh there);
 *  - h(M,I) is checked per merged face against the whole image boundary;
 *  - h(I,M): an image face whose neighbourhood (its box grown by h(I,M))
 *    lies in one block is certified and kept by that block; for any other
 *    image face, every cell of the block that comes near it is frozen, so
 *    the mesh faces within h(I,M) of it stay the initial mesh's until the
 *    last pass (a merge only rebuilds its vertex's star, inside the star);
 *  - a border pass is a block whose keys are those of all blocks so far: it
 *    certifies every image face near it, settled or not, before merging;
 *    its input is the output of passes that kept every bound, so it does
 *    not re-check angles and h(M,I) (DecimationScope::InputKept): the last
 *    pass does, on every face;
 *  - the last pass re-checks the assembled mesh from scratch (angles, h(M,I)
 *    of every face, a certificate for every image face) before merging.
 * One block gives exactly DecimateMesh(MeshLabelImage(...)).
 *
 * Parts: the blocks are grouped PartBlocks to a part, the unit one process
 * takes under MPI (PartExchange.h). A part knows nothing of the others: its
 * blocks settle image faces among themselves only, and its border passes
 * cover its own keys. Rank 0 refines the octree, finds the parts and sends
 * every other process the leaves of its parts (PartAssignment); that process
 * reads only the slab of the image they need, and of its boundary only the
 * faces in that slab. Rank 0 joins the parts in order, with border passes
 * between them by the blocks' rule, then runs the last pass. The blocks and
 * parts depend on the image, BlockCells and PartBlocks only, so the mesh is
 * the same on any number of threads and of processes; with another BlockCells
 * or PartBlocks it differs (borders elsewhere).
 */

#include "Decimation/MeshDecimator.h"
#include "MesherParameters.h"
#include "Support/LabelImage.h"
#include "Support/ProgressObserver.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace labelmesher
{

class PartExchange;

/// Initial cells per block by default: about 150 MB of working memory.
constexpr std::size_t kDefaultBlockCells = 1000000;
/// Blocks per part by default.
constexpr std::size_t kDefaultPartBlocks = 2;

struct StreamingParameters
{
  /// A block is closed once its leaves made this many initial cells (0: one
  /// block, the whole mesh at once).
  std::size_t BlockCells = kDefaultBlockCells;
  /// Border passes: once the assembled blocks hold a quarter of BlockCells
  /// cells and twice as many as after the previous border pass, they are
  /// decimated from what they froze at the borders between them. Off, only
  /// the last pass does that (all borders held until the end).
  bool BorderPasses = true;
  /// For tests only: off, nothing is frozen near image faces that cross a
  /// block border (unsound), to show that the tests catch it.
  bool FreezeNearBorders = true;
  /// Blocks per part (0: one part, every block): a part is meshed by one
  /// process, so parts are what several processes share out.
  std::size_t PartBlocks = kDefaultPartBlocks;
};

struct StreamingCounts
{
  std::size_t Leaves = 0;
  std::size_t Parts = 0;
  std::size_t Processes = 1; ///< that meshed parts (with more processes than parts, the others idle)
  std::size_t Blocks = 0;
  std::size_t LargestBlockCells = 0;  ///< initial cells of the largest block
  std::size_t ForegroundCellsBefore = 0; ///< initial cells of a label other than 0
  std::size_t AssembledCells = 0;     ///< cells entering the last pass (0: one block, no last pass)
  std::size_t BorderPasses = 0;       ///< border passes run between blocks
  std::size_t LargestAssembledCells = 0; ///< the most cells the assembled blocks held (a border pass's or the last pass's input)
  std::size_t MergesInBlocks = 0;     ///< merges done before the last pass (in the blocks and the border passes)
};

/// Which process meshed which part of the box: part p covers the Morton keys
/// [StartKeys[p], StartKeys[p + 1]) (the last to the end) and was meshed by
/// Owners[p]. Empty for a run on one process.
struct PartMap
{
  int Dimension = 3;
  int Depth = 0; ///< of the octree: keys of voxels in [0, 2^Depth)^Dimension
  std::vector<std::uint64_t> StartKeys;
  std::vector<int> Owners;
};

/// Per cell of `mesh` (points in index space, as DecimationResult::Mesh): the
/// process that meshed the part its centroid's voxel lies in. A cell merged
/// across a seam goes to one side. All 0 for an empty map.
std::vector<std::int32_t> CellProcesses(const SimplexMesh& mesh, const PartMap& parts);

struct StreamedResult
{
  DecimationResult Decimated;
  StreamingCounts Streaming;
  /// False on the processes other than rank 0 of a run shared out over
  /// several: they sent their parts to rank 0 and hold no mesh.
  bool HoldsMesh = true;
  /// On rank 0 of a run shared out over several processes: who meshed what.
  PartMap Parts;
};

/// Where a process other than rank 0 of a shared-out run takes its part of the
/// image from: the slices [first, end) along the last axis (z in 3D, y in 2D)
/// as LabelImage::Slab makes them, or a LabelImage holding at least those.
using SlabSource = std::function<LabelImage(int first, int end)>;

/// Meshes `image` with `mesher` and decimates with `decimation` block by
/// block. Throws std::invalid_argument for bad input or parameters (as
/// MeshLabelImage and DecimateMesh) and AbortRequested when `observer` says stop.
/// With `exchange` of more than one rank, every process passes the same
/// parameters and rank 0 the whole image; each meshes the parts it owns
/// (consecutive parts to a process), rank 0 receives the others' and returns
/// the mesh, the others return none (HoldsMesh false). A process other than
/// rank 0 reads only the slab of the image its parts need: from `slabs` when
/// given (then `image` is not read and may be empty), else copied from `image`. A process that fails tells rank 0,
/// which throws std::runtime_error naming it ("process R of N: reason")
/// after taking every part still on its way; rank 0 looks for such a notice
/// whenever it reports progress, so it stops then, not when it reaches the
/// failed process's part.
StreamedResult MeshAndDecimate(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming = {},
  const ProgressObserver& observer = {}, PartExchange* exchange = nullptr, const SlabSource& slabs = {});

} // namespace labelmesher

#endif
