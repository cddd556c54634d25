// SPDX-License-Identifier: GPL-2.0-or-later
// CurvingBenchmarks: per-stage figures of CurveMesh (dissertation chapter 4) in
// the pipeline of `labelmesher curve`: MeshLabelImage, DecimateMesh (15
// degrees), then CurveMesh with the image and the same bounds (C1 fitted, the
// default; C2 for the shared images too), on discs of growing size, the shared
// 2D label images, and a batch of random 2D images. The peer figure is our own
// linear mesher on the same image in the same run: `curve/mesh` is the curving
// time over the linear meshing time. See README.md.
#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"
#include "Curving/BezierCurver.h"
#include "Curving/CurvedMeshLocator.h"
#include "Decimation/MeshDecimator.h"
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


/// The curver's parameters for `image` at bound h: the image, its border, the bounds.
CurvingParameters CurvingFor(const LabelImage& image, double h, Smoothness smoothness)
{
  CurvingParameters curving;
  curving.Smoothing.Continuity = smoothness;
  curving.HasBorder = true;
  curving.Border = { -0.5, image.Dimensions[0] - 0.5, -0.5, image.Dimensions[1] - 0.5 };
  curving.Image = { &image, { 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 } };
  curving.Bounds.ImageToMesh = curving.Bounds.MeshToImage = h;
  return curving;
}

/// Meshes `image` at h = `h` (timed as the peer), decimates it, then times CurveMesh.
void CurveAndReport(benchmark::State& state, const LabelImage& image, double h, Smoothness smoothness)
{
  MesherParameters meshing;
  meshing.ImageToMeshDistance = meshing.MeshToImageDistance = h;
  DecimationParameters decimation;
  decimation.ImageToMeshDistance = decimation.MeshToImageDistance = h;
  const CurvingParameters curving = CurvingFor(image, h, smoothness);
  double meshSeconds = 0.0, decimateSeconds = 0.0, curveSeconds = 0.0;
  benchmarks::StageTotals stages;
  std::size_t linearCells = 0, cells = 0, invalidBefore = 0, invalidAfter = 0, shortened = 0, pieces = 0;
  std::size_t misclassifiedLinear = 0, misclassifiedCurved = 0;
  int steps = 0, rounds = 0;
  std::int64_t iterations = 0;
  try
  {
    for (auto _ : state)
    {
      auto start = Clock::now();
      const SimplexMesh initial = MeshLabelImage(image, meshing).Mesh;
      meshSeconds += SecondsSince(start);
      start = Clock::now();
      const SimplexMesh linear = SelectMaterials(DecimateMesh(image, initial, decimation).Mesh);
      decimateSeconds += SecondsSince(start);
      start = Clock::now();
      const CurvingResult result = CurveMesh(linear, curving);
      curveSeconds += SecondsSince(start);
      stages.Add(result.Timings);
      linearCells = linear.NumberOfCells();
      cells = result.Mesh.Cells.size();
      invalidBefore = result.InvalidBeforeUntangling;
      invalidAfter = result.InvalidCells.size();
      steps = result.UntanglingSteps;
      rounds = result.UntanglingRounds;
      shortened = result.ShortenedPieces;
      pieces = result.Pieces.size();
      const std::array<double, 6> identity{ 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 };
      misclassifiedLinear = MeasurePixelAccuracy(MakeStraightCurvedMesh(result.Linear), image, identity).Misclassified;
      misclassifiedCurved = MeasurePixelAccuracy(result.Mesh, image, identity).Misclassified;
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
  state.counters["linear_cells"] = double(linearCells);
  state.counters["cells"] = double(cells);
  state.counters["cells/s"] = double(cells) * iterations / curveSeconds;
  state.counters["s_curve"] = curveSeconds / iterations;
  state.counters["s_mesh"] = meshSeconds / iterations;
  state.counters["s_decimate"] = decimateSeconds / iterations;
  state.counters["curve/mesh"] = curveSeconds / meshSeconds;
  state.counters["invalid_before"] = double(invalidBefore);
  state.counters["invalid_after"] = double(invalidAfter);
  state.counters["steps"] = steps;
  state.counters["rounds"] = rounds;
  state.counters["pieces"] = double(pieces);
  state.counters["shortened"] = double(shortened);
  state.counters["misclassified_linear"] = double(misclassifiedLinear);
  state.counters["misclassified_curved"] = double(misclassifiedCurved);
  for (const auto& stage : stages.Order)
    state.counters[CounterName(stage)] = stages.Seconds[stage] / iterations;
}

void BenchmarkDisc(benchmark::State& state, int n)
{
  const LabelImage image = testing::MakeDisc(n, 0.4 * n + 0.3);
  CurveAndReport(state, image, 1.0, Smoothness::C1);
}

void BenchmarkFile(benchmark::State& state, const std::string& path, Smoothness smoothness)
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
  CurveAndReport(state, image, 2.0, smoothness);
}

void BenchmarkRandomImages(benchmark::State& state, int count)
{
  std::vector<LabelImage> images;
  std::vector<SimplexMesh> meshes;
  MesherParameters meshing; // h = 2
  DecimationParameters decimation;
  for (int seed = 0; seed < count; ++seed)
  {
    images.push_back(testing::GenerateRandomLabelImage(std::uint64_t(seed), 2));
    meshes.push_back(SelectMaterials(DecimateMesh(images.back(), MeshLabelImage(images.back(), meshing).Mesh, decimation).Mesh));
  }
  std::size_t cells = 0, invalidMeshes = 0;
  double seconds = 0.0;
  std::int64_t iterations = 0;
  for (auto _ : state)
  {
    const auto start = Clock::now();
    cells = invalidMeshes = 0;
    for (std::size_t k = 0; k < meshes.size(); ++k)
    {
      const CurvingResult result = CurveMesh(meshes[k], CurvingFor(images[k], 2.0, Smoothness::C1));
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
    for (const Smoothness smoothness : { Smoothness::C1, Smoothness::C2 })
      benchmark::RegisterBenchmark(("CurveMesh/File/" + name.substr(0, name.rfind('.')) +
                                     (smoothness == Smoothness::C1 ? "/C1" : "/C2")).c_str(),
        [path, smoothness](benchmark::State& state) { BenchmarkFile(state, path, smoothness); })
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
  labelmesher::SetMPIStarter(&labelmesher::StartMPI); // the core starts nothing itself
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  RegisterAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
