// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MemoryEstimate_h
#define labelmesher_MemoryEstimate_h

/**
 * @file MemoryEstimate.h
 * What a run will need, said before it starts. The initial mesh is the run's
 * largest structure, and its size follows the image boundary: the octree is
 * refined to single voxels along interfaces and stays coarse elsewhere. So the
 * estimate counts the voxel faces between different labels (one pass over the
 * image) and prices them with figures measured on the shared real volumes
 * (Benchmarks/README.md, "Memory"): initial cells per interface face, peak
 * bytes per initial cell, bytes per voxel for the image and its copies.
 */

#include "Support/LabelImage.h"

#include <cstdint>
#include <string>

namespace labelmesher
{

struct MemoryEstimate
{
  std::uint64_t Voxels = 0;
  std::uint64_t InterfaceFaces = 0; ///< voxel faces (pixel edges) between different labels, outside = 0
  std::uint64_t InitialCells = 0;   ///< estimated cells of the initial mesh, background included
  /// Estimated memory the run takes on top of what the process holds when it
  /// starts (libraries, the image as read): its peak resident growth.
  std::uint64_t RunBytes = 0;
};

/// Voxel faces (pixel edges in 2D) between different labels, the image's
/// outside counting as label 0.
std::uint64_t CountInterfaceFaces(const LabelImage& image);

/// The memory of meshing `image` (and of decimating the mesh when `decimate`),
/// as read -> mesh -> decimate -> write runs it in one process.
MemoryEstimate EstimateMemory(const LabelImage& image, bool decimate);

/// The memory of meshing and decimating `image` block by block
/// (Streaming/StreamedPipeline.h), blocks of `blockCells` initial cells (0: one block).
MemoryEstimate EstimateStreamedMemory(const LabelImage& image, std::uint64_t blockCells);
/// What a process that reads only its slab of the image needs at least before it knows the
/// slab (a process other than rank 0 of a run shared out over several): the fixed part. Its slab
/// and its blocks come on top; rank 0's EstimateStreamedMemory of the whole run bounds them.
std::uint64_t SlabProcessFloorBytes();
/// `estimate` (EstimateStreamedMemory's) with the quadratic stage after the
/// decimation (vtkLabelMesher's Order 2, Quadratic/QuadraticCurver.h): its
/// mid-nodes, elastic system and distance certificates, and when `measured`
/// what its measurements hold (the flattened boundary faces; the voxel count
/// refines one cell at a time), beside the output held, priced per voxel face
/// between labels (the curved interfaces follow them).
MemoryEstimate WithQuadraticStage(MemoryEstimate estimate, bool measured);
/// The memory of decimating a mesh of `cells` cells (the decimator alone, its
/// input already held).
std::uint64_t EstimateDecimationMemory(std::uint64_t cells);

/// `n` with thousands separators: "7,077,888".
std::string WithThousandsSeparators(std::uint64_t n);

/// "7,077,888 voxels, 2,301,114 voxel faces between labels".
std::string DescribeEstimate(const MemoryEstimate& estimate);

} // namespace labelmesher

#endif
