// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_DecimationParameters_h
#define labelmesher_DecimationParameters_h

/**
 * @file DecimationParameters.h
 * What the user asks of the decimated mesh (Algorithm 4's inputs theta, h1,
 * h2), and what the decimator reports back. Distances are in voxels of the
 * image as meshed (LabelImage.h), angles in degrees.
 */

#include "Support/StageClock.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace labelmesher
{

/// The order in which vertices are offered for merging.
enum class MergeOrder
{
  ShortestEdgeFirst, ///< the vertex with the shortest incident edge first (default: fewest cells)
  Queue              ///< first in, first out, as in Algorithm 4
};

struct DecimationParameters
{
  /// Smallest dihedral (3D) or planar (2D) angle a merge may create. Degrees,
  /// 0 < theta <= the initial mesh's proven bound (30 in 3D, 45 in 2D); the
  /// input must have no smaller angle. Default 15.
  double MinimumAngle = 15.0;
  /// h(I, M): every point of the image boundary between materials a and b
  /// stays within this distance of the mesh boundary of a and of b. Voxels, >= 0.
  double ImageToMeshDistance = 2.0;
  /// h(M, I): every point of a mesh face between materials a and b stays
  /// within this distance of the image boundary between a and b. Voxels, >= 0.
  double MeshToImageDistance = 2.0;
  MergeOrder Order = MergeOrder::ShortestEdgeFirst;
  /// Move interior vertices to raise their cells' smallest angle between
  /// rounds of merges (InteriorRelocation.h; not in the dissertation).
  /// Default on: it leaves 2-3x fewer cells and keeps every guarantee.
  bool RelocateInteriorVertices = true;

  /// For tests only: stop after this many merges (to find the one that breaks
  /// something), and skip one check, to show that the tests catch what it
  /// guards. Never set in a product.
  std::size_t MaximumMerges = static_cast<std::size_t>(-1);
  struct
  {
    bool Quality = true;
    bool Fidelity = true;
    bool Topology = true;
  } Checks;
};

struct DecimationCounts
{
  std::size_t CellsBefore = 0, CellsAfter = 0;       ///< all cells, background included
  std::size_t VerticesBefore = 0, VerticesAfter = 0;
  std::size_t Offers = 0;                             ///< vertices taken from the queue and tried
  std::size_t Merges = 0;                             ///< merges done
  /// Merges tried and refused, by the first check that refused them (checks
  /// run in this order: quality, topology, fidelity).
  std::size_t RejectedByQuality = 0, RejectedByTopology = 0, RejectedByFidelity = 0;
  std::size_t Relocations = 0;    ///< interior vertices moved (InteriorRelocation.h), counted per move
  std::size_t FrozenVertices = 0; ///< vertices that may not move (image faces no single star certifies)
};

} // namespace labelmesher

#endif
