// SPDX-License-Identifier: GPL-2.0-or-later
// The decimation of section 3.1.3 (Algorithm 4): regions in parallel with frozen borders, then the
// borders.
#include "Decimation/MeshDecimator.h"

#include "Decimation/EdgeCollapse.h"
#include "Decimation/EditableMesh.h"
#include "Decimation/FidelityCheck.h"
#include "Decimation/ImageBoundary.h"
#include "Decimation/ImageBoundaryAnchors.h"
#include "Decimation/InteriorRelocation.h"
#include "Decimation/MergeQueue.h"
#include "Decimation/QualityCheck.h"
#include "Decimation/TopologyCheck.h"
#include "Mesh/MeshBoundary.h"
#include "Support/ParallelChunks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

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
  const double bound = ProvenAngleBound(d);
  if (!(p.MinimumAngle > 0.0 && p.MinimumAngle <= bound))
    throw std::invalid_argument("the minimum angle must be in (0, " + std::to_string(bound).substr(0, 4) +
      "] degrees, the initial mesh's proven bound; got " + std::to_string(p.MinimumAngle));
  if (!(p.ImageToMeshDistance >= 0.0) || !(p.MeshToImageDistance >= 0.0) || !std::isfinite(p.ImageToMeshDistance) ||
    !std::isfinite(p.MeshToImageDistance))
    throw std::invalid_argument("the distance bounds must be finite and non-negative");
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

