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

#include <algorithm>
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

  SimplexMesh Mesh;
  std::vector<std::uint8_t> Offered; ///< per vertex of Mesh

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

} // namespace

StreamedResult MeshAndDecimate(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming, const ProgressObserver& observer)
{
  const int dimension = image.Dimension();
  ValidateDecimationParameters(dimension, decimation);
  StreamedResult result;
  DecimationResult& out = result.Decimated;
  std::vector<StageTiming> timings;
  StageClock clock(timings);

  // The octree over the whole image: small beside the mesh (one record per leaf).
  const ProgressObserver octreeProgress{ [&](const std::string& stage, double f) {
    return observer.Report(stage, 0.25 * f);
  } };
  const MesherOctree octree = RefineOctree(image, mesher, octreeProgress, clock);
  const std::vector<OctreeLeaf>& leaves = octree.Leaves;
  result.Streaming.Leaves = leaves.size();
  for (std::size_t i = 1; i < leaves.size(); ++i)
    if (VoxelKey(leaves[i].Box.Origin, dimension, octree.Depth) <=
      VoxelKey(leaves[i - 1].Box.Origin, dimension, octree.Depth))
      throw std::logic_error("the octree's leaves are not in Morton order");

  const ImageBoundary boundary(image);
  const std::vector<VoxelBox> near =
    FaceNeighbourhoods(boundary, decimation.ImageToMeshDistance, dimension, octree.Depth);
  const std::int32_t extent = 2 * (std::int32_t(1) << octree.Depth);
  const Lattice boxLow{ -1, -1, dimension == 2 ? 0 : -1 };
  const Lattice boxHigh{ extent - 1, extent - 1, dimension == 2 ? 0 : extent - 1 };
  const PieceContext pieces{ image, boundary, near, octree.Depth, boxLow, boxHigh, streaming.FreezeNearBorders };
  clock.Finish("block plan");

  BlockAssembly assembly(dimension);
  const std::size_t minimumBorderPass = std::max<std::size_t>(1, streaming.BlockCells / 4);
  std::size_t nextBorderPass = minimumBorderPass;
  // Per image face: certified by a finished block (its certificate lies in
  // cells no later block changes), or selected for the block under way.
  std::vector<std::uint8_t> settled(near.size(), 0), selected(near.size(), 0);
  const double blocksStart = 0.15, blocksShare = 0.7;
  for (std::size_t first = 0; first < leaves.size();)
  {
    ReleaseFreedMemory(); // the previous block's and border pass's
    // Fill leaves until the block holds BlockCells cells.
    const double start = blocksStart + blocksShare * double(first) / double(leaves.size());
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
    const bool whole = first == 0 && last == leaves.size();
    const KeyRange keys = LeafRunKeys(leaves, first, last, dimension, octree.Depth);
    ++result.Streaming.Blocks;
    result.Streaming.LargestBlockCells = std::max(result.Streaming.LargestBlockCells, assembler.NumberOfCells());
    clock.Finish("fill");

    // The block certifies the image faces near it that no earlier block
    // did; around those it cannot (their certificates lie beyond its
    // border), its cells are frozen.
    for (std::size_t f = 0; f < near.size(); ++f)
      selected[f] = !settled[f] && keys.MayMeet(near[f]);
    SimplexMesh filled = assembler.Release();
    result.Streaming.ForegroundCellsBefore += static_cast<std::size_t>(
      std::count_if(filled.Materials.begin(), filled.Materials.end(), [](std::int32_t m) { return m != 0; }));
    DecimationScope scope;
    scope.ImageFaces = &selected;
    scope.FreezeNear = [&](const EditableMesh& mesh, const std::vector<std::uint8_t>& uncertified,
                         std::vector<std::uint8_t>& frozen) {
      const BoxBinsByVoxel around =
        SettleCertified(near, selected, uncertified, streaming.FreezeNearBorders, settled);
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
          FreezeCellsNear(mesh, around, i == first ? 0 : cellEnd[i - first - 1], cellEnd[i - first], octree.Depth,
            frozen);
    };
    if (whole)
      scope.FreezeNear = nullptr; // one block certifies every image face, or the input is wrong
    clock.Finish("block plan");

    EditableMesh block(std::move(filled), boxLow, boxHigh);
    const double share = blocksShare * double(last - first) / double(leaves.size());
    DecimateInScope(image, boundary, block, decimation, scope, observer, start, whole ? 0.95 - start : share,
      out.Counts, clock);
    if (whole)
    {
      FinishDecimation(block, out);
      clock.Finish("decimation output");
      out.Timings = Coalesced(timings);
      observer.Report("decimation done", 1.0);
      return result;
    }
    // scope.Frozen now holds every vertex the block froze, its border's included.
    assembly.Add(block, scope.Frozen);
    first = last;
    if (first < leaves.size() && streaming.BorderPasses && assembly.Mesh.NumberOfCells() >= nextBorderPass)
    {
      // The blocks so far cover the keys [0, End): what they froze at the
      // borders between them can be resolved now, so that the assembled mesh
      // is the output so far and one frontier, not every block's border zone.
      // Doubling the threshold each time keeps the passes' merges within
      // about twice the last pass's; each pass also re-certifies the image
      // faces of all blocks so far (Cassini 1024: 7 passes, 71 of 577 s).
      result.Streaming.LargestAssembledCells =
        std::max(result.Streaming.LargestAssembledCells, assembly.Mesh.NumberOfCells());
      const double at = blocksStart + blocksShare * double(first) / double(leaves.size());
      const std::size_t passFrom = timings.size();
      DecimateAssembled(pieces, LeafRunKeys(leaves, 0, first, dimension, octree.Depth), decimation, settled,
        assembly, observer, at, out.Counts, clock);
      PrefixStages(timings, passFrom, "border passes: ");
      ++result.Streaming.BorderPasses;
      nextBorderPass = std::max(minimumBorderPass, 2 * assembly.Mesh.NumberOfCells());
    }
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
  observer.Report("decimation done", 1.0);
  return result;
}

} // namespace labelmesher
