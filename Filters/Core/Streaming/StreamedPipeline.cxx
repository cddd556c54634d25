// SPDX-License-Identifier: GPL-2.0-or-later
// Fill and decimate block by block, border frozen, then the assembled mesh once more.
#include "Streaming/StreamedPipeline.h"

#include "Decimation/DecimationScope.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/ImageBoundary.h"
#include "Fill/LeafFill.h"
#include "Fill/MeshAssembler.h"
#include "LabelOctreeMesher.h"
#include "Streaming/BlockPlan.h"
#include "Streaming/MeshPart.h"
#include "Streaming/PartExchange.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#if defined(__GLIBC__) // defined by <features.h>, which the standard headers above include
#include <malloc.h>
#endif

namespace labelmesher
{
namespace
{

/// Beyond h(I,M), how far (voxels) an image face's neighbourhood reaches: more
/// than ImageBoundaryAnchors' own margin, so that no face it certifies with
/// lies outside.
constexpr double kNeighbourhoodMargin = 0.01;

/// The neighbourhood of every image face: its box grown by h(I,M).
std::vector<VoxelBox> FaceNeighbourhoods(const ImageBoundary& boundary, double h, int dimension, int depth)
{
  std::vector<VoxelBox> boxes(boundary.Faces().size());
  for (std::size_t f = 0; f < boxes.size(); ++f)
  {
    const ConvexPiece piece = boundary.Piece(f);
    std::array<double, 3> lo{ piece.Points[0][0], piece.Points[0][1], piece.Points[0][2] }, hi = lo;
    for (int c = 1; c < piece.Count; ++c)
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], piece.Points[c][a]);
        hi[a] = std::max(hi[a], piece.Points[c][a]);
      }
    boxes[f] = GrownVoxelBox(lo, hi, h + kNeighbourhoodMargin, dimension, depth);
  }
  return boxes;
}

/// Voxel boxes binned by cubes of kBin voxels, only where there are some.
class BoxBinsByVoxel
{
public:
  static constexpr int kBin = 8;
  explicit BoxBinsByVoxel(const std::vector<VoxelBox>& boxes)
    : Boxes(boxes)
  {
  }
  void Add(std::uint32_t box)
  {
    const VoxelBox& b = Boxes[box];
    for (int z = b.Low[2] / kBin; z <= b.High[2] / kBin; ++z)
      for (int y = b.Low[1] / kBin; y <= b.High[1] / kBin; ++y)
        for (int x = b.Low[0] / kBin; x <= b.High[0] / kBin; ++x)
          Bins[Key(x, y, z)].push_back(box);
  }
  bool Empty() const { return Bins.empty(); }
  /// Some added box meets `leaf`.
  bool Meets(const LeafBox& leaf) const
  {
    VoxelBox box;
    for (int a = 0; a < 3; ++a)
    {
      box.Low[a] = leaf.Origin[a];
      box.High[a] = leaf.Origin[a] + (a < leaf.Dimension ? leaf.Size - 1 : 0);
    }
    return Meets(box);
  }
  /// Some added box meets `box`.
  bool Meets(const VoxelBox& box) const
  {
    bool meets = false;
    ForEachMeeting(box, [&](std::uint32_t) { meets = true; });
    return meets;
  }
  /// Calls visit(box) for every added box that meets `b` (a box may come more than once).
  template <typename Visit>
  void ForEachMeeting(const VoxelBox& b, Visit&& visit) const
  {
    for (int z = b.Low[2] / kBin; z <= b.High[2] / kBin; ++z)
      for (int y = b.Low[1] / kBin; y <= b.High[1] / kBin; ++y)
        for (int x = b.Low[0] / kBin; x <= b.High[0] / kBin; ++x)
        {
          const auto it = Bins.find(Key(x, y, z));
          if (it != Bins.end())
            for (std::uint32_t box : it->second)
              if (Overlap(Boxes[box], b))
                visit(box);
        }
  }

private:
  static bool Overlap(const VoxelBox& a, const VoxelBox& b)
  {
    for (int k = 0; k < 3; ++k)
      if (a.Low[k] > b.High[k] || b.Low[k] > a.High[k])
        return false;
    return true;
  }
  static std::uint64_t Key(int x, int y, int z)
  {
    return static_cast<std::uint64_t>(x) | (static_cast<std::uint64_t>(y) << 21) | (static_cast<std::uint64_t>(z) << 42);
  }
  const std::vector<VoxelBox>& Boxes;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> Bins;
};

/// After a run's certificates: the selected image faces it certified are
/// settled (a later block need not select them), and the neighbourhoods of
/// those it could not certify are returned, binned, for freezing (none when
/// `freeze` is off, which is unsound: tests only).
BoxBinsByVoxel SettleCertified(const std::vector<VoxelBox>& near, const std::vector<std::uint8_t>& selected,
  const std::vector<std::uint8_t>& uncertified, bool freeze, std::vector<std::uint8_t>& settled)
{
  BoxBinsByVoxel around(near);
  for (std::size_t f = 0; f < near.size(); ++f)
  {
    if (selected[f])
      settled[f] = !uncertified[f];
    if (uncertified[f] && freeze)
      around.Add(static_cast<std::uint32_t>(f));
  }
  return around;
}

/// Freezes (in `frozen`) the vertices of every alive cell of `mesh` among
/// [begin, end) whose box meets a box of `around`.
void FreezeCellsNear(const EditableMesh& mesh, const BoxBinsByVoxel& around, std::size_t begin, std::size_t end,
  int depth, std::vector<std::uint8_t>& frozen)
{
  const int nv = mesh.VerticesPerCell();
  for (std::size_t c = begin; c < end; ++c)
  {
    if (!mesh.CellAlive[c])
      continue;
    std::array<double, 3> lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = hi[a] = mesh.Position[mesh.Cells[c][0]][a] / 2.0;
      for (int k = 1; k < nv; ++k)
      {
        lo[a] = std::min(lo[a], mesh.Position[mesh.Cells[c][k]][a] / 2.0);
        hi[a] = std::max(hi[a], mesh.Position[mesh.Cells[c][k]][a] / 2.0);
      }
    }
    if (around.Meets(GrownVoxelBox(lo, hi, 0.0, mesh.Dimension, depth)))
      for (int k = 0; k < nv; ++k)
        frozen[static_cast<std::size_t>(mesh.Cells[c][k])] = 1;
  }
}