struct Shared
{
  const DecimationParameters& Parameters;
  EditableMesh& Mesh;
  ImageBoundaryAnchors& Anchors;
  const std::vector<std::uint8_t>& Frozen;
  std::vector<std::int32_t> Region; ///< per vertex
  std::vector<std::uint32_t> Stamps;
  std::vector<std::int64_t> Key; ///< per vertex: a lower bound of its shortest edge (squared)
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
  if (s.Region[b] != region)
    return false;
  for (VertexId v : { a, b })
    for (CellId c : s.Mesh.CellsOf[v])
      for (int i = 0; i < s.Mesh.VerticesPerCell(); ++i)
        if (s.Region[s.Mesh.Cells[c][i]] != region)
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
    if (mesh.CellsOf[a].empty() || s.Frozen[a] || (region >= 0 && s.Region[a] != region))
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
        if ((region < 0 || s.Region[x] == region) && !s.Frozen[x])
        {
          s.Key[x] = std::min(s.Key[x], SquaredLength(mesh, x, b));
          queue.Push(x, s.Key[x]);
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

/// Morton key of a doubled-lattice position (coordinates below 2^21).
std::uint64_t Morton(const Lattice& p, const Lattice& low)
{
  std::uint64_t key = 0;
  for (int bit = 20; bit >= 0; --bit)
    for (int a = 2; a >= 0; --a)
      key = (key << 1) | ((static_cast<std::uint64_t>(p[a] - low[a]) >> bit) & 1u);
  return key;
}

} // namespace

double ProvenAngleBound(int dimension)
{
  return dimension == 2 ? 45.0 : 30.0;
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

  EditableMesh mesh(input);
  if (release)
    *release = SimplexMesh{};
  ValidateAgainstImage(mesh, image, parameters.MinimumAngle);
  const ImageBoundary boundary(image);
  ImageBoundaryAnchors anchors(boundary, parameters.ImageToMeshDistance);
  std::vector<std::uint8_t> frozen(mesh.Position.size(), 0);
  {
    const std::vector<InterfaceFace> faces = mesh.InterfaceFaces();
    // The input must hold h(M, I) already: merges only check what they move.
    std::vector<std::int64_t> far(MaxThreads(), -1);
    ParallelChunks(faces.size(), 4096, [&](unsigned thread, std::size_t begin, std::size_t end) {
      FidelityCheck check(boundary, anchors, parameters.MeshToImageDistance);
      for (std::size_t f = begin; f < end && far[thread] < 0; ++f)
        if (!check.FaceWithinBound(mesh, faces[f]))
          far[thread] = static_cast<std::int64_t>(f);
    });
    for (std::int64_t f : far)
      if (f >= 0)
        throw std::invalid_argument("the input mesh does not hold h(M,I) <= " +
          std::to_string(parameters.MeshToImageDistance) + " (a face between materials " +
          std::to_string(std::max(faces[f].Low, 0)) + " and " + std::to_string(faces[f].High) +
          " is farther from their image interface): mesh it with this bound or a smaller one first");
    if (!observer.Report("decimation setup", 0.05))
      throw AbortRequested{};
    anchors.Initialize(mesh, faces, frozen);
  }
  result.Counts.CellsBefore = mesh.Cells.size();
  result.Counts.VerticesBefore = mesh.AliveVertices();
  result.Counts.FrozenVertices = static_cast<std::size_t>(std::count(frozen.begin(), frozen.end(), std::uint8_t(1)));
  clock.Finish("decimation setup");

  // Regions: runs of the Morton order of the vertices.
  Shared shared{ parameters, mesh, anchors, frozen, {}, {}, {}, {}, {}, {} };
  shared.Stamps.assign(mesh.Position.size(), 0);
  shared.Key.assign(mesh.Position.size(), 0);
  for (VertexId v = 0; v < static_cast<VertexId>(mesh.Position.size()); ++v)
    if (!mesh.CellsOf[v].empty())
      shared.Key[v] = ShortestEdge(mesh, v);
  // The alive vertices in Morton order (the octree's, as p4est partitions it).
  std::vector<std::uint64_t> keys(mesh.Position.size());
  for (std::size_t v = 0; v < mesh.Position.size(); ++v)
    keys[v] = Morton(mesh.Position[v], mesh.BoxLow);
  auto aliveInMortonOrder = [&] {
    std::vector<VertexId> order;
    for (std::size_t v = 0; v < mesh.Position.size(); ++v)
      if (!mesh.CellsOf[v].empty())
        order.push_back(static_cast<VertexId>(v));
    std::sort(order.begin(), order.end(), [&](VertexId x, VertexId y) { return keys[x] < keys[y] || (keys[x] == keys[y] && x < y); });
    return order;
  };
  shared.Region.assign(mesh.Position.size(), -1);

  const double total = static_cast<double>(result.Counts.VerticesBefore);
  // Offers are counted per thread and published every 1024; only the
  // calling thread (0) talks to the observer.
  auto tickFor = [&](unsigned thread, double start, double share) {
    return [&, thread, start, share, local = std::size_t(0)]() mutable {
      if (++local % 1024 != 0)
        return;
      const std::size_t offered = shared.Offered += 1024;
      if (thread == 0 &&
        !observer.Report("decimation", start + share * std::min(1.0, static_cast<double>(offered) / total)))
        shared.Abort = true;
      if (shared.Abort)
        throw AbortRequested{};
    };
  };

  // One pass over the vertices flagged in `offered`: the alive vertices, in
  // Morton order, cut into runs of kDecimationRegionVertices with the cuts
  // moved by `shift` (a fraction of a run); each run decimated on its own,
  // on any core, with its border frozen (one run: no border, one thread).
  // Returns the vertices a border held back.
  auto pass = [&](const std::vector<std::uint8_t>& offered, double shift, bool oneRun, double start, double share) {
    const std::vector<VertexId> order = aliveInMortonOrder();
    const std::size_t n = order.size();
    const std::size_t regions = oneRun ? 1 : std::max<std::size_t>(1, n / kDecimationRegionVertices);
    const std::size_t offset = static_cast<std::size_t>(shift * n / regions);
    // Run r holds positions [runStart(r), runStart(r + 1)) of the shifted
    // order; the same bounds decide membership and what a run queues.
    auto runStart = [&](std::size_t r) { return r * n / regions; };
    for (std::size_t r = 0; r < regions; ++r)
      for (std::size_t i = runStart(r); i < runStart(r + 1); ++i)
        shared.Region[order[(i + offset) % n]] = regions > 1 ? static_cast<std::int32_t>(r) : -1;
    std::vector<std::vector<VertexId>> held(regions);
    std::vector<DecimationCounts> counts(regions);
    shared.Offered = 0;
    anchors.SetShared(regions > 1);
    ParallelChunks(regions, 1, [&](unsigned thread, std::size_t begin, std::size_t end) {
      Worker worker(shared, boundary);
      auto tick = tickFor(thread, start, share);
      for (std::size_t r = begin; r < end; ++r)
      {
        MergeQueue queue(parameters.Order, shared.Stamps);
        for (std::size_t i = runStart(r); i < runStart(r + 1); ++i)
        {
          const VertexId v = order[(i + offset) % n];
          if (offered[v] && !frozen[v])
            queue.Push(v, shared.Key[v]);
        }
        worker.Counts = {};
        OfferVertices(shared, worker, queue, regions > 1 ? static_cast<std::int32_t>(r) : -1, held[r], tick);
        counts[r] = worker.Counts;
      }
    });
    anchors.SetShared(false);
    for (const auto& c : counts)
      Add(result.Counts, c);
    std::vector<std::uint8_t> next(mesh.Position.size(), 0);
    for (const auto& list : held)
      for (VertexId v : list)
        next[v] = 1;
    return std::make_pair(next, regions);
  };

  // The pass sequence over the vertices flagged in `offered`. Pass 1 offers
  // them all; passes 2 and 3 what the borders held back, cut afresh from the
  // vertices left (the mesh is coarser: as many vertices per run cover more
  // of it) with the cuts moved by half and a quarter run, so that old borders
  // lie inside the new runs; the last pass, on one thread, whatever is still
  // held.
  auto decimate = [&](const std::vector<std::uint8_t>& offered, double start, double share) {
    auto [held, regions] = pass(offered, 0.0, false, start, 0.85 * share);
    const double shifts[] = { 0.5, 0.25 };
    for (int k = 0; k < 2 && regions > 1; ++k)
      std::tie(held, regions) = pass(held, shifts[k], false, start + (0.85 + 0.05 * k) * share, 0.05 * share);
    if (regions > 1)
      pass(held, 0.0, true, start + 0.95 * share, 0.05 * share);
  };
  decimate(std::vector<std::uint8_t>(mesh.Position.size(), 1), 0.1, 0.7);

  // Rounds of relocation (InteriorRelocation.h): interior vertices move to
  // where their cells' smallest angle is larger, and they and their
  // neighbours are offered for merging again, until no vertex moves. One
  // thread, in Morton order: the decimated mesh is small by now, and the
  // order is the same for every thread count.
  if (parameters.RelocateInteriorVertices)
  {
    InteriorRelocation relocation;
    Worker scratch(shared, boundary);
    for (int round = 0; round < kRelocationRounds; ++round)
    {
      const double start = 0.8 + 0.15 * round / kRelocationRounds;
      if (!observer.Report("decimation: relocation", start))
        throw AbortRequested{};
      std::vector<std::uint8_t> touched(mesh.Position.size(), 0);
      std::size_t moved = 0;
      for (VertexId v : aliveInMortonOrder())
      {
        if (frozen[v] || !relocation.TryMove(mesh, v, parameters.Checks.Quality))
          continue;
        ++moved;
        touched[v] = 1;
        shared.Key[v] = ShortestEdge(mesh, v);
        NeighboursOf(mesh, v, scratch, scratch.Neighbours);
        for (VertexId x : scratch.Neighbours)
        {
          touched[x] = 1;
          shared.Key[x] = ShortestEdge(mesh, x);
        }
      }
      result.Counts.Relocations += moved;
      if (moved == 0)
        break;
      decimate(touched, start, 0.15 / kRelocationRounds);
    }
  }
  clock.Finish("decimation");

  if (!observer.Report("decimation output", 0.95))
    throw AbortRequested{};
  result.Mesh = mesh.ToSimplexMesh();
  MaterialInterfaces interfaces = ExtractMaterialInterfaces(result.Mesh);
  result.Boundary = std::move(interfaces.Faces);
  result.BoundaryMaterials = std::move(interfaces.Sides);
  result.Counts.CellsAfter = result.Mesh.NumberOfCells();
  result.Counts.VerticesAfter = result.Mesh.Points.size();
  clock.Finish("decimation output");
  observer.Report("decimation done", 1.0);
  return result;
}
} // namespace

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
