// SPDX-License-Identifier: GPL-2.0-or-later
// The decimation of section 3.1.3 (Algorithm 4): regions in parallel with frozen borders, then the
// borders.
#include "Decimation/MeshDecimator.h"

#include "Decimation/DecimationScope.h"

#include "Decimation/EdgeCollapse.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/FidelityCheck.h"
#include "Decimation/ImageBoundary.h"
#include "Decimation/ImageBoundaryAnchors.h"
#include "Decimation/InteriorRelocation.h"
#include "Decimation/MergeQueue.h"
#include "Decimation/QualityCheck.h"
#include "Decimation/RegionScheduler.h"
#include "Decimation/TopologyCheck.h"
#include "Mesh/MeshBoundary.h"
#include "Support/ParallelChunks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

namespace labelmesher
{
namespace
{


void Validate(const LabelImage& image, const SimplexMesh& mesh, const DecimationParameters& p)
{
  const int d = mesh.Dimension;
  if (d != image.Dimension())
    throw std::invalid_argument(std::string("the mesh is ") + (d == 3 ? "3D" : "2D") + " but the image is " +
      (image.Dimension() == 3 ? "3D" : "2D"));
  ValidateDecimationParameters(d, p);
}

/// The mesh must cover the image (its box is the octree domain) and every
/// cell must have no angle below the bound: merges only keep what is there.
void ValidateAgainstImage(const EditableMesh& mesh, const LabelImage& image, double minimumAngle)
{
  for (int a = 0; a < mesh.Dimension; ++a)
    if (mesh.BoxLow[a] > -1 || mesh.BoxHigh[a] < 2 * image.Dimensions[a] - 1)
      throw std::invalid_argument("the mesh does not cover the image: it is not the mesh of this image");
  std::vector<double> smallest(MaxThreads(), 180.0);
  ParallelChunks(mesh.Cells.size(), 65536, [&](unsigned thread, std::size_t begin, std::size_t end) {
    Lattice p[4];
    for (std::size_t c = begin; c < end; ++c)
    {
      for (int i = 0; i < mesh.VerticesPerCell(); ++i)
        p[i] = mesh.Position[mesh.Cells[c][i]];
      smallest[thread] = std::min(smallest[thread], QualityCheck::SmallestAngle(mesh.Dimension, p));
    }
  });
  const double worst = *std::min_element(smallest.begin(), smallest.end());
  if (worst < minimumAngle - 1e-9)
    throw std::invalid_argument("the input mesh has an angle of " + std::to_string(worst) +
      " degrees, below the minimum angle " + std::to_string(minimumAngle) + " asked for");
}

/// The input must hold h(M, I) already: merges only check the faces they move.
void CheckMeshToImage(const EditableMesh& mesh, const std::vector<InterfaceFace>& faces,
  const ImageBoundary& boundary, const ImageBoundaryAnchors& anchors, double bound)
{
  std::vector<std::int64_t> far(MaxThreads(), -1);
  ParallelChunks(faces.size(), 4096, [&](unsigned thread, std::size_t begin, std::size_t end) {
    FidelityCheck check(boundary, anchors, bound);
    for (std::size_t f = begin; f < end && far[thread] < 0; ++f)
      if (!check.FaceWithinBound(mesh, faces[f]))
        far[thread] = static_cast<std::int64_t>(f);
  });
  for (std::int64_t f : far)
    if (f >= 0)
      throw std::invalid_argument("the input mesh does not hold h(M,I) <= " +
        std::to_string(bound) + " (a face between materials " +
        std::to_string(std::max(faces[f].Low, 0)) + " and " + std::to_string(faces[f].High) +
        " is farther from their image interface): mesh it with this bound or a smaller one first");
}

struct Shared
{
  const DecimationParameters& Parameters;
  EditableMesh& Mesh;
  ImageBoundaryAnchors& Anchors;
  const std::vector<std::uint8_t>& Frozen;
  const RegionScheduler& Regions;
  std::vector<std::uint32_t> Stamps;
  std::vector<std::int64_t> Key; ///< per vertex: a lower bound of its shortest edge (squared)
  /// Per vertex, during the relocation rounds: 1 once InteriorRelocation::TryMove found no better
  /// place for it, back to 0 when its star changes (a neighbour moves, a merge edits its cells).
  /// TryMove depends on the star alone, so a settled vertex would be refused again: skipping it
  /// gives the same moves and the same mesh. Empty outside the rounds.
  std::vector<std::uint8_t> Settled;
  std::atomic<std::size_t> Offered{ 0 };
  std::atomic<std::size_t> Merges{ 0 }; ///< for MaximumMerges
  std::atomic<bool> Abort{ false };
};

/// One thread's checks and scratch.
struct Worker
{
  Worker(const Shared& s, const ImageBoundary& boundary)
    : Quality(s.Mesh.Dimension, s.Parameters.MinimumAngle)
    , Fidelity(boundary, s.Anchors, s.Parameters.MeshToImageDistance)
  {
  }
  QualityCheck Quality;
  TopologyCheck Topology;
  FidelityCheck Fidelity;
  EdgeCollapse Merge;
  DecimationCounts Counts;
  std::vector<VertexId> Neighbours;
  std::vector<std::pair<std::int64_t, VertexId>> Targets;
  std::vector<std::uint32_t> Seen; ///< per mesh vertex: the epoch NeighboursOf saw it in
  std::uint32_t Epoch = 0;
};

std::int64_t SquaredLength(const EditableMesh& mesh, VertexId a, VertexId b)
{
  std::int64_t s = 0;
  for (int k = 0; k < 3; ++k)
  {
    const std::int64_t d = mesh.Position[a][k] - mesh.Position[b][k];
    s += d * d;
  }
  return s;
}

/// The neighbours of v, each once, in the order the cells around v give
/// them (deterministic; stamps instead of a sort).
void NeighboursOf(const EditableMesh& mesh, VertexId v, Worker& w, std::vector<VertexId>& out)
{
  if (w.Seen.size() != mesh.Position.size())
  {
    w.Seen.assign(mesh.Position.size(), 0u);
    w.Epoch = 0;
  }
  if (++w.Epoch == 0)
  {
    std::fill(w.Seen.begin(), w.Seen.end(), 0u);
    w.Epoch = 1;
  }
  out.clear();
  for (CellId c : mesh.CellsOf[v])
    for (int i = 0; i < mesh.VerticesPerCell(); ++i)
    {
      const VertexId x = mesh.Cells[c][i];
      if (x != v && w.Seen[x] != w.Epoch)
      {
        w.Seen[x] = w.Epoch;
        out.push_back(x);
      }
    }
}

std::int64_t ShortestEdge(const EditableMesh& mesh, VertexId v)
{
  std::int64_t shortest = INT64_MAX;
  for (CellId c : mesh.CellsOf[v])
    for (int i = 0; i < mesh.VerticesPerCell(); ++i)
      if (mesh.Cells[c][i] != v)
        shortest = std::min(shortest, SquaredLength(mesh, v, mesh.Cells[c][i]));
  return shortest;
}

/// Every vertex of a merge's cells lies in `region`: then no other region's
/// merge can touch them.
bool InRegion(const Shared& s, VertexId a, VertexId b, std::int32_t region)
{
  // b first: its cells may be another region's, being edited right now,
  // until b is known to be ours.
  if (s.Regions.RegionOf(b) != region)
    return false;
  for (VertexId v : { a, b })
    for (CellId c : s.Mesh.CellsOf[v])
      for (int i = 0; i < s.Mesh.VerticesPerCell(); ++i)
        if (s.Regions.RegionOf(s.Mesh.Cells[c][i]) != region)
          return false;
  return true;
}

/// Offers the queue's vertices for merging until it is empty (Algorithm 4's
/// loop). `region` < 0: no region restriction. Vertices that only a region
/// border kept from merging go to `held`. `tick` is called per vertex offered.
template <typename Tick>
void OfferVertices(Shared& s, Worker& w, MergeQueue& queue, std::int32_t region, std::vector<VertexId>& held,
  Tick&& tick)
{
  EditableMesh& mesh = s.Mesh;
  const auto& checks = s.Parameters.Checks;
  VertexId a;
  while (queue.Pop(a))
  {
    if (s.Merges >= s.Parameters.MaximumMerges)
      return;
    if (s.Parameters.Order == MergeOrder::ShortestEdgeFirst && !mesh.CellsOf[a].empty())
    {
      // Keys are lower bounds (see the push below): offer a only once its
      // true shortest edge is due.
      const std::int64_t shortest = ShortestEdge(mesh, a);
      if (shortest > s.Key[a])
      {
        s.Key[a] = shortest;
        queue.Push(a, shortest);
        continue;
      }
    }
    tick();
    if (mesh.CellsOf[a].empty() || s.Frozen[a] || (region >= 0 && s.Regions.RegionOf(a) != region))
      continue;
    ++w.Counts.Offers;
    const bool interior = TopologyCheck::IsInterior(mesh, a);
    w.Quality.Prepare(mesh, a);
    NeighboursOf(mesh, a, w, w.Neighbours);
    w.Targets.clear();
    for (VertexId x : w.Neighbours)
      w.Targets.emplace_back(SquaredLength(mesh, a, x), x);
    std::sort(w.Targets.begin(), w.Targets.end());
    bool merged = false, blocked = false;
    for (const auto& target : w.Targets)
    {
      const VertexId b = target.second;
      if (checks.Quality && !w.Quality.OrientationsHold(mesh, b))
      {
        ++w.Counts.RejectedByQuality;
        continue;
      }
      if (region >= 0 && !InRegion(s, a, b, region))
      {
        blocked = true;
        continue;
      }
      w.Merge.Plan(mesh, a, b);
      if (checks.Quality && !w.Quality.AnglesHold(mesh, w.Merge))
      {
        ++w.Counts.RejectedByQuality;
        continue;
      }
      if (interior)
      {
        // No interface passes through a's star: the merge moves none, so
        // neither distance can change (FidelityCheck has nothing to test).
        if (checks.Topology && !w.Topology.AcceptsInteriorMove(mesh, w.Merge))
        {
          ++w.Counts.RejectedByTopology;
          continue;
        }
      }
      else if (!w.Merge.PlanInterfaces(mesh))
      {
        ++w.Counts.RejectedByTopology; // would not stay a conforming mesh of the box
        continue;
      }
      else if (checks.Topology && !w.Topology.Accepts(mesh, w.Merge))
      {
        ++w.Counts.RejectedByTopology;
        continue;
      }
      else if (checks.Fidelity && !w.Fidelity.Accepts(mesh, w.Merge))
      {
        ++w.Counts.RejectedByFidelity;
        continue;
      }
      w.Merge.Apply(mesh);
      if (checks.Fidelity && !interior)
        s.Anchors.Commit(w.Merge, w.Fidelity.Updates);
      ++w.Counts.Merges;
      ++s.Merges;
      // The merge changed the neighbourhoods of b and of a's neighbours, now b's.
      // A neighbour x of b lost its edge to a and gained (at most) the edge
      // to b, so min(old key, |xb|) bounds its new shortest edge from below:
      // cheap to push, checked when popped. (Keying it by |xb| alone halves
      // the offers but leaves 40 % more cells.)
      NeighboursOf(mesh, b, w, w.Neighbours);
      for (VertexId x : w.Neighbours)
        if ((region < 0 || s.Regions.RegionOf(x) == region) && !s.Frozen[x])
        {
          s.Key[x] = std::min(s.Key[x], SquaredLength(mesh, x, b));
          queue.Push(x, s.Key[x]);
        }
      // Every star the merge changed is b's or a neighbour's of b (all in this run: InRegion).
      if (!s.Settled.empty())
      {
        s.Settled[b] = 0;
        for (VertexId x : w.Neighbours)
          s.Settled[x] = 0;
      }
      s.Key[b] = ShortestEdge(mesh, b);
      queue.Push(b, s.Key[b]);
      merged = true;
      break;
    }
    if (!merged && blocked)
      held.push_back(a);
  }
}

void Add(DecimationCounts& total, const DecimationCounts& part)
{
  total.Offers += part.Offers;
  total.Merges += part.Merges;
  total.RejectedByQuality += part.RejectedByQuality;
  total.RejectedByTopology += part.RejectedByTopology;
  total.RejectedByFidelity += part.RejectedByFidelity;
}

/// Algorithm 4's loop on the runs the RegionScheduler hands out: one Worker
/// per thread, kept across runs and passes (its scratch is per mesh vertex),
/// and the progress ticks; only the calling thread (0) talks to the observer.
class MergeRuns final : public RegionScheduler::Work
{
public:
  MergeRuns(Shared& shared, const ImageBoundary& boundary, const ProgressObserver& observer, double vertices)
    : S(shared)
    , Boundary(boundary)
    , Observer(observer)
    , Vertices(vertices)
  {
  }