/// The decimated blocks joined into one mesh: border vertices, which every
/// block sharing them kept in place, become one vertex by their position.
class BlockAssembly
{
public:
  explicit BlockAssembly(int dimension) { Mesh.Dimension = dimension; }

  /// Appends the alive cells of `block`; vertices of cells that touch a
  /// `frozen` vertex are offered again in the last pass.
  void Add(const EditableMesh& block, const std::vector<std::uint8_t>& frozen)
  {
    std::vector<std::int64_t> id(block.Position.size(), -1);
    const int nv = block.VerticesPerCell();
    for (std::size_t c = 0; c < block.Cells.size(); ++c)
    {
      if (!block.CellAlive[c])
        continue;
      bool touchesFrozen = false;
      for (int i = 0; i < nv; ++i)
      {
        const VertexId v = block.Cells[c][i];
        touchesFrozen = touchesFrozen || frozen[v];
        if (id[v] < 0)
          id[v] = VertexOf(block.Position[v], block.Border[v] != 0);
        Mesh.Connectivity.push_back(id[v]);
      }
      Mesh.Materials.push_back(block.Labels[c]);
      if (touchesFrozen)
        for (int i = 0; i < nv; ++i)
          Offered[static_cast<std::size_t>(id[block.Cells[c][i]])] = 1;
    }
  }

  /// Appends a part's cells; its border vertices are shared with the parts before it by position.
  void Add(const MeshPart& part)
  {
    std::vector<std::int64_t> id(part.Mesh.Points.size());
    for (std::size_t v = 0; v < id.size(); ++v)
    {
      const Point3& x = part.Mesh.Points[v];
      const Lattice p{ static_cast<std::int32_t>(std::lround(2 * x[0])), static_cast<std::int32_t>(std::lround(2 * x[1])),
        static_cast<std::int32_t>(std::lround(2 * x[2])) };
      id[v] = VertexOf(p, part.Border[v] != 0);
      Offered[static_cast<std::size_t>(id[v])] |= part.Offered[v];
    }
    for (std::int64_t v : part.Mesh.Connectivity)
      Mesh.Connectivity.push_back(id[static_cast<std::size_t>(v)]);
    Mesh.Materials.insert(Mesh.Materials.end(), part.Mesh.Materials.begin(), part.Mesh.Materials.end());
  }

  /// What is left once the assembly is handed on as a part.
  void MoveTo(MeshPart& part)
  {
    part.Mesh = std::move(Mesh);
    part.Offered = std::move(Offered);
    part.Border = std::move(Border);
    *this = BlockAssembly(part.Mesh.Dimension);
  }

  SimplexMesh Mesh;
  std::vector<std::uint8_t> Offered; ///< per vertex of Mesh
  /// Per vertex of Mesh: on a border of the blocks it came from (every
  /// vertex on the assembly's own border is; some inside it too).
  std::vector<std::uint8_t> Border;

private:
  std::int64_t VertexOf(const Lattice& p, bool shared)
  {
    const std::int64_t next = static_cast<std::int64_t>(Mesh.Points.size());
    if (shared)
    {
      // Doubled-lattice coordinates lie in [-1, 2^22): shifted by one, 23 bits each.
      const std::uint64_t key = static_cast<std::uint64_t>(p[0] + 1) | (static_cast<std::uint64_t>(p[1] + 1) << 23) |
        (static_cast<std::uint64_t>(p[2] + 1) << 46);
      const auto [it, inserted] = Shared.try_emplace(key, next);
      if (!inserted)
        return it->second;
    }
    Mesh.Points.push_back({ p[0] / 2.0, p[1] / 2.0, Mesh.Dimension == 2 ? 0.0 : p[2] / 2.0 });
    Offered.push_back(0);
    Border.push_back(shared ? 1 : 0);
    return next;
  }
  std::unordered_map<std::uint64_t, std::int64_t> Shared;
};

/// The stage times with the entries of one name (one per block) added up, in order of first appearance.
std::vector<StageTiming> Coalesced(const std::vector<StageTiming>& timings)
{
  std::vector<StageTiming> total;
  for (const StageTiming& t : timings)
  {
    auto it = std::find_if(total.begin(), total.end(), [&](const StageTiming& x) { return x.Stage == t.Stage; });
    if (it == total.end())
      total.push_back(t);
    else
      it->Seconds += t.Seconds;
  }
  return total;
}

/// Hands the heap's free pages back to the system once a block is released:
/// glibc keeps them otherwise, and the next block's arrays, of other sizes,
/// do not fit the holes, so the resident size ratchets up block after block.
void ReleaseFreedMemory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

void AddMergeCounts(DecimationCounts& total, const DecimationCounts& part)
{
  total.Offers += part.Offers;
  total.Merges += part.Merges;
  total.RejectedByQuality += part.RejectedByQuality;
  total.RejectedByTopology += part.RejectedByTopology;
  total.RejectedByFidelity += part.RejectedByFidelity;
  total.Relocations += part.Relocations;
}

/// What every pass over a piece of the mesh shares: the image, its boundary
/// and every face's neighbourhood, the octree's depth and the whole box (on
/// the doubled lattice).
struct PieceContext
{
  const LabelImage& Image;
  const ImageBoundary& Boundary;
  const std::vector<VoxelBox>& Near;
  int Depth;
  Lattice BoxLow, BoxHigh;
  bool FreezeNearBorders;
};

