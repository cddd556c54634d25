// SPDX-License-Identifier: GPL-2.0-or-later
// LabelMesherBenchmarks: per-stage figures of MeshLabelImage (h(I,M) = h(M,I) = 2
// voxels) on the Cassini volumes of dissertation section 5.1.1 (100..400 voxels a
// side), on the shared real label volumes and on a batch of random property-test
// images. See Benchmarks/README.md for what each counter means.
#include "BenchmarkSupport.h"
#include "LabelOctreeMesher.h"
#include "RandomLabelImages.h"
#include "SyntheticShapes.h"
#include "LabelImageFile.h"

#include <benchmark/benchmark.h>

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

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

namespace
{

using Clock = std::chrono::steady_clock;

/// A field of /proc/self/status in MiB (its values are in kB); -1 if unknown.
double StatusMiB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(status, line))
    if (line.rfind(key, 0) == 0)
      return std::atof(line.c_str() + key.size()) / 1024.0;
  return -1.0;
}
/// Peak resident set (VmHWM) since the last ResetPeakRss().
double PeakRssMiB() { return StatusMiB("VmHWM"); }
/// Current resident set (VmRSS).
double RssMiB() { return StatusMiB("VmRSS"); }
/// Linux >= 4.0: writing 5 to clear_refs resets VmHWM to the current RSS, so
/// each benchmark case reports its own peak (ru_maxrss cannot be reset).
void ResetPeakRss()
{
#if defined(__GLIBC__)
  // Hand memory freed by earlier cases back to the system first, so the new
  // baseline is close to what this case itself holds.
  malloc_trim(0);
#endif
  std::ofstream clear("/proc/self/clear_refs");
  if (clear)
    clear << "5";
}
/// getrusage's ru_maxrss: the process's lifetime peak, in MiB.
double MaxRssMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kB on Linux
}

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
  std::map<std::string, double> stages;
  std::vector<std::string> stageOrder;
  std::size_t cells = 0, foregroundCells = 0, boundaryFaces = 0, leaves = 0;
  std::int64_t iterations = 0;
  try
  {
    for (auto _ : state)
    {
      const auto start = Clock::now();
      MesherResult result = MeshLabelImage(image, parameters);
      total += std::chrono::duration<double>(Clock::now() - start).count();
      for (const auto& timing : result.Timings)
      {
        if (!stages.count(timing.Stage))
          stageOrder.push_back(timing.Stage);
        stages[timing.Stage] += timing.Seconds;
      }
      cells = result.Mesh.NumberOfCells();
      foregroundCells = 0;
      for (auto m : result.Mesh.Materials)
        foregroundCells += m != 0;
      boundaryFaces = result.Boundary.NumberOfCells();
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
  for (const auto& stage : stageOrder)
    state.counters[CounterName(stage)] = stages[stage] / iterations;
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
  benchmark::AddCustomContext("data", DataDirectory());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
