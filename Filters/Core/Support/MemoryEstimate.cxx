// SPDX-License-Identifier: GPL-2.0-or-later
// The run's peak memory, priced from the image's interface faces.
#include "Support/MemoryEstimate.h"

#include <algorithm>

namespace labelmesher
{
namespace
{
// Fitted to the shared volumes (Benchmarks/README.md, "Memory"): liver and
// digimouse fix the figures, frog, torso, totalseg and the rat head check them.
// Initial cells, background included, follow the boundary (leaves of one
// voxel along it) plus a little of the volume (the coarse leaves elsewhere).
constexpr double kCellsPerFace3D = 17.9, kCellsPerFace2D = 4.5, kCellsPerVoxel = 0.05;
// Peak growth of the process, bytes: the mesher with its output packed for
// VTK, per initial cell; the decimator with that output held, per initial
// cell; per voxel, the core's copy of the (resampled) image, as wide as its
// labels need (LabelImage.h), and its pyramid from the second level up (8
// bytes per 64 voxels, and an eighth of that again per level above); and a
// fixed part (MPI's start, threads' arenas).
constexpr double kMesherBytesPerCell = 112.0;
constexpr double kHeldBytesPerCell = 50.0; ///< VTK's grid: 4 + 1 ids, a type, a label, a fifth of a point
constexpr double kDecimatorBytesPerCell = 91.0;
constexpr double kPyramidBytesPerVoxel = 0.15;
constexpr double kFixedBytes = 25.0 * 1024 * 1024;
/// Streamed (Streaming/StreamedPipeline.h; Benchmarks/README.md, "Memory"):
/// a block filled and decimated in place, per initial cell; the output held
/// while blocks go on and the last pass, per cell entering that pass; the share
/// of the initial cells that enter it (0.13-0.18 measured at 1M-cell blocks);
/// the image boundary, its certificates' neighbourhoods and flags, per face.
/// Refitted on 2026-12-05 (labels stored in one byte, border passes, pages
/// handed back per block): the six shared volumes at 0.98-1.13x their peak.
constexpr double kBlockBytesPerCell = 50.0;
constexpr double kOutputBytesPerCell = 30.0;
constexpr double kLastPassBytesPerCell = 105.0;
constexpr double kLastPassShare = 0.18;
constexpr double kStreamedBytesPerFace = 48.0;

/// The quadratic stage (Order 2), per voxel face between labels, beside the output it starts
/// from: its own structures (totalseg 510, digimouse 665 bytes a face measured), and its
/// measurements (the curved faces flattened for the distances each at its own step, the
/// measures' own structures: about 100-300 bytes a face on totalseg and digimouse since ae73cba,
/// 3,900 before). A mesh whose faces were all as bent as its most bent edge would flatten every
/// face at the finest step again and need up to that former figure: priced on real data, which
/// is far from it. Benchmarks/README.md, "Quadratic tetrahedra: time and memory".
constexpr double kQuadraticBytesPerFace = 650.0;
constexpr double kQuadraticMeasureBytesPerFace = 250.0;

double ImageBytes(const LabelImage& image)
{
  return (image.BytesPerLabel() + kPyramidBytesPerVoxel) * static_cast<double>(image.NumberOfVoxels());
}
} // namespace

std::uint64_t CountInterfaceFaces(const LabelImage& image)
{
  const int nx = image.Dimensions[0], ny = image.Dimensions[1], nz = image.Dimensions[2];
  const bool flat = image.Dimension() == 2;
  std::uint64_t faces = 0;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::int32_t l = image.Label(image.Index(i, j, k));
        // Each voxel owns its low faces; the image's high border adds the rest.
        faces += l != image.At(i - 1, j, k);
        faces += l != image.At(i, j - 1, k);
        faces += (i == nx - 1 && l != 0) + (j == ny - 1 && l != 0);
        if (!flat)
          faces += (l != image.At(i, j, k - 1)) + (k == nz - 1 && l != 0);
      }
  return faces;
}

MemoryEstimate EstimateMemory(const LabelImage& image, bool decimate)
{
  MemoryEstimate e;
  e.Voxels = image.NumberOfVoxels();
  e.InterfaceFaces = CountInterfaceFaces(image);
  const double perFace = image.Dimension() == 2 ? kCellsPerFace2D : kCellsPerFace3D;
  const double cells = perFace * static_cast<double>(e.InterfaceFaces) + kCellsPerVoxel * static_cast<double>(e.Voxels);
  e.InitialCells = static_cast<std::uint64_t>(cells);
  const double mesher = kMesherBytesPerCell * cells;
  const double decimator = decimate ? (kHeldBytesPerCell + kDecimatorBytesPerCell) * cells : 0.0;
  e.RunBytes = static_cast<std::uint64_t>(kFixedBytes + ImageBytes(image) +
    std::max(mesher, decimator));
  return e;
}

MemoryEstimate EstimateStreamedMemory(const LabelImage& image, std::uint64_t blockCells)
{
  // One block in flight (filled, then decimated in place) beside the output
  // so far; with several blocks, the last pass over the assembled mesh, a
  // share of the initial one, is the peak.
  MemoryEstimate e = EstimateMemory(image, false);
  const double cells = static_cast<double>(e.InitialCells);
  const bool oneBlock = blockCells == 0 || cells <= static_cast<double>(blockCells);
  const double block = oneBlock ? cells : static_cast<double>(blockCells);
  const double assembled = oneBlock ? 0.0 : kLastPassShare * cells;
  const double run = std::max(kBlockBytesPerCell * block + kOutputBytesPerCell * assembled,
    kLastPassBytesPerCell * assembled);
  e.RunBytes = static_cast<std::uint64_t>(kFixedBytes + ImageBytes(image) +
    kStreamedBytesPerFace * static_cast<double>(e.InterfaceFaces) + run);
  return e;
}

std::uint64_t SlabProcessFloorBytes()
{
  return static_cast<std::uint64_t>(kFixedBytes);
}

MemoryEstimate WithQuadraticStage(MemoryEstimate estimate, bool measured)
{
  // The stage runs once the decimation has let go of its blocks: its need adds to what the run
  // holds after it (the image, the output), which the streamed peak already covers.
  const double perFace = kQuadraticBytesPerFace + (measured ? kQuadraticMeasureBytesPerFace : 0.0);
  estimate.RunBytes += static_cast<std::uint64_t>(perFace * static_cast<double>(estimate.InterfaceFaces));
  return estimate;
}

std::uint64_t EstimateDecimationMemory(std::uint64_t cells)
{
  return static_cast<std::uint64_t>(kFixedBytes + kDecimatorBytesPerCell * static_cast<double>(cells));
}

std::string WithThousandsSeparators(std::uint64_t n)
{
  std::string digits = std::to_string(n);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3)
    digits.insert(static_cast<std::size_t>(at), ",");
  return digits;
}

std::string DescribeEstimate(const MemoryEstimate& estimate)
{
  return WithThousandsSeparators(estimate.Voxels) + " voxels, " + WithThousandsSeparators(estimate.InterfaceFaces) +
    " voxel faces between labels";
}

} // namespace labelmesher