/// Renames the stage times from index `from` on as `prefix` + their name.
void PrefixStages(std::vector<StageTiming>& timings, std::size_t from, const std::string& prefix)
{
  for (std::size_t t = from; t < timings.size(); ++t)
    timings[t].Stage = prefix + timings[t].Stage;
}

/// A border pass: decimates the assembled blocks, which cover the Morton keys
/// `keys` (a prefix of the octree), from the vertices they froze, with the
/// frontier (faces towards leaves not filled yet) frozen. It certifies every
/// image face whose neighbourhood meets `keys` (settled ones too: its merges
/// may touch their certificates) and freezes every cell near those it cannot
/// (their neighbourhoods cross the frontier), as a block does. No relocation:
/// the last pass relocates every vertex. The assembly is replaced by the
/// result, with what this pass froze offered again later.
void DecimateAssembled(const PieceContext& context, const KeyRange& keys, const DecimationParameters& decimation,
  std::vector<std::uint8_t>& settled, BlockAssembly& assembly, const ProgressObserver& observer, double at,
  DecimationCounts& counts, StageClock& clock)
{
  const std::vector<VoxelBox>& near = context.Near;
  std::vector<std::uint8_t> selected(near.size(), 0);
  for (std::size_t f = 0; f < near.size(); ++f)
    selected[f] = keys.MayMeet(near[f]);
  DecimationScope scope;
  scope.ImageFaces = &selected;
  scope.InputKept = true; // the blocks' or parts' output: the last pass re-checks it
  scope.Offered = std::move(assembly.Offered);
  scope.FreezeNear = [&](const EditableMesh& mesh, const std::vector<std::uint8_t>& uncertified,
                       std::vector<std::uint8_t>& frozen) {
    const BoxBinsByVoxel around = SettleCertified(near, selected, uncertified, context.FreezeNearBorders, settled);
    if (!around.Empty())
      FreezeCellsNear(mesh, around, 0, mesh.Cells.size(), context.Depth, frozen);
  };
  EditableMesh mesh(std::move(assembly.Mesh), context.BoxLow, context.BoxHigh);
  assembly = BlockAssembly(mesh.Dimension);
  DecimationParameters mergesOnly = decimation;
  mergesOnly.RelocateInteriorVertices = false;
  DecimationCounts passCounts;
  DecimateInScope(context.Image, context.Boundary, mesh, mergesOnly, scope, observer, at, 0.0, passCounts, clock);
  AddMergeCounts(counts, passCounts);
  assembly.Add(mesh, scope.Frozen);
}

/// When the assembled blocks (or parts) are due for a border pass: once they
/// hold a quarter of BlockCells cells and twice what the previous pass left.
/// Doubling the threshold keeps the passes' merges within about twice the
/// last pass's.
class BorderPassRule
{
public:
  explicit BorderPassRule(const StreamingParameters& streaming)
    : Enabled(streaming.BorderPasses)
    , Minimum(std::max<std::size_t>(1, streaming.BlockCells / 4))
    , Next(Minimum)
  {
  }
  bool Due(std::size_t assembledCells) const { return Enabled && assembledCells >= Next; }
  void Passed(std::size_t cellsLeft) { Next = std::max(Minimum, 2 * cellsLeft); }

private:
  bool Enabled;
  std::size_t Minimum, Next;
};

/// The leaves a process meshes, in Morton order: every leaf of the octree, or
/// on a process other than rank 0 of a shared-out run the run of its parts
/// (PartAssignment).
struct LeafRun
{
  const std::vector<OctreeLeaf>& Leaves;
  int Dimension, Depth;
  std::uint64_t EndKey;             ///< the key just past the last leaf
  bool EveryLeaf;                   ///< the whole octree: one block of it may be the whole mesh
  std::size_t Before, OctreeLeaves; ///< leaves before the run, and in the octree: for progress only

  /// The keys of leaves [first, last) of the run.
  KeyRange Keys(std::size_t first, std::size_t last) const
  {
    KeyRange range = LeafRunKeys(Leaves, first, last, Dimension, Depth);
    if (last == Leaves.size())
      range.End = EndKey;
    return range;
  }
  /// How far into the octree leaf `leaf` of the run lies, in [0, 1].
  double Progress(std::size_t leaf) const { return double(Before + leaf) / double(std::max<std::size_t>(1, OctreeLeaves)); }
};

/// Where a part ends: the leaf after its last, and whether it was the whole mesh.
struct PartRun
{
  std::size_t End = 0;
  bool Whole = false;
};

