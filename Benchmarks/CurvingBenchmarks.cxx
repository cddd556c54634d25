// SPDX-License-Identifier: GPL-2.0-or-later
// CurvingBenchmarks: per-stage figures of CurveMesh (dissertation chapter 4) on
// 2D meshes from MeshLabelImage: discs of growing size (untangling time against
// element count), the shared 2D label images, and a batch of random 2D images.
// The peer figure is our own linear mesher on the same image in the same run:
// `curve/mesh` is the curving time over the linear meshing time. See README.md.
#include "Curving/BezierCurver.h"
#include "BenchmarkSupport.h"
#include "LabelOctreeMesher.h"
#include "Mesh/MeshSelection.h"
#include "RandomLabelImages.h"
#include "SyntheticShapes.h"
#include "LabelImageFile.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <vector>

using namespace labelmesher;
using benchmarks::CounterName;
using benchmarks::DataDirectory;

namespace
{

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}


/// Meshes `image` at h = `h` (timed as the peer), then times CurveMesh (C2).
void CurveAndReport(benchmark::State& state, const LabelImage& image, double h)
{
  MesherParameters meshing;
  meshing.ImageToMeshDistance = meshing.MeshToImageDistance = h;
  CurvingParameters curving;
  curving.HasBorder = true;
  curving.Border = { -0.5, image.Dimensions[0] - 0.5, -0.5, image.Dimensions[1] - 0.5 };
  double meshSeconds = 0.0, curveSeconds = 0.0;
  benchmarks::StageTotals stages;
  std::size_t cells = 0, invalidBefore = 0, invalidAfter = 0;
  int steps = 0;
  std::int64_t iterations = 0;
  try
  {
    for (auto _ : state)
    {
      auto start = Clock::now();
      const SimplexMesh linear = SelectMaterials(MeshLabelImage(image, meshing).Mesh);
      meshSeconds += SecondsSince(start);
      start = Clock::now();
      const CurvingResult result = CurveMesh(linear, curving);
      curveSeconds += SecondsSince(start);
      stages.Add(result.Timings);
      cells = result.Mesh.Cells.size();
      invalidBefore = result.InvalidBeforeUntangling;
      invalidAfter = result.InvalidCells.size();
      steps = result.UntanglingSteps;
      ++iterations;
      benchmark::DoNotOptimize(result.Mesh.ControlPoints.data());
    }
  }
  catch (const std::exception& e)
  {
    state.SkipWithError(e.what());
    return;
  }
  if (iterations == 0)
    return;
  state.counters["pixels"] = double(image.NumberOfVoxels());
  state.counters["cells"] = double(cells);
  state.counters["cells/s"] = double(cells) * iterations / curveSeconds;
  state.counters["s_curve"] = curveSeconds / iterations;
  state.counters["s_mesh"] = meshSeconds / iterations;
  state.counters["curve/mesh"] = curveSeconds / meshSeconds;
  state.counters["invalid_before"] = double(invalidBefore);
  state.counters["invalid_after"] = double(invalidAfter);
  state.counters["steps"] = steps;
  for (const auto& stage : stages.Order)
    state.counters[CounterName(stage)] = stages.Seconds[stage] / iterations;
}

void BenchmarkDisc(benchmark::State& state, int n)
{
  const LabelImage image = testing::MakeDisc(n, 0.4 * n + 0.3);
  CurveAndReport(state, image, 1.0);
}

void BenchmarkFile(benchmark::State& state, const std::string& path)
{
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
  CurveAndReport(state, image, 2.0);
}

void BenchmarkRandomImages(benchmark::State& state, int count)
{
  std::vector<SimplexMesh> meshes;
  MesherParameters meshing; // h = 2
  for (int seed = 0; seed < count; ++seed)
    meshes.push_back(SelectMaterials(MeshLabelImage(testing::GenerateRandomLabelImage(std::uint64_t(seed), 2), meshing).Mesh));
  std::size_t cells = 0, invalidMeshes = 0;
  double seconds = 0.0;
  std::int64_t iterations = 0;
  for (auto _ : state)
  {
    const auto start = Clock::now();
    cells = invalidMeshes = 0;
    for (const SimplexMesh& mesh : meshes)
    {
      const CurvingResult result = CurveMesh(mesh, {});
      cells += result.Mesh.Cells.size();
      invalidMeshes += result.Valid ? 0 : 1;
    }
    seconds += SecondsSince(start);
    ++iterations;
  }
  state.counters["meshes"] = double(count);
  state.counters["cells"] = double(cells);
  state.counters["cells/s"] = double(cells) * iterations / seconds;
  state.counters["invalid_meshes"] = double(invalidMeshes);
}

void RegisterAll()
{
  for (int n : { 256, 512, 1024, 2048 })
    benchmark::RegisterBenchmark(("CurveMesh/Disc/" + std::to_string(n)).c_str(),
      [n](benchmark::State& state) { BenchmarkDisc(state, n); })
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1)
      ->UseRealTime();
  for (const std::string& path : testing::ListNrrdFiles(DataDirectory() + "/2d"))
  {
    const std::string name = path.substr(path.find_last_of('/') + 1);
    benchmark::RegisterBenchmark(("CurveMesh/File/" + name.substr(0, name.rfind('.'))).c_str(),
      [path](benchmark::State& state) { BenchmarkFile(state, path); })
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1)
      ->UseRealTime();
  }
  benchmark::RegisterBenchmark("CurveMesh/RandomImages2D/100",
    [](benchmark::State& state) { BenchmarkRandomImages(state, 100); })
    ->Unit(benchmark::kMillisecond)
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
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
