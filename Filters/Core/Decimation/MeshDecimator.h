// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MeshDecimator_h
#define labelmesher_MeshDecimator_h

/**
 * @file MeshDecimator.h
 * The decimation of section 3.1.3 (Algorithm 4) as one free function: the
 * ORD initial mesh and its label image in, a coarser mesh out that keeps the
 * angle bound, both distance bounds and the topology of every material,
 * interface and feature curve.
 *
 * Vertices are merged into neighbours along edges (EdgeCollapse), each merge
 * accepted only when its three checks hold, cheapest first: quality
 * (QualityCheck: no inverted cell, no angle below the bound), topology
 * (TopologyCheck: strata, link conditions, commutation; combinatorial and
 * cheap) and fidelity (FidelityCheck: both one-sided distances, exact
 * geometry). The queue offers the vertex with the shortest edge first.
 *
 * Parallel by regions: RegionScheduler cuts the vertices into runs of their
 * Morton order (the octree's order, as p4est partitions it) and decimates
 * each on its own, on any core, with its border frozen, then the borders. The
 * runs do not depend on the number of threads, so neither does the mesh.
 * Streaming/StreamedPipeline.h runs the same decimation block by block
 * (DecimationScope.h), so that the whole initial mesh is never held.
 */

#include "Decimation/DecimationParameters.h"
#include "Mesh/SimplexMesh.h"
#include "Support/LabelImage.h"
#include "Support/ProgressObserver.h"
#include "Support/StageClock.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace labelmesher
{

struct DecimationResult
{
  /// Every cell of the box, background (label 0) included, points in index space.
  SimplexMesh Mesh;
  /// The interfaces: faces between different materials, as MesherResult::Interfaces.
  SimplexMesh Interfaces;
  std::vector<std::pair<std::int32_t, std::int32_t>> InterfaceMaterials;
  DecimationCounts Counts;
  std::vector<StageTiming> Timings;
};

/// At most this many rounds of relocation and merges: they stop earlier, when
/// no vertex moves (Cassini 100 at 15 degrees: after 12 rounds).
constexpr int kRelocationRounds = 32;

/// The smallest angle (degrees) a decimation may ask for: the initial mesh's
/// proven bound (Testing/Cxx/Fill/TestAngleBoundEnumeration.cxx).
double ProvenAngleBound(int dimension);

/// Throws std::invalid_argument, naming the problem, for an angle outside
/// (0, ProvenAngleBound] or a negative or infinite distance bound.
void ValidateDecimationParameters(int dimension, const DecimationParameters& parameters);

/// Decimates `mesh`, the whole box of the ORD mesh of `image` (background
/// cells included: MesherResult::Mesh, or vtkLabelOctreeMesher with
/// IncludeBackground on). Throws std::invalid_argument, naming the problem,
/// for bad parameters, a mesh that does not fill its box or does not lie on
/// the image's lattice, or an input that breaks a requested bound; and
/// AbortRequested when `observer` says stop.
DecimationResult DecimateMesh(const LabelImage& image, const SimplexMesh& mesh,
  const DecimationParameters& parameters, const ProgressObserver& observer = {});
/// The same, taking `mesh` over: it is released as soon as the decimator's own
/// copy is built, so the two never add up at the run's peak.
DecimationResult DecimateMesh(const LabelImage& image, SimplexMesh&& mesh,
  const DecimationParameters& parameters, const ProgressObserver& observer = {});

} // namespace labelmesher

#endif