/// One part: PartBlocks blocks (every block when 0) from leaf `partFirst` on,
/// each filled, decimated with its border frozen and released, what is left
/// of it joined to `part`, with border passes between them as the blocks
/// grow (their keys from `partFirst` on: the part knows no other). When the
/// part is one block of every leaf, that block is the whole mesh: finished
/// into `whole` instead.
PartRun StreamPart(const PieceContext& context, const LeafRun& run, std::size_t partFirst,
  const DecimationParameters& decimation, const StreamingParameters& streaming, const ProgressObserver& observer,
  MeshPart& part, DecimationResult& whole)
{
  const std::vector<OctreeLeaf>& leaves = run.Leaves;
  const LabelImage& image = context.Image;
  const int dimension = image.Dimension();
  const int depth = context.Depth;
  const std::vector<VoxelBox>& near = context.Near;
  std::vector<StageTiming> timings;
  StageClock clock(timings);
  BlockAssembly assembly(dimension);
  BorderPassRule borderPasses(streaming);
  // Per image face: certified by a finished block of this part (its
  // certificate lies in cells no later block changes), or selected for the
  // block under way.
  std::vector<std::uint8_t> settled(near.size(), 0), selected(near.size(), 0);
  const double blocksStart = 0.15, blocksShare = 0.7;
  std::size_t first = partFirst;
  auto partGoesOn = [&] {
    return first < leaves.size() && (streaming.PartBlocks == 0 || part.Blocks < streaming.PartBlocks);
  };
  while (partGoesOn())
  {
    ReleaseFreedMemory(); // the previous block's and border pass's
    // Fill leaves until the block holds BlockCells cells.
    const double start = blocksStart + blocksShare * run.Progress(first);
    if (!observer.Report("fill", start))
      throw AbortRequested{};
    MeshAssembler assembler(dimension);
    std::vector<std::size_t> cellEnd; // per leaf of the block
    std::size_t last = first;
    while (last < leaves.size() && (streaming.BlockCells == 0 || assembler.NumberOfCells() < streaming.BlockCells))
    {
      FillLeaf(image, leaves[last++], assembler);
      cellEnd.push_back(assembler.NumberOfCells());
    }
    const bool isWhole = run.EveryLeaf && first == 0 && last == leaves.size();
    const KeyRange keys = run.Keys(first, last);
    ++part.Blocks;
    part.LargestBlockCells = std::max(part.LargestBlockCells, assembler.NumberOfCells());
    clock.Finish("fill");

    // The block certifies the image faces near it that no earlier block
    // did; around those it cannot (their certificates lie beyond its
    // border), its cells are frozen.
    for (std::size_t f = 0; f < near.size(); ++f)
      selected[f] = !settled[f] && keys.MayMeet(near[f]);
    SimplexMesh filled = assembler.Release();
    part.ForegroundCellsBefore += static_cast<std::size_t>(
      std::count_if(filled.Materials.begin(), filled.Materials.end(), [](std::int32_t m) { return m != 0; }));
    DecimationScope scope;
    scope.ImageFaces = &selected;
    scope.FreezeNear = [&](const EditableMesh& mesh, const std::vector<std::uint8_t>& uncertified,
                         std::vector<std::uint8_t>& frozen) {
      const BoxBinsByVoxel around =
        SettleCertified(near, selected, uncertified, context.FreezeNearBorders, settled);
      if (around.Empty())
        return;
      // Every cell near such a face stays as it is, so that whatever certified
      // it in the initial mesh still does (a merge rebuilds only the star of
      // the vertex it removes, inside that star). Freezing only the faces of
      // its sides left 3 % more cells on digimouse: the volume around them
      // was merged against a fixed fine interface.
      // Cells lie in their leaves until merged, and none is merged yet: only
      // the cells of leaves near such a face are tested, each by its own box
      // (a cell whose box misses the face's neighbourhood holds no mesh face
      // within h(I,M) of it).
      for (std::size_t i = first; i < last; ++i)
        if (around.Meets(leaves[i].Box))
          FreezeCellsNear(mesh, around, i == first ? 0 : cellEnd[i - first - 1], cellEnd[i - first], depth, frozen);
    };
    if (isWhole)
      scope.FreezeNear = nullptr; // one block certifies every image face, or the input is wrong
    clock.Finish("block plan");

    EditableMesh block(std::move(filled), context.BoxLow, context.BoxHigh);
    const double share = blocksShare * (run.Progress(last) - run.Progress(first));
    DecimateInScope(image, context.Boundary, block, decimation, scope, observer, start,
      isWhole ? 0.95 - start : share, part.Counts, clock);
    if (isWhole)
    {
      whole.Counts = part.Counts;
      FinishDecimation(block, whole);
      clock.Finish("decimation output");
      part.Timings = std::move(timings);
      return { last, true };
    }
    // scope.Frozen now holds every vertex the block froze, its border's included.
    assembly.Add(block, scope.Frozen);
    first = last;
    if (partGoesOn() && borderPasses.Due(assembly.Mesh.NumberOfCells()))
    {
      // The part's blocks so far cover the keys [part's first, End): what
      // they froze at the borders between them can be resolved now, so that
      // the assembled mesh is the output so far and one frontier, not every
      // block's border zone (BorderPassRule). Each pass also
      // re-certifies the image faces of all blocks so far (Cassini 1024: 7
      // passes, 71 of 577 s).
      part.LargestAssembledCells = std::max(part.LargestAssembledCells, assembly.Mesh.NumberOfCells());
      const double at = blocksStart + blocksShare * run.Progress(first);
      const std::size_t passFrom = timings.size();
      DecimateAssembled(context, run.Keys(partFirst, first), decimation, settled,
        assembly, observer, at, part.Counts, clock);
      PrefixStages(timings, passFrom, "border passes: ");
      ++part.BorderPasses;
      borderPasses.Passed(assembly.Mesh.NumberOfCells());
    }
  }
  part.LargestAssembledCells = std::max(part.LargestAssembledCells, assembly.Mesh.NumberOfCells());
  part.Timings = Coalesced(timings);
  assembly.MoveTo(part);
  return { first, false };
}

/// The leaf where each part starts, then leaves.size(): the blocks cut as
/// StreamPart cuts them (a block closes once its leaves made BlockCells
/// cells), PartBlocks to a part, so that every process finds the same parts.
/// It fills every leaf once, one block at a time, and keeps nothing.
std::vector<std::size_t> PartStarts(const LabelImage& image, const std::vector<OctreeLeaf>& leaves,
  const StreamingParameters& streaming)
{
  std::vector<std::size_t> starts{ 0 };
  if (streaming.PartBlocks != 0 && streaming.BlockCells != 0)
  {
    std::size_t blocks = 0;
    for (std::size_t first = 0; first < leaves.size();)
    {
      MeshAssembler assembler(image.Dimension());
      while (first < leaves.size() && assembler.NumberOfCells() < streaming.BlockCells)
        FillLeaf(image, leaves[first++], assembler);
      if (++blocks % streaming.PartBlocks == 0 && first < leaves.size())
        starts.push_back(first);
    }
  }
  starts.push_back(leaves.size());
  return starts;
}