  DecimationCounts Counts; ///< summed over the passes run since the caller last took them

  void BeginPass(std::size_t runs, double start, double share) override
  {
    PerRun.assign(runs, DecimationCounts{});
    Start = start;
    Share = share;
    S.Offered = 0;
    S.Anchors.SetShared(runs > 1);
    if (Workers.size() < MaxThreads())
      Workers.resize(MaxThreads());
  }

  void OfferRun(unsigned thread, std::int32_t region, const std::vector<VertexId>& offered,
    std::vector<VertexId>& held) override
  {
    std::unique_ptr<Worker>& worker = Workers[thread];
    if (!worker)
      worker = std::make_unique<Worker>(S, Boundary);
    MergeQueue queue(S.Parameters.Order, S.Stamps);
    for (VertexId v : offered)
      if (!S.Frozen[v])
        queue.Push(v, S.Key[v]);
    worker->Counts = {};
    // Offers are counted per run and published every 1024.
    std::size_t local = 0;
    auto tick = [&] {
      if (++local % 1024 != 0)
        return;
      const std::size_t published = S.Offered += 1024;
      if (thread == 0 &&
        !Observer.Report("decimation", Start + Share * std::min(1.0, static_cast<double>(published) / Vertices)))
        S.Abort = true;
      if (S.Abort)
        throw AbortRequested{};
    };
    OfferVertices(S, *worker, queue, region, held, tick);
    PerRun[region < 0 ? 0 : static_cast<std::size_t>(region)] = worker->Counts;
  }

