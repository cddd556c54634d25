// SPDX-License-Identifier: GPL-2.0-or-later
// LabelMesherBenchmarks: per-stage figures of MeshLabelImage (h(I,M) = h(M,I) = 2
// voxels), of DecimateMesh (the same bounds, 15 degrees) and of MeshAndDecimate
// (both, block by block: MeshAndDecimate/Cassini/N, up to 800, and at 1024 with every
// guarantee measured: MeshAndDecimateChecked/Cassini/1024) on the Cassini volumes
// of dissertation section 5.1.1 (100..400 voxels a side), on the shared real label
// volumes and on a batch of random property-test images. See Benchmarks/README.md
// for what each counter means.
#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"
#include "BenchmarkSupport.h"
#include "Checks/MeshChecks.h"
#include "Decimation/MeshDecimator.h"
#include "LabelOctreeMesher.h"
#include "RandomLabelImages.h"
#include "Streaming/StreamedPipeline.h"
#include "SyntheticShapes.h"
#include "LabelImageFile.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace labelmesher;
using benchmarks::CounterName;
using benchmarks::DataDirectory;
using benchmarks::MaxRssMiB;
using benchmarks::PeakRssMiB;
using benchmarks::ResetPeakRss;
using benchmarks::RssMiB;

namespace
{

using Clock = std::chrono::steady_clock;

MesherParameters H2()
{
  MesherParameters parameters;
  parameters.ImageToMeshDistance = 2.0;
  parameters.MeshToImageDistance = 2.0;
  return parameters;
}

/// Times MeshLabelImage(image, h = 2) and reports the counters.
void MeshAndReport(benchmark::State& state, const LabelImage& image)
{
  const MesherParameters parameters = H2();
  ResetPeakRss();
  const double rssBefore = RssMiB();
  double total = 0.0;
  benchmarks::StageTotals stages;
  std::size_t cells = 0, foregroundCells = 0, boundaryFaces = 0, leaves = 0;
  std::int64_t iterations = 0;
  try
  {
    for (auto _ : state)
    {
      const auto start = Clock::now();
      MesherResult result = MeshLabelImage(image, parameters);
      total += std::chrono::duration<double>(Clock::now() - start).count();
      stages.Add(result.Timings);
      cells = result.Mesh.NumberOfCells();
      foregroundCells = benchmarks::ForegroundCells(result.Mesh);
      boundaryFaces = result.Interfaces.NumberOfCells();
      leaves = result.NumberOfLeaves;
      ++iterations;
      benchmark::DoNotOptimize(result.Mesh.Points.data());
    }
  }
  catch (const std::exception& e)
  {
    state.SkipWithError(e.what());
    return;
  }
  if (iterations == 0)
    return;
  const double seconds = total / iterations;
  const double voxels = double(image.NumberOfVoxels());
  state.counters["voxels"] = voxels;
  state.counters["cells"] = double(cells);
  state.counters["fg_cells"] = double(foregroundCells);
  state.counters["bnd_faces"] = double(boundaryFaces);
  state.counters["leaves"] = double(leaves);
  state.counters["voxels/s"] = voxels / seconds;
  state.counters["cells/s"] = double(cells) / seconds;
  for (const auto& stage : stages.Order)
    state.counters[CounterName(stage)] = stages.Seconds[stage] / iterations;
  state.counters["rss_before_MiB"] = rssBefore;
  state.counters["peak_rss_MiB"] = PeakRssMiB();
  state.counters["maxrss_MiB"] = MaxRssMiB();
}

void BenchmarkCassini(benchmark::State& state, int n)
{
  // Built outside the timed loop: input preparation is not part of the figure.
  const LabelImage image = testing::MakeCassiniVolume(n);
  MeshAndReport(state, image);
}

void BenchmarkFile(benchmark::State& state, const std::string& path)
{
  // Read outside the timed loop: I/O is not part of the figure.
  LabelImage image;
  try
  {
    image = testing::ReadLabelImageFile(path).Image;
  }
  catch (const std::exception& e)
  {
    state.SkipWithError(e.what());
    return;
  }
  MeshAndReport(state, image);
}

/// Times DecimateMesh (h = 2, 15 degrees) on the mesh of `image` (meshed
/// outside the timed loop) and reports the counters.
void DecimateAndReport(benchmark::State& state, const LabelImage& image)
{
  SimplexMesh initial;
  try
  {
    initial = MeshLabelImage(image, H2()).Mesh;
  }
  catch (const std::exception& e)
  {
    state.SkipWithError(e.what());
    return;
  }
  DecimationParameters parameters;
  parameters.ImageToMeshDistance = parameters.MeshToImageDistance = 2.0;
  parameters.MinimumAngle = 15.0;
  ResetPeakRss();
  const double rssBefore = RssMiB();
  double total = 0.0;
  benchmarks::StageTotals stages;
  DecimationCounts counts;
  const std::size_t foregroundBefore = benchmarks::ForegroundCells(initial);
  std::size_t foregroundAfter = 0;
  std::int64_t iterations = 0;
  try
  {
    for (auto _ : state)
    {
      const auto start = Clock::now();
      DecimationResult result = DecimateMesh(image, initial, parameters);
      total += std::chrono::duration<double>(Clock::now() - start).count();
      stages.Add(result.Timings);
      counts = result.Counts;
      foregroundAfter = benchmarks::ForegroundCells(result.Mesh);
      ++iterations;
      benchmark::DoNotOptimize(result.Mesh.Points.data());
    }
  }
  catch (const std::exception& e)
  {
    state.SkipWithError(e.what());
    return;
  }
  if (iterations == 0)
    return;
  const double seconds = total / iterations;
  state.counters["cells_in"] = double(counts.CellsBefore);
  state.counters["cells_out"] = double(counts.CellsAfter);
  state.counters["fg_in"] = double(foregroundBefore);
  state.counters["fg_out"] = double(foregroundAfter);
  state.counters["merges"] = double(counts.Merges);
  state.counters["offers"] = double(counts.Offers);
  state.counters["cells/s"] = double(counts.CellsBefore) / seconds;
  state.counters["merges/s"] = double(counts.Merges) / seconds;
  for (const auto& stage : stages.Order)
    state.counters[CounterName(stage)] = stages.Seconds[stage] / iterations;
  state.counters["rss_before_MiB"] = rssBefore;
  state.counters["peak_rss_MiB"] = PeakRssMiB();
}

/// Times MeshAndDecimate (mesher and decimator block by block, h = 2, 15 degrees,
/// blocks of `blockCells`) on `image` and reports the counters: what enters and
/// leaves, the blocks, and the peak memory over what the process held with the
/// image (growth_MiB), which is what must follow the output, not the initial mesh.
/// The guarantees of `mesh` (decimated from `image` with `decimation`),
/// measured whole and timed, as counters; `violations` counts the broken ones.
void CheckGuarantees(benchmark::State& state, const LabelImage& image, const SimplexMesh& mesh,
  const DecimationParameters& decimation)
{
  auto timed = [&](const char* name, auto&& measure) {
    const auto start = Clock::now();
    measure();
    state.counters[std::string("s_check_") + name] = std::chrono::duration<double>(Clock::now() - start).count();
  };
  int violations = 0;
  timed("quality", [&] {
    const QualityReport q = MeasureQuality(mesh);
    state.counters["min_dihedral"] = q.MinimumAngle;
    state.counters["inverted"] = double(q.InvertedCells);
    violations += q.MinimumAngle < decimation.MinimumAngle - 1e-9 || q.InvertedCells > 0;
  });
  timed("conformity", [&] {
    const ConformityReport c = MeasureConformity(mesh);
    state.counters["conforming"] = c.Conforming();
    violations += !c.Conforming();
  });
  timed("hausdorff", [&] {
    const HausdorffReport h = MeasureHausdorff(image, mesh);
    double im = h.Overall.ImageToMesh, mi = h.Overall.MeshToImage;
    for (const auto& entry : h.PerMaterial)
    {
      im = std::max(im, entry.second.ImageToMesh);
      mi = std::max(mi, entry.second.MeshToImage);
    }
    state.counters["hIM_max"] = im;
    state.counters["hMI_max"] = mi;
    // The measurement is an upper bound tight to 1/1024 voxel.
    violations += im > decimation.ImageToMeshDistance + 1.0 / 512 || mi > decimation.MeshToImageDistance + 1.0 / 512;
  });
  timed("topology", [&] {
    std::size_t mismatches = 0;
    for (const auto& entry : CompareTopology(image, mesh))
      mismatches += !entry.second.Matches();
    state.counters["topology_mismatches"] = double(mismatches);
    violations += mismatches > 0;
  });
  state.counters["violations"] = violations;
}

/// With `check`, the decimated mesh's guarantees are then measured on the
/// whole mesh, independently of the decimator (MeshChecks.h), each timed:
/// smallest and largest dihedral angle and inverted cells, conformity, both
/// Hausdorff distances overall and per material, topology of every material.
void StreamAndReport(benchmark::State& state, const LabelImage& image, std::size_t blockCells, bool check = false)
{
  DecimationParameters decimation;
  decimation.ImageToMeshDistance = decimation.MeshToImageDistance = 2.0;
  decimation.MinimumAngle = 15.0;
  StreamingParameters streaming;
  streaming.BlockCells = blockCells;
  ResetPeakRss();
  const double rssBefore = RssMiB();
  double total = 0.0;
  benchmarks::StageTotals stages;
  StreamedResult last;
  std::size_t foregroundAfter = 0;
  std::int64_t iterations = 0;
  try
  {
    for (auto _ : state)
    {
      const auto start = Clock::now();
      StreamedResult result = MeshAndDecimate(image, H2(), decimation, streaming);
      total += std::chrono::duration<double>(Clock::now() - start).count();
      stages.Add(result.Decimated.Timings);
      last.Decimated.Counts = result.Decimated.Counts;
      last.Streaming = result.Streaming;
      foregroundAfter = benchmarks::ForegroundCells(result.Decimated.Mesh);
      ++iterations;
      benchmark::DoNotOptimize(result.Decimated.Mesh.Points.data());
      if (check)
        last.Decimated.Mesh = std::move(result.Decimated.Mesh);
    }
  }
  catch (const std::exception& e)
  {
    state.SkipWithError(e.what());
    return;
  }
  if (iterations == 0)
    return;
  const double seconds = total / iterations;
  const DecimationCounts& counts = last.Decimated.Counts;
  state.counters["voxels"] = double(image.NumberOfVoxels());
  state.counters["cells_in"] = double(counts.CellsBefore);
  state.counters["blocks"] = double(last.Streaming.Blocks);
  state.counters["assembled"] = double(last.Streaming.AssembledCells);
  state.counters["border_passes"] = double(last.Streaming.BorderPasses);
  state.counters["max_assembled"] = double(last.Streaming.LargestAssembledCells);
  state.counters["cells_out"] = double(counts.CellsAfter);
  state.counters["fg_out"] = double(foregroundAfter);
  state.counters["cells/s"] = double(counts.CellsBefore) / seconds;
  for (const auto& stage : stages.Order)
    state.counters[CounterName(stage)] = stages.Seconds[stage] / iterations;
  state.counters["rss_before_MiB"] = rssBefore;
  state.counters["peak_rss_MiB"] = PeakRssMiB();
  state.counters["growth_MiB"] = PeakRssMiB() - rssBefore;
  if (check)
    CheckGuarantees(state, image, last.Decimated.Mesh, decimation);
}

/// Meshes `count` random property-test images per iteration (seeds 0..count-1).
void BenchmarkRandomImages(benchmark::State& state, int dimension, int count)
{
  std::vector<LabelImage> images;
  std::size_t voxels = 0;
  for (int seed = 0; seed < count; ++seed)
  {
    images.push_back(testing::GenerateRandomLabelImage(std::uint64_t(seed), dimension));
    voxels += images.back().NumberOfVoxels();
  }
  const MesherParameters parameters = H2();
  ResetPeakRss();
  double total = 0.0;
  std::size_t cells = 0, failures = 0;
  std::int64_t iterations = 0;
  for (auto _ : state)
  {
    const auto start = Clock::now();
    cells = 0;
    failures = 0;
    for (const auto& image : images)
    {
      try
      {
        cells += MeshLabelImage(image, parameters).Mesh.NumberOfCells();
      }
      catch (const std::exception&)
      {
        ++failures;
      }
    }
    total += std::chrono::duration<double>(Clock::now() - start).count();
    ++iterations;
  }
  const double seconds = total / std::max<std::int64_t>(1, iterations);
  state.counters["images"] = double(count);
  state.counters["images/s"] = count / seconds;
  state.counters["voxels"] = double(voxels);
  state.counters["voxels/s"] = voxels / seconds;
  state.counters["cells"] = double(cells);
  state.counters["cells/s"] = cells / seconds;
  state.counters["failures"] = double(failures);
  state.counters["peak_rss_MiB"] = PeakRssMiB();
}

void RegisterAll()
{
  for (int n : { 100, 200, 300, 400 })
    benchmark::RegisterBenchmark(("MeshLabelImage/Cassini/" + std::to_string(n)).c_str(),
      [n](benchmark::State& state) { BenchmarkCassini(state, n); })
      ->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->UseRealTime();

  for (const std::string& path : testing::ListNrrdFiles(DataDirectory() + "/3d"))
  {
    const std::string name = std::filesystem::path(path).stem().string();
    benchmark::RegisterBenchmark(("MeshLabelImage/File/" + name).c_str(),
      [path](benchmark::State& state) { BenchmarkFile(state, path); })
      ->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->UseRealTime();
  }

  // The memory-growth table (Benchmarks/README.md, "Memory"): block by block, default blocks.
  // At scale (issue 32, item 4): 1024^3 voxels, then every guarantee measured on the whole mesh.
  for (int n : { 400, 1024 })
    benchmark::RegisterBenchmark(("MeshAndDecimateChecked/Cassini/" + std::to_string(n)).c_str(),
      [n](benchmark::State& state) {
        StreamAndReport(state, testing::MakeCassiniVolume(n), kDefaultBlockCells, true);
      })
      ->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->UseRealTime();
  for (int n : { 100, 200, 400, 800 })
    benchmark::RegisterBenchmark(("MeshAndDecimate/Cassini/" + std::to_string(n)).c_str(),
      [n](benchmark::State& state) { StreamAndReport(state, testing::MakeCassiniVolume(n), kDefaultBlockCells); })
      ->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->UseRealTime();

  for (int n : { 100, 200, 300, 400 })
    benchmark::RegisterBenchmark(("DecimateMesh/Cassini/" + std::to_string(n)).c_str(),
      [n](benchmark::State& state) { DecimateAndReport(state, testing::MakeCassiniVolume(n)); })
      ->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->UseRealTime();
  for (const std::string& path : testing::ListNrrdFiles(DataDirectory() + "/3d"))
  {
    const std::string name = std::filesystem::path(path).stem().string();
    benchmark::RegisterBenchmark(("DecimateMesh/File/" + name).c_str(),
      [path](benchmark::State& state) {
        try
        {
          DecimateAndReport(state, testing::ReadLabelImageFile(path).Image);
        }
        catch (const std::exception& e)
        {
          state.SkipWithError(e.what());
        }
      })
      ->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->UseRealTime();
  }

  for (int dimension : { 2, 3 })
    benchmark::RegisterBenchmark(("MeshLabelImage/RandomImages" + std::to_string(dimension) + "D/100").c_str(),
      [dimension](benchmark::State& state) { BenchmarkRandomImages(state, dimension, 100); })
      ->Unit(benchmark::kSecond)
      ->Iterations(1)
      ->UseRealTime();
}

} // namespace

int main(int argc, char** argv)
{
  labelmesher::SetMPIStarter(&labelmesher::StartMPI); // the core starts nothing itself
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  RegisterAll();
  // MPI and p4est start once per process (an MPI singleton start takes about
  // 0.3 s): done here, and reported, so that it is not charged to the first case.
  const auto startUp = Clock::now();
  MeshLabelImage(testing::MakeSphere(8, 3.0), MesherParameters{});
  benchmark::AddCustomContext("process start-up (MPI, p4est), once",
    std::to_string(std::chrono::duration<double>(Clock::now() - startUp).count()) + " s");
  benchmark::AddCustomContext("h(I,M)=h(M,I)", "2 voxels");
  benchmark::AddCustomContext("decimation angle", "15 degrees");
  benchmark::AddCustomContext("data", DataDirectory());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