/// The process that meshes part `part` of `parts`: consecutive parts to a
/// process, each part to the rank its middle falls to, so that when they do
/// not divide evenly rank 0, which also joins them, takes fewer. Part 0 is
/// always rank 0's (it may be the whole mesh).
int OwnerOf(std::size_t part, std::size_t parts, int ranks)
{
  if (part == 0)
    return 0;
  return static_cast<int>((2 * part + 1) * static_cast<std::size_t>(ranks) / (2 * parts));
}

/// How many processes mesh at least one of `parts` parts (the others idle).
std::size_t ProcessesWithParts(std::size_t parts, int ranks)
{
  std::size_t owners = 0;
  for (std::size_t p = 0; p < parts; ++p)
    owners += p == 0 || OwnerOf(p, parts, ranks) != OwnerOf(p - 1, parts, ranks); // consecutive parts to a process
  return owners;
}

PartMap MapOfParts(const std::vector<OctreeLeaf>& leaves, const std::vector<std::size_t>& starts, int dimension,
  int depth, int ranks)
{
  PartMap map;
  map.Dimension = dimension;
  map.Depth = depth;
  const std::size_t parts = starts.size() - 1;
  for (std::size_t p = 0; p < parts; ++p)
  {
    map.StartKeys.push_back(VoxelKey(leaves[starts[p]].Box.Origin, dimension, depth));
    map.Owners.push_back(OwnerOf(p, parts, ranks));
  }
  return map;
}