  void EndPass() override
  {
    S.Anchors.SetShared(false);
    for (const DecimationCounts& c : PerRun)
      Add(Counts, c);
  }

private:
  Shared& S;
  const ImageBoundary& Boundary;
  const ProgressObserver& Observer;
  double Vertices;
  double Start = 0.0, Share = 0.0;
  std::vector<DecimationCounts> PerRun;
  std::vector<std::unique_ptr<Worker>> Workers;
};

} // namespace

double ProvenAngleBound(int dimension)
{
  return dimension == 2 ? 45.0 : 30.0;
}

void ValidateDecimationParameters(int dimension, const DecimationParameters& p)
{
  const double bound = ProvenAngleBound(dimension);
  if (!(p.MinimumAngle > 0.0 && p.MinimumAngle <= bound))
    throw std::invalid_argument("the minimum angle must be in (0, " + std::to_string(bound).substr(0, 4) +
      "] degrees, the initial mesh's proven bound; got " + std::to_string(p.MinimumAngle));
  if (!(p.ImageToMeshDistance >= 0.0) || !(p.MeshToImageDistance >= 0.0) || !std::isfinite(p.ImageToMeshDistance) ||
    !std::isfinite(p.MeshToImageDistance))
    throw std::invalid_argument("the distance bounds must be finite and non-negative");
}

void DecimateInScope(const LabelImage& image, const ImageBoundary& boundary, EditableMesh& mesh, const DecimationParameters& parameters,
  DecimationScope& scope, const ProgressObserver& observer, double start, double share,
  DecimationCounts& counts, StageClock& clock)
{
  auto report = [&](const char* stage, double fraction) {
    if (!observer.Report(stage, start + share * fraction))
      throw AbortRequested{};
  };
  report("decimation setup", 0.0);
  if (!scope.InputKept)
    ValidateAgainstImage(mesh, image, parameters.MinimumAngle);
  ImageBoundaryAnchors anchors(boundary, parameters.ImageToMeshDistance);
  std::vector<std::uint8_t> frozen = scope.Frozen;
  frozen.resize(mesh.Position.size(), 0);
  for (std::size_t v = 0; v < mesh.Border.size(); ++v)
    frozen[v] |= mesh.Border[v];
  {
    const std::vector<InterfaceFace> faces = mesh.InterfaceFaces();
    if (!scope.InputKept)
      CheckMeshToImage(mesh, faces, boundary, anchors, parameters.MeshToImageDistance);
    report("decimation setup", 0.05);
    if (scope.FreezeNear)
    {
      std::vector<std::uint8_t> uncertified(boundary.Faces().size(), 0);
      anchors.Initialize(mesh, faces, frozen, scope.ImageFaces, &uncertified);
      scope.FreezeNear(mesh, uncertified, frozen);
    }
    else
      anchors.Initialize(mesh, faces, frozen, scope.ImageFaces);
  }
  counts.CellsBefore += mesh.AliveCells();
  counts.VerticesBefore += mesh.AliveVertices();
  counts.FrozenVertices += static_cast<std::size_t>(std::count(frozen.begin(), frozen.end(), std::uint8_t(1)));
  clock.Finish("decimation setup");

  RegionScheduler regions(mesh);
  Shared shared{ parameters, mesh, anchors, frozen, regions, {}, {}, {}, {}, {} };
  shared.Stamps.assign(mesh.Position.size(), 0);
  shared.Key.assign(mesh.Position.size(), 0);
  for (VertexId v = 0; v < static_cast<VertexId>(mesh.Position.size()); ++v)
    if (!mesh.CellsOf[v].empty())
      shared.Key[v] = ShortestEdge(mesh, v);
  MergeRuns runs(shared, boundary, observer, static_cast<double>(mesh.AliveVertices()));
  auto decimate = [&](const std::vector<std::uint8_t>& offered, double from, double part) {
    regions.Decimate(offered, runs, start + share * from, share * part);
    Add(counts, runs.Counts);
    runs.Counts = {};
  };
  decimate(scope.Offered.empty() ? std::vector<std::uint8_t>(mesh.Position.size(), 1) : scope.Offered, 0.1, 0.7);

  // Rounds of relocation (InteriorRelocation.h): interior vertices move to
  // where their cells' smallest angle is larger, and they and their
  // neighbours are offered for merging again, until no vertex moves. One
  // thread, in Morton order: the decimated mesh is small by now, and the
  // order is the same for every thread count. Every vertex, offered or not:
  // in the streamed pipeline's last pass, moving only the offered ones left
  // 3 % more cells on digimouse.
  if (parameters.RelocateInteriorVertices)
  {
    InteriorRelocation relocation;
    Worker scratch(shared, boundary);
    shared.Settled.assign(mesh.Position.size(), 0);
    for (int round = 0; round < kRelocationRounds; ++round)
    {
      const double from = 0.8 + 0.15 * round / kRelocationRounds;
      report("decimation: relocation", from);
      std::vector<std::uint8_t> touched(mesh.Position.size(), 0);
      std::size_t moved = 0;
      for (VertexId v : regions.AliveInMortonOrder())
      {
        if (frozen[v] || shared.Settled[v])
          continue;
        if (!relocation.TryMove(mesh, v, parameters.Checks.Quality))
        {
          shared.Settled[v] = 1;
          continue;
        }
        ++moved;
        touched[v] = 1;
        shared.Key[v] = ShortestEdge(mesh, v);
        NeighboursOf(mesh, v, scratch, scratch.Neighbours);
        for (VertexId x : scratch.Neighbours)
        {
          touched[x] = 1;
          shared.Settled[x] = 0;
          shared.Key[x] = ShortestEdge(mesh, x);
        }
      }
      counts.Relocations += moved;
      if (moved == 0)
        break;
      decimate(touched, from, 0.15 / kRelocationRounds);
    }
  }
  clock.Finish("decimation");
  scope.Frozen = std::move(frozen);
}

namespace
{
DecimationResult Decimate(const LabelImage& image, const SimplexMesh& input, SimplexMesh* release,
  const DecimationParameters& parameters, const ProgressObserver& observer)
{
  Validate(image, input, parameters);
  DecimationResult result;
  StageClock clock(result.Timings);
  if (!observer.Report("decimation setup", 0.0))
    throw AbortRequested{};

  // Taken over, the input is freed array by array as the editable copy grows.
  EditableMesh mesh = release ? EditableMesh(std::move(*release)) : EditableMesh(input);
  const ImageBoundary boundary(image);
  DecimationScope whole;
  DecimateInScope(image, boundary, mesh, parameters, whole, observer, 0.0, 0.95, result.Counts, clock);

  if (!observer.Report("decimation output", 0.95))
    throw AbortRequested{};
  FinishDecimation(mesh, result);
  clock.Finish("decimation output");
  observer.Report("decimation done", 1.0);
  return result;
}
} // namespace

void FinishDecimation(const EditableMesh& mesh, DecimationResult& result)
{
  result.Mesh = mesh.ToSimplexMesh();
  MaterialInterfaces interfaces = ExtractMaterialInterfaces(result.Mesh);
  result.Interfaces = std::move(interfaces.Faces);
  result.InterfaceMaterials = std::move(interfaces.Sides);
  result.Counts.CellsAfter = result.Mesh.NumberOfCells();
  result.Counts.VerticesAfter = result.Mesh.Points.size();
}

DecimationResult DecimateMesh(const LabelImage& image, const SimplexMesh& mesh,
  const DecimationParameters& parameters, const ProgressObserver& observer)
{
  return Decimate(image, mesh, nullptr, parameters, observer);
}

DecimationResult DecimateMesh(const LabelImage& image, SimplexMesh&& mesh,
  const DecimationParameters& parameters, const ProgressObserver& observer)
{
  return Decimate(image, mesh, &mesh, parameters, observer);
}

} // namespace labelmesher
