// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_RegionScheduler_h
#define labelmesher_RegionScheduler_h

/**
 * @file RegionScheduler.h
 * How the merges of section 3.1.3 run on several cores: the alive vertices in
 * Morton order (the octree's, as p4est partitions it) are cut into runs of
 * kDecimationRegionVertices; each run is decimated on its own, on any core,
 * with its border frozen (a merge may not touch a vertex of another run, so
 * runs never share a cell). The vertices a border held back are offered again
 * in two passes cut afresh from the coarser mesh, with the cuts moved by half
 * and a quarter of a run so that old borders lie inside new runs, and last in
 * one run on one thread. The runs depend on the mesh only, never on the
 * number of threads, so neither does the result.
 *
 * This is the unit a block-streamed or distributed run replaces: what a run
 * does (MeshDecimator.cxx's merge loop) does not depend on how runs are cut.
 */

#include "Decimation/EditableMesh.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace labelmesher
{

/// Vertices per run of the parallel passes.
constexpr std::size_t kDecimationRegionVertices = 16384;

class RegionScheduler
{
public:
  /// What the scheduler asks of the decimator.
  class Work
  {
  public:
    virtual ~Work() = default;
    /// A pass of `runs` runs starts; its progress spans [start, start + share].
    virtual void BeginPass(std::size_t runs, double start, double share) = 0;
    /// Decimates `queue` (the run's offered vertices, in Morton order) within
    /// run `region` (-1: the whole mesh, no border) on thread `thread`, and
    /// appends to `held` the vertices that only the run's border kept from merging.
    virtual void OfferRun(unsigned thread, std::int32_t region, const std::vector<VertexId>& queue,
      std::vector<VertexId>& held) = 0;
    virtual void EndPass() = 0;
  };

  explicit RegionScheduler(const EditableMesh& mesh);

  /// The run of `v` in the pass under way (-1: the pass is one run).
  std::int32_t RegionOf(VertexId v) const { return Region[static_cast<std::size_t>(v)]; }

  /// The passes over the vertices flagged in `offered` (per vertex), with
  /// progress in [start, start + share].
  void Decimate(const std::vector<std::uint8_t>& offered, Work& work, double start, double share);

  /// The alive vertices (those with cells) in Morton order, ties by id.
  std::vector<VertexId> AliveInMortonOrder() const;

private:
  /// One pass over `offered` with the cuts moved by `shift` (a fraction of a
  /// run); `oneRun`: a single run on one thread. Returns the held vertices
  /// (flags) and the number of runs.
  std::vector<std::uint8_t> Pass(const std::vector<std::uint8_t>& offered, double shift, bool oneRun, Work& work,
    double start, double share, std::size_t& runs);

  const EditableMesh& Mesh;
  std::vector<std::uint64_t> Keys;   ///< Morton key per vertex
  std::vector<std::int32_t> Region;  ///< run per vertex in the pass under way
};

} // namespace labelmesher

#endif
