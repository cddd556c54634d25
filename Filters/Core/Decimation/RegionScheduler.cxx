// SPDX-License-Identifier: GPL-2.0-or-later
// Runs of the Morton order decimated in parallel with frozen borders, then the borders.
#include "Decimation/RegionScheduler.h"

#include "Support/ParallelChunks.h"

#include <algorithm>

namespace labelmesher
{
namespace
{
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

RegionScheduler::RegionScheduler(const EditableMesh& mesh)
  : Mesh(mesh)
  , Keys(mesh.Position.size())
  , Region(mesh.Position.size(), -1)
{
  for (std::size_t v = 0; v < mesh.Position.size(); ++v)
    Keys[v] = Morton(mesh.Position[v], mesh.BoxLow);
}

std::vector<VertexId> RegionScheduler::AliveInMortonOrder() const
{
  std::vector<VertexId> order;
  for (std::size_t v = 0; v < Mesh.Position.size(); ++v)
    if (!Mesh.CellsOf[v].empty())
      order.push_back(static_cast<VertexId>(v));
  std::sort(order.begin(), order.end(),
    [&](VertexId x, VertexId y) { return Keys[x] < Keys[y] || (Keys[x] == Keys[y] && x < y); });
  return order;
}

std::vector<std::uint8_t> RegionScheduler::Pass(const std::vector<std::uint8_t>& offered, double shift, bool oneRun,
  Work& work, double start, double share, std::size_t& runs)
{
  const std::vector<VertexId> order = AliveInMortonOrder();
  const std::size_t n = order.size();
  runs = oneRun ? 1 : std::max<std::size_t>(1, n / kDecimationRegionVertices);
  const std::size_t offset = static_cast<std::size_t>(shift * n / runs);
  // Run r holds positions [runStart(r), runStart(r + 1)) of the shifted
  // order; the same bounds decide membership and what a run queues.
  auto runStart = [&](std::size_t r) { return r * n / runs; };
  for (std::size_t r = 0; r < runs; ++r)
    for (std::size_t i = runStart(r); i < runStart(r + 1); ++i)
      Region[order[(i + offset) % n]] = runs > 1 ? static_cast<std::int32_t>(r) : -1;
  std::vector<std::vector<VertexId>> held(runs);
  work.BeginPass(runs, start, share);
  ParallelChunks(runs, 1, [&](unsigned thread, std::size_t begin, std::size_t end) {
    std::vector<VertexId> queue;
    for (std::size_t r = begin; r < end; ++r)
    {
      queue.clear();
      for (std::size_t i = runStart(r); i < runStart(r + 1); ++i)
      {
        const VertexId v = order[(i + offset) % n];
        if (offered[v])
          queue.push_back(v);
      }
      work.OfferRun(thread, runs > 1 ? static_cast<std::int32_t>(r) : -1, queue, held[r]);
    }
  });
  work.EndPass();
  std::vector<std::uint8_t> next(Mesh.Position.size(), 0);
  for (const auto& list : held)
    for (VertexId v : list)
      next[v] = 1;
  return next;
}

void RegionScheduler::Decimate(const std::vector<std::uint8_t>& offered, Work& work, double start, double share)
{
  std::size_t runs = 0;
  std::vector<std::uint8_t> held = Pass(offered, 0.0, false, work, start, 0.85 * share, runs);
  const double shifts[] = { 0.5, 0.25 };
  for (int k = 0; k < 2 && runs > 1; ++k)
    held = Pass(held, shifts[k], false, work, start + (0.85 + 0.05 * k) * share, 0.05 * share, runs);
  if (runs > 1)
    Pass(held, 0.0, true, work, start + 0.95 * share, 0.05 * share, runs);
}

} // namespace labelmesher
