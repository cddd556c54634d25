// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_LabelOctreeMesher_h
#define labelmesher_LabelOctreeMesher_h

/**
 * @file LabelOctreeMesher.h
 * The ORD initial mesh (dissertation chapter 3, Algorithms 1-3) as one free
 * function over VTK-free types: a multi-label image in, a conforming, labelled
 * triangle (2D) or tetrahedral (3D) mesh out.
 */

#include "MesherParameters.h"
#include "Octree/LeafBox.h"
#include "Support/LabelImage.h"
#include "Support/ProgressObserver.h"
#include "Support/StageClock.h"
#include "Mesh/SimplexMesh.h"

#include <string>
#include <utility>
#include <vector>

namespace labelmesher
{

struct MesherResult
{
  /// Every cell of the padded octree domain, background (label 0) included.
  SimplexMesh Mesh;
  /// The interfaces: faces between different materials (background included),
  /// triangles in 3D, segments in 2D, with the labels on either side.
  SimplexMesh Interfaces;
  std::vector<std::pair<std::int32_t, std::int32_t>> InterfaceMaterials;
  std::vector<StageTiming> Timings;
  std::size_t NumberOfLeaves = 0;
};

/// The refined octree of MeshLabelImage's first stages.
struct MesherOctree
{
  int Depth = 0;                    ///< the octree covers 2^Depth voxels a side
  std::vector<OctreeLeaf> Leaves;   ///< in p4est's (Morton) order
};

/// Stages 1 and 2 of MeshLabelImage (validation, label pyramid, octree),
/// progress up to 0.6: what the block-streamed pipeline fills block by block.
MesherOctree RefineOctree(const LabelImage& image, const MesherParameters& parameters,
  const ProgressObserver& observer, StageClock& clock);

/// Meshes `image`. Throws std::invalid_argument for bad input (no foreground,
/// negative labels, empty extent) and AbortRequested when `observer` says stop.
MesherResult MeshLabelImage(const LabelImage& image, const MesherParameters& parameters,
  const ProgressObserver& observer = {});

} // namespace labelmesher

#endif
