// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_OctreeRefinement_h
#define labelmesher_OctreeRefinement_h

/**
 * @file OctreeRefinement.h
 * Octree O2 of Algorithm 2 on a p4est forest (one tree, the unit cube, mapped
 * onto a 2^depth voxel cube whose voxel (0,0,0) is the image's first voxel).
 *
 * A leaf is split while the caller's evaluator says so (more than two labels,
 * single manifold condition, fidelity), the forest is kept 2:1 balanced across
 * faces and edges (p4est_balance, P8EST_CONNECT_EDGE; faces in 2D), and a leaf
 * larger than a proper boundary face- or edge-neighbour is split: intersection
 * vertices never become quarter points of a larger leaf (the configuration
 * that breaks the dissertation's 19.47 degree claim, and which the angle
 * enumeration, Testing/Cxx/Fill/TestAngleBoundEnumeration.cxx, excludes), and the faces a
 * proper leaf's surface crosses (its rigid faces) never carry points of finer
 * leaves. A proper leaf may meet finer uniform leaves across its other faces
 * and edges: those are filled like a uniform leaf's. Refinement and balance
 * alternate until nothing changes; it ends because single voxels are never
 * split.
 */

#include "Octree/LeafBox.h"
#include "Support/LabelImage.h"
#include "Support/ProgressObserver.h"

#include <functional>
#include <vector>

namespace labelmesher
{

struct LeafVerdict
{
  bool Refine = false;
  std::int32_t First = 0, Second = 0; ///< labels held, when not refined
  /// Proper leaves: the faces (3D) or sides (2D) that may not carry a point of
  /// a finer neighbour, because the surface crosses them (their stencil has no
  /// room for hanging points).
  std::uint8_t RigidFaces = 0;
};
using LeafEvaluator = std::function<LeafVerdict(const LeafBox&)>;

/// The depth of the octree over `image`: the smallest d with 2^d voxels a
/// side covering the image (at least 1).
int OctreeDepth(const LabelImage& image);

/// Builds the octree (dimension 3) or quadtree (dimension 2) over a cube of
/// 2^depth voxels a side and returns its leaves, with the midpoints and split
/// faces their finer neighbours impose.
std::vector<OctreeLeaf> BuildOctree(int dimension, int depth, const LeafEvaluator& evaluate,
  const ProgressObserver& observer, double progressStart, double progressEnd);

/// Starts MPI for a process that runs without mpirun (Filters/MPIStartup.h: StartMPI).
using MPIStarter = void (*)();
/// MPI start-up belongs to the application, never to the core: the forest needs MPI running
/// (p4est's communicator), and when it is not, it calls the starter registered here, once; with
/// none it throws std::logic_error. The filters start MPI themselves before they mesh; programs
/// that call the core directly (tests, benchmarks, the scan) register StartMPI in their main, so
/// that only a run that builds a forest pays for the start.
void SetMPIStarter(MPIStarter starter);

namespace detail
{
std::vector<OctreeLeaf> BuildForest2(int depth, const LeafEvaluator&, const ProgressObserver&, double, double);
std::vector<OctreeLeaf> BuildForest3(int depth, const LeafEvaluator&, const ProgressObserver&, double, double);
/// libsc and p4est set up once (their log and abort handlers), with MPI running (SetMPIStarter).
void InitializeP4est();
}

} // namespace labelmesher

#endif