std::string Reason(std::exception_ptr error)
{
  try
  {
    std::rethrow_exception(error);
  }
  catch (const AbortRequested&)
  {
    return "stopped";
  }
  catch (const std::bad_alloc&)
  {
    return "out of memory";
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  catch (...)
  {
    return "an unknown error";
  }
}

/// A failure every rank has heard of (PartExchange::Agree, or rank 0's
/// in place of an assignment): not sent again.
struct AgreedFailure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// On rank 0: what process `rank` meshes, its parts being the consecutive run
/// OwnerOf gives it (none: an assignment of no part). Its slab reaches beyond
/// its leaves by what every query near its cells reads (ImageBoundary::SlabMargin).
PartAssignment AssignmentOf(int rank, int ranks, const LabelImage& image, const MesherOctree& octree,
  const std::vector<std::size_t>& starts, const DecimationParameters& decimation)
{
  PartAssignment a;
  a.ImageDimensions = image.Dimensions;
  a.Depth = octree.Depth;
  a.OctreeLeaves = octree.Leaves.size();
  const std::size_t parts = starts.size() - 1;
  std::size_t from = parts, to = parts;
  for (std::size_t p = 0; p < parts; ++p)
    if (OwnerOf(p, parts, ranks) == rank)
    {
      from = std::min(from, p);
      to = p + 1;
    }
  if (from == parts)
    return a;
  const std::vector<OctreeLeaf>& leaves = octree.Leaves;
  a.Leaves.assign(leaves.begin() + static_cast<std::ptrdiff_t>(starts[from]),
    leaves.begin() + static_cast<std::ptrdiff_t>(starts[to]));
  a.Starts.clear();
  for (std::size_t p = from; p <= to; ++p)
    a.Starts.push_back(starts[p] - starts[from]);
  a.LeavesBefore = starts[from];
  a.EndKey = LeafRunKeys(leaves, starts[from], starts[to], image.Dimension(), octree.Depth).End;
  const int axis = image.SlabAxis();
  const int margin =
    ImageBoundary::SlabMargin(std::max(decimation.ImageToMeshDistance, decimation.MeshToImageDistance));
  int low = image.Dimensions[static_cast<std::size_t>(axis)], high = 0;
  for (const OctreeLeaf& leaf : a.Leaves)
  {
    // The octree's cube reaches beyond a box-shaped image: a leaf farther than the margin from
    // the image reads none of its voxels (they are background there), so it needs no slice.
    bool reads = true;
    for (std::size_t d = 0; d < static_cast<std::size_t>(image.Dimension()); ++d)
      reads = reads && leaf.Box.Origin[d] - margin < image.Dimensions[d] && leaf.Box.Origin[d] + leaf.Box.Size + margin > 0;
    if (!reads)
      continue;
    low = std::min(low, leaf.Box.Origin[static_cast<std::size_t>(axis)]);
    high = std::max(high, leaf.Box.Origin[static_cast<std::size_t>(axis)] + leaf.Box.Size);
  }
  const int slices = image.Dimensions[static_cast<std::size_t>(axis)];
  if (low >= high)
  {
    a.SlabFirst = a.SlabEnd = 0; // no leaf reads the image: an empty slab
  }
  else
  {
    a.SlabFirst = std::clamp(low - margin, 0, slices);
    a.SlabEnd = std::clamp(high + margin, a.SlabFirst, slices);
  }
  a.SlabHash = image.SliceHash(a.SlabFirst, a.SlabEnd);
  return a;
}

/// A rank other than 0: its assignment from rank 0, its slab of the image,
/// and its parts, meshed and sent to rank 0 in order.
void SendParts(const LabelImage& image, const SlabSource& slabs, const DecimationParameters& decimation,
  const StreamingParameters& streaming, const ProgressObserver& observer, PartExchange& exchange, StageClock& clock)
{
  const PartAssignment assigned = UnpackPartAssignment(exchange.ReceiveAssignment());
  if (assigned.Failed)
    throw AgreedFailure(ProcessFailure(0, exchange.Ranks(), assigned.Reason));
  if (assigned.Leaves.empty())
  {
    exchange.Flush();
    return;
  }
  const LabelImage slab =
    slabs ? slabs(assigned.SlabFirst, assigned.SlabEnd) : LabelImage::Slab(image, assigned.SlabFirst, assigned.SlabEnd);
  if (slab.Dimensions != assigned.ImageDimensions || slab.SlabFirst() > assigned.SlabFirst ||
    slab.SlabEnd() < assigned.SlabEnd)
    throw std::logic_error("the slab of the image given is not the one this process's parts need");
  // A process that read its slab itself may have been given another file than rank 0.
  if (slab.SliceHash(assigned.SlabFirst, assigned.SlabEnd) != assigned.SlabHash)
    throw std::runtime_error("it was given another image than process 0 (their labels differ in slices " +
      std::to_string(assigned.SlabFirst) + " to " + std::to_string(assigned.SlabEnd - 1) +
      " along the last axis): every process must mesh the same");
  const int dimension = slab.Dimension(), depth = assigned.Depth;
  ValidateDecimationParameters(dimension, decimation);
  const ImageBoundary boundary(slab);
  const std::vector<VoxelBox> near = FaceNeighbourhoods(boundary, decimation.ImageToMeshDistance, dimension, depth);
  const std::int32_t extent = 2 * (std::int32_t(1) << depth);
  const PieceContext context{ slab, boundary, near, depth, { -1, -1, dimension == 2 ? 0 : -1 },
    { extent - 1, extent - 1, dimension == 2 ? 0 : extent - 1 }, streaming.FreezeNearBorders };
  const LeafRun run{ assigned.Leaves, dimension, depth, assigned.EndKey, false,
    static_cast<std::size_t>(assigned.LeavesBefore), static_cast<std::size_t>(assigned.OctreeLeaves) };
  clock.Finish("block plan");
  for (std::size_t p = 0; p + 1 < assigned.Starts.size(); ++p)
  {
    PartMessage message;
    DecimationResult unused;
    const PartRun ran = StreamPart(context, run, assigned.Starts[p], decimation, streaming, observer, message.Part, unused);
    if (ran.Whole || ran.End != assigned.Starts[p + 1])
      throw std::logic_error("a part ended at another leaf than the plan's");
    exchange.Send(PackPartMessage(message));
  }
  exchange.Flush();
}

/// A rank other than 0 that failed: rank 0 takes this in place of the next
/// part it expects from it.
void SendFailure(PartExchange& exchange, std::exception_ptr error)
{
  PartMessage failure;
  failure.Failed = true;
  failure.Reason = Reason(error);
  exchange.Notify(failure.Reason);
  exchange.Send(PackPartMessage(failure));
  exchange.Flush();
}

/// A part's counts into the run's (its stage times are the meshing process's own: rank 0 adds
/// those of its parts, and the others' wait shows as its "waiting for other processes").
void AddPartCounts(StreamedResult& result, const MeshPart& part)
{
  DecimationCounts& total = result.Decimated.Counts;
  AddMergeCounts(total, part.Counts);
  total.CellsBefore += part.Counts.CellsBefore;
  total.VerticesBefore += part.Counts.VerticesBefore;
  total.FrozenVertices += part.Counts.FrozenVertices;
  StreamingCounts& s = result.Streaming;
  ++s.Parts;
  s.Blocks += part.Blocks;
  s.LargestBlockCells = std::max(s.LargestBlockCells, part.LargestBlockCells);
  s.ForegroundCellsBefore += part.ForegroundCellsBefore;
  s.BorderPasses += part.BorderPasses;
  s.LargestAssembledCells = std::max(s.LargestAssembledCells, part.LargestAssembledCells);
}

/// What every pass of a run reads: the octree, the image boundary, its
/// faces' neighbourhoods, the box, and with several processes the parts.
struct RunPlan
{
  MesherOctree Octree;
  std::unique_ptr<ImageBoundary> Boundary;
  std::vector<VoxelBox> Near;
  Lattice BoxLow{}, BoxHigh{};
  std::vector<std::size_t> Starts; ///< with several processes; one finds the parts as it goes
};

RunPlan MakeRunPlan(const LabelImage& image, const MesherParameters& mesher, const DecimationParameters& decimation,
  const StreamingParameters& streaming, const ProgressObserver& observer, bool findParts, StageClock& clock)
{
  const int dimension = image.Dimension();
  RunPlan plan;
  const ProgressObserver octreeProgress{ [&](const std::string& stage, double f) {
    return observer.Report(stage, 0.25 * f);
  } };
  plan.Octree = RefineOctree(image, mesher, octreeProgress, clock);
  const std::vector<OctreeLeaf>& leaves = plan.Octree.Leaves;
  const int depth = plan.Octree.Depth;
  for (std::size_t i = 1; i < leaves.size(); ++i)
    if (VoxelKey(leaves[i].Box.Origin, dimension, depth) <= VoxelKey(leaves[i - 1].Box.Origin, dimension, depth))
      throw std::logic_error("the octree's leaves are not in Morton order");
  plan.Boundary = std::make_unique<ImageBoundary>(image);
  plan.Near = FaceNeighbourhoods(*plan.Boundary, decimation.ImageToMeshDistance, dimension, depth);
  const std::int32_t extent = 2 * (std::int32_t(1) << depth);
  plan.BoxLow = { -1, -1, dimension == 2 ? 0 : -1 };
  plan.BoxHigh = { extent - 1, extent - 1, dimension == 2 ? 0 : extent - 1 };
  if (findParts)
    plan.Starts = PartStarts(image, leaves, streaming);
  return plan;
}

/// MeshAndDecimate, whose failures on a rank other than 0 it reports to rank 0.
StreamedResult MeshAndDecimateOrJoin(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming, const ProgressObserver& observer,
  PartExchange* exchange, const SlabSource& slabs)
{
  const int dimension = image.Dimension();
  StreamedResult result;
  DecimationResult& out = result.Decimated;
  std::vector<StageTiming> timings;
  StageClock clock(timings);

  // The octree over the whole image: small beside the mesh (one record per
  // leaf). Rank 0 refines it and finds the parts; the others go on only if
  // it got this far, each with its assignment: its parts' leaves and the
  // slab of the image they need.
  const int ranks = exchange != nullptr ? exchange->Ranks() : 1;
  if (ranks > 1 && exchange->Rank() != 0)
  {
    const std::string failure = exchange->Agree(std::string());
    if (!failure.empty())
      throw AgreedFailure(failure);
    SendParts(image, slabs, decimation, streaming, observer, *exchange, clock);
    result.HoldsMesh = false;
    out.Timings = Coalesced(timings);
    return result;
  }
  RunPlan plan;
  if (ranks > 1)
  {
    std::exception_ptr error;
    try
    {
      ValidateDecimationParameters(dimension, decimation);
      plan = MakeRunPlan(image, mesher, decimation, streaming, observer, true, clock);
    }
    catch (...)
    {
      error = std::current_exception();
    }
    const std::string failure = exchange->Agree(error ? Reason(error) : std::string());
    if (error)
      std::rethrow_exception(error);
    if (!failure.empty())
      throw AgreedFailure(failure);
    // Every assignment is made before any is sent: a failure making them
    // (out of memory) is sent to every process in their place, so none
    // waits for its assignment or meshes parts no one will take.
    std::vector<std::vector<char>> assignments;
    try
    {
      for (int rank = 1; rank < ranks; ++rank)
        assignments.push_back(
          PackPartAssignment(AssignmentOf(rank, ranks, image, plan.Octree, plan.Starts, decimation)));
    }
    catch (...)
    {
      assignments.clear();
      PartAssignment failed;
      failed.Failed = true;
      failed.Reason = Reason(std::current_exception());
      for (int rank = 1; rank < ranks; ++rank)
        exchange->Assign(rank, PackPartAssignment(failed));
      exchange->Flush();
      throw;
    }
    for (int rank = 1; rank < ranks; ++rank)
      exchange->Assign(rank, std::move(assignments[static_cast<std::size_t>(rank - 1)]));
    exchange->Flush();
  }
  else
  {
    ValidateDecimationParameters(dimension, decimation);
    plan = MakeRunPlan(image, mesher, decimation, streaming, observer, false, clock);
  }
  const std::vector<OctreeLeaf>& leaves = plan.Octree.Leaves;
  const std::vector<std::size_t>& starts = plan.Starts;
  const std::vector<VoxelBox>& near = plan.Near;
  result.Streaming.Processes = ranks > 1 ? ProcessesWithParts(starts.size() - 1, ranks) : 1;
  const ImageBoundary& boundary = *plan.Boundary;
  const int depth = plan.Octree.Depth;
  result.Streaming.Leaves = leaves.size();
  const PieceContext pieces{ image, boundary, near, depth, plan.BoxLow, plan.BoxHigh, streaming.FreezeNearBorders };
  const LeafRun everyLeaf{ leaves, dimension, depth, std::uint64_t(1) << (dimension * depth), true, 0, leaves.size() };
  clock.Finish("block plan");

  // Rank 0: the parts, its own meshed here and the others' received, joined
  // in order, with border passes between them as between blocks.
  BlockAssembly assembly(dimension);
  BorderPassRule borderPasses(streaming);
  std::vector<std::uint8_t> settled; // per image face, made in the try below
  std::size_t pending = 0; // the first part not yet taken
  std::vector<std::uint8_t> failed(static_cast<std::size_t>(ranks), 0), noticed(failed);
  // Whenever rank 0 reports progress (between the stages of its own blocks and
  // passes) it looks for another process's failure notice, and stops at once
  // rather than when it reaches that process's part.
  int noticedFirst = -1;
  std::string noticedReason;
  const ProgressObserver watched{ [&](const std::string& stage, double fraction) {
    if (ranks > 1 && noticedFirst < 0)
    {
      const int rank = exchange->PollNotice(noticedReason);
      if (rank > 0 && rank < ranks)
      {
        noticed[static_cast<std::size_t>(rank)] = 1;
        noticedFirst = rank;
        return false;
      }
    }
    return observer.Report(stage, fraction);
  } };
  // A process whose failure came in place of a part also sent a notice: taken, so that it can end.
  auto takeNotice = [&](int rank) {
    if (!noticed[static_cast<std::size_t>(rank)])
    {
      noticed[static_cast<std::size_t>(rank)] = 1;
      exchange->TakeNotice(rank);
    }
  };
  try
  {
    settled.assign(near.size(), 0);
    for (std::size_t first = 0; first < leaves.size(); ++pending)
    {
      MeshPart part;
      const int owner = ranks > 1 ? OwnerOf(pending, starts.size() - 1, ranks) : 0;
      if (owner == 0)
      {
        const PartRun run = StreamPart(pieces, everyLeaf, first, decimation, streaming, watched, part, out);
        if (run.Whole)
        {
          result.Streaming.Parts = 1;
          result.Streaming.Blocks = 1;
          result.Streaming.LargestBlockCells = part.LargestBlockCells;
          result.Streaming.ForegroundCellsBefore = part.ForegroundCellsBefore;
          timings.insert(timings.end(), part.Timings.begin(), part.Timings.end());
          out.Timings = Coalesced(timings);
          observer.Report("decimation done", 1.0);
          return result;
        }
        if (ranks > 1 && run.End != starts[pending + 1])
          throw std::logic_error("a part ended at another leaf than the plan's");
        first = run.End;
        timings.insert(timings.end(), part.Timings.begin(), part.Timings.end());
        clock.Restart(); // the part's stages are in its own timings
      }
      else
      {
        PartMessage message = UnpackPartMessage(exchange->Receive(owner));
        if (message.Failed)
        {
          failed[static_cast<std::size_t>(owner)] = 1;
          takeNotice(owner);
          throw std::runtime_error(ProcessFailure(owner, ranks, message.Reason));
        }
        part = std::move(message.Part);
        first = starts[pending + 1];
        clock.Finish("waiting for other processes");
      }
      AddPartCounts(result, part);
      assembly.Add(part);
      part = MeshPart{};
      if (first < leaves.size() && borderPasses.Due(assembly.Mesh.NumberOfCells()))
      {
        ReleaseFreedMemory();
        result.Streaming.LargestAssembledCells =
          std::max(result.Streaming.LargestAssembledCells, assembly.Mesh.NumberOfCells());
        const std::size_t passFrom = timings.size();
        DecimateAssembled(pieces, LeafRunKeys(leaves, 0, first, dimension, depth), decimation, settled,
          assembly, watched, 0.15 + 0.7 * double(first) / double(leaves.size()), out.Counts, clock);
        PrefixStages(timings, passFrom, "joining parts: ");
        ++result.Streaming.BorderPasses;
        borderPasses.Passed(assembly.Mesh.NumberOfCells());
      }
    }
  }
  catch (...)
  {
    // The other processes send every part they own (or one failure): take
    // them all, so that none waits on a send for ever.
    for (std::size_t p = pending + 1; ranks > 1 && p + 1 < starts.size(); ++p)
    {
      const int owner = OwnerOf(p, starts.size() - 1, ranks);
      if (owner == 0 || failed[static_cast<std::size_t>(owner)])
        continue;
      try
      {
        if (UnpackPartMessage(exchange->Receive(owner)).Failed)
        {
          failed[static_cast<std::size_t>(owner)] = 1;
          takeNotice(owner);
        }
      }
      catch (const std::exception&)
      {
        failed[static_cast<std::size_t>(owner)] = 1;
      }
    }
    if (noticedFirst > 0) // rank 0 stopped for it
      throw std::runtime_error(ProcessFailure(noticedFirst, ranks, noticedReason));
    throw;
  }

  // The assembled mesh, once more from what the blocks froze: its setup
  // re-checks every bound on the whole mesh before any merge.
  result.Streaming.AssembledCells = assembly.Mesh.NumberOfCells();
  result.Streaming.LargestAssembledCells =
    std::max(result.Streaming.LargestAssembledCells, result.Streaming.AssembledCells);
  result.Streaming.MergesInBlocks = out.Counts.Merges;
  ReleaseFreedMemory();
  DecimationScope last;
  last.Offered = std::move(assembly.Offered);
  EditableMesh mesh(std::move(assembly.Mesh));
  DecimationCounts lastCounts;
  const std::size_t lastFrom = timings.size();
  DecimateInScope(image, boundary, mesh, decimation, last, observer, 0.85, 0.1, lastCounts, clock);
  PrefixStages(timings, lastFrom, "last pass: ");
  AddMergeCounts(out.Counts, lastCounts);
  if (!observer.Report("decimation output", 0.95))
    throw AbortRequested{};
  FinishDecimation(mesh, out);
  clock.Finish("decimation output");
  out.Timings = Coalesced(timings);
  if (ranks > 1)
    result.Parts = MapOfParts(leaves, starts, dimension, depth, ranks);
  observer.Report("decimation done", 1.0);
  return result;
}

} // namespace

std::vector<std::int32_t> CellProcesses(const SimplexMesh& mesh, const PartMap& parts)
{
  std::vector<std::int32_t> process(mesh.NumberOfCells(), 0);
  if (parts.StartKeys.empty())
    return process;
  const int nv = mesh.VerticesPerCell();
  const int last = (1 << parts.Depth) - 1;
  for (std::size_t c = 0; c < process.size(); ++c)
  {
    std::array<double, 3> centroid{ 0, 0, 0 };
    for (int k = 0; k < nv; ++k)
      for (int a = 0; a < 3; ++a)
        centroid[a] += mesh.Points[static_cast<std::size_t>(mesh.Cell(c)[k])][a] / nv;
    std::array<int, 3> voxel{ 0, 0, 0 };
    for (int a = 0; a < parts.Dimension; ++a) // voxel centres at integers: its voxel is the nearest
      voxel[a] = std::clamp(static_cast<int>(std::lround(centroid[a])), 0, last);
    const std::uint64_t key = VoxelKey(voxel, parts.Dimension, parts.Depth);
    const auto after = std::upper_bound(parts.StartKeys.begin(), parts.StartKeys.end(), key);
    const std::size_t part = after == parts.StartKeys.begin() ? 0 : std::size_t(after - parts.StartKeys.begin()) - 1;
    process[c] = parts.Owners[part];
  }
  return process;
}

StreamedResult MeshAndDecimate(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming, const ProgressObserver& observer,
  PartExchange* exchange, const SlabSource& slabs)
{
  if (exchange == nullptr || exchange->Ranks() < 2 || exchange->Rank() == 0)
    return MeshAndDecimateOrJoin(image, mesher, decimation, streaming, observer, exchange, slabs);
  try
  {
    return MeshAndDecimateOrJoin(image, mesher, decimation, streaming, observer, exchange, slabs);
  }
  catch (const AgreedFailure&)
  {
    throw; // every rank knows
  }
  catch (const AbortRequested&)
  {
    SendFailure(*exchange, std::current_exception());
    throw;
  }
  catch (...)
  {
    // Whatever stopped this process (bad input, no memory), rank 0 must hear of it; and this
    // process says it in rank 0's words, naming itself (pvbatch prints every process's error).
    const std::exception_ptr error = std::current_exception();
    SendFailure(*exchange, error);
    throw std::runtime_error(ProcessFailure(exchange->Rank(), exchange->Ranks(), Reason(error)));
  }
}

} // namespace labelmesher
