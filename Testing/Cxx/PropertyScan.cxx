// SPDX-License-Identifier: GPL-2.0-or-later
//
// labelmesher_property_scan: the property tests' assertions (MesherGuarantees.h,
// DecimatorGuarantees.h, CurverGuarantees.h) over as many seeded random images as one asks for,
// outside ctest. The CI suites run a few thousand images; the bugs they missed
// showed up at rates of 1 in 3,000 to 1 in 10,000, so run this with tens of
// thousands before trusting a change to the mesher's per-leaf tests or the
// decimator's checks. Prints every failing seed; exit status 1 if any.
//
//   labelmesher_property_scan [--decimate|--streamed CELLS [--processes N]|--curve|--order2] smooth|boxes|thin 2|3 FIRST_SEED COUNT [SIZE]
//
// --streamed CELLS: mesher and decimator block by block (StreamedPipeline.h),
// blocks of CELLS initial cells (a few dozen: every image crosses many
// borders); the decimated mesh must keep every guarantee. With
// LABELMESHER_SCAN_UNSOUND_BORDERS=1 in the environment the blocks do not
// freeze near image faces they cannot certify (unsound, to find images that
// show it).
// --processes N (after --streamed CELLS): each image stacked along its last
// axis (StackedAlongLastAxis) to at least 160 slices in 2D, 72 in 3D, and
// meshed on N processes run one after another (MeshOnQueuedRanks: every one
// but rank 0 from its slab of the image only) and on one; the two meshes must
// be the same, and nothing may go wrong between the processes. (The one-process
// mesh's guarantees are --streamed's.) Prints how many processes' slabs were
// shorter than the image.
//
// --decimate: mesher then decimator, with the angle drawn per seed
// (DrawDecimationParameters); the decimated mesh must keep every guarantee.
// --curve (2D only): mesher, decimator and curver, C1 or C2 drawn per seed
// (DrawSmoothness); the curved mesh must keep every guarantee of
// TestCurverProperties.
// --order2: in 3D, mesher, decimator and the quadratic curver; the quadratic
// mesh must keep every guarantee of TestQuadraticCurver (QuadraticGuarantees.h).
// In 2D, the curver making quadratic triangles (CurvingParameters::Order 2), with
// every guarantee of --curve and each cell exactly quadratic.
// With LABELMESHER_SCAN_UNCERTIFIED=distances (or =jacobians, =corners) in the
// environment the curver skips that certificate (to find images that show it
// is needed).
// smooth: GenerateRandomLabelImageWithDescription(seed, dimension) (the images
// of TestMesherProperties' MesherProperties suites); boxes:
// GenerateRandomBoxImage(seed, dimension, SIZE) (default 24 in 2D, 14 in 3D);
// thin: GenerateThinFeatureImage(seed, dimension, SIZE) (default 20 in 2D, 12 in 3D).
// Distance bounds: DrawDistanceBounds(seed), as in the tests.

#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"
#include "CurverGuarantees.h"
#include "DecimatorGuarantees.h"
#include "MesherGuarantees.h"
#include "QuadraticGuarantees.h"
#include "QueuedPartExchange.h"
#include "RandomLabelImages.h"
#include "ThinFeatureImages.h"

#include "Streaming/StreamedPipeline.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

using namespace labelmesher;

int main(int argc, char** argv)
{
  labelmesher::SetMPIStarter(&labelmesher::StartMPI); // the core starts nothing itself
  const bool curve = argc > 1 && std::string(argv[1]) == "--curve";
  const bool quadratic = argc > 1 && std::string(argv[1]) == "--order2";
  const bool streamed = argc > 2 && std::string(argv[1]) == "--streamed";
  const bool decimate = curve || quadratic || streamed || (argc > 1 && std::string(argv[1]) == "--decimate");
  QuadraticParameters quadraticCurver;
  if (const char* uncertified = std::getenv("LABELMESHER_SCAN_UNCERTIFIED"))
  {
    quadraticCurver.CertifyDistances = std::string(uncertified) != "distances";
    quadraticCurver.CertifyValidity = std::string(uncertified) != "jacobians";
    quadraticCurver.CertifyCorners = std::string(uncertified) != "corners";
  }
  quadraticCurver.MinimumScaledJacobian = testing::kQuadraticScaledJacobian;
  StreamingParameters streaming;
  int processes = 0;
  if (streamed)
  {
    streaming.BlockCells = std::strtoull(argv[2], nullptr, 10);
    streaming.FreezeNearBorders = std::getenv("LABELMESHER_SCAN_UNSOUND_BORDERS") == nullptr;
    ++argv;
    --argc;
    if (argc > 3 && std::string(argv[2]) == "--processes")
    {
      processes = std::atoi(argv[3]);
      if (processes < 2)
      {
        std::fprintf(stderr, "bad arguments: --processes needs 2 or more\n");
        return 2;
      }
      argv += 2;
      argc -= 2;
    }
  }
  if (decimate)
  {
    ++argv;
    --argc;
  }
  if (argc < 5)
  {
    std::fprintf(
      stderr, "usage: %s [--decimate|--streamed CELLS [--processes N]|--curve|--order2] smooth|boxes|thin 2|3 FIRST_SEED COUNT [SIZE]\n", argv[0]);
    return 2;
  }
  const std::string family = argv[1];
  const int dimension = std::atoi(argv[2]);
  const std::uint64_t first = std::strtoull(argv[3], nullptr, 10);
  const std::uint64_t count = std::strtoull(argv[4], nullptr, 10);
  const bool thin = family == "thin";
  const int size = argc > 5 ? std::atoi(argv[5]) : (dimension == 3 ? (thin ? 12 : 14) : (thin ? 20 : 24));
  if ((family != "smooth" && family != "boxes" && !thin) || (dimension != 2 && dimension != 3) || size < (thin ? 6 : 2))
  {
    std::fprintf(stderr, "bad arguments: family smooth, boxes or thin, dimension 2 or 3, size >= 2 (thin: >= 6)\n");
    return 2;
  }
  if (curve && dimension != 2)
  {
    std::fprintf(stderr, "bad arguments: --curve needs dimension 2\n");
    return 2;
  }
  // In 2D, --order2 is the curver's (quadratic triangles).
  const bool curveOrder2 = quadratic && dimension == 2;
  const bool quadratic3D = quadratic && dimension == 3;
  std::uint64_t misclassifiedLinear = 0, misclassifiedCurved = 0;
  std::uint64_t failures = 0, cellsBefore = 0, cellsAfter = 0, slabs = 0, shortSlabs = 0;
  for (std::uint64_t seed = first; seed < first + count; ++seed)
  {
    const testing::RandomLabelImage random = family == "smooth"
      ? testing::GenerateRandomLabelImageWithDescription(seed, dimension)
      : thin ? testing::GenerateThinFeatureImage(seed, dimension, size)
             : testing::GenerateRandomBoxImage(seed, dimension, size);
    const MesherParameters parameters = testing::DrawDistanceBounds(seed);
    const DecimationParameters decimation = testing::DrawDecimationParameters(seed, dimension, parameters);
    DecimationCounts counts;
    testing::CurverRun run;
    testing::QuadraticRun quadraticRun;
    const Smoothness smoothness = testing::DrawSmoothness(seed);
    if (processes > 0)
    {
      const int height = random.Image.Dimensions[static_cast<std::size_t>(random.Image.SlabAxis())];
      const LabelImage tall =
        testing::StackedAlongLastAxis(random.Image, std::max(2, ((dimension == 2 ? 160 : 72) + height - 1) / height));
      std::vector<std::string> problems;
      std::vector<std::array<int, 2>> taken;
      try
      {
        const StreamedResult one = MeshAndDecimate(tall, parameters, decimation, streaming);
        const StreamedResult shared =
          testing::MeshOnQueuedRanks(tall, parameters, decimation, streaming, processes, problems, &taken);
        const SimplexMesh& a = one.Decimated.Mesh;
        const SimplexMesh& b = shared.Decimated.Mesh;
        if (a.Points != b.Points || a.Connectivity != b.Connectivity || a.Materials != b.Materials)
          problems.push_back("the mesh on " + std::to_string(processes) + " processes differs from one process's");
      }
      catch (const std::exception& e)
      {
        problems.push_back(std::string("failed: ") + e.what());
      }
      const int slices = tall.Dimensions[static_cast<std::size_t>(tall.SlabAxis())];
      slabs += taken.size();
      shortSlabs += static_cast<std::uint64_t>(
        std::count_if(taken.begin(), taken.end(), [&](const auto& t) { return t[1] - t[0] < slices; }));
      if (problems.empty())
        continue;
      ++failures;
      std::printf("seed %llu FAILS on %d processes (blocks of %zu cells)\n", static_cast<unsigned long long>(seed),
        processes, streaming.BlockCells);
      for (const auto& problem : problems)
        std::printf("  %s\n", problem.c_str());
      std::fflush(stdout);
      continue;
    }
    const auto problems = curve || curveOrder2
      ? testing::ViolatedCurverGuarantees(random.Image, parameters, decimation, smoothness, &run,
          testing::kCurvedScaledJacobian, -1.0, curveOrder2 ? 2 : 3)
      : quadratic3D ? testing::ViolatedQuadraticGuarantees(random.Image, parameters, decimation, &quadraticRun, &quadraticCurver)
      : streamed ? testing::ViolatedStreamedGuarantees(random.Image, parameters, decimation, streaming, &counts)
      : decimate ? testing::ViolatedDecimatorGuarantees(random.Image, parameters, decimation, &counts)
                 : testing::ViolatedMesherGuarantees(random.Image, parameters);
    misclassifiedLinear += run.MisclassifiedLinear + quadraticRun.MisclassifiedLinear;
    misclassifiedCurved += run.MisclassifiedCurved + quadraticRun.MisclassifiedCurved;
    cellsBefore += counts.CellsBefore;
    cellsAfter += counts.CellsAfter;
    if (problems.empty())
      continue;
    ++failures;
    std::printf("seed %llu FAILS (h(I,M) <= %g, h(M,I) <= %g", static_cast<unsigned long long>(seed),
      parameters.ImageToMeshDistance, parameters.MeshToImageDistance);
    if (decimate)
      std::printf(", decimated at %g degrees", decimation.MinimumAngle);
    if (curve || curveOrder2)
      std::printf(", curved C%d", static_cast<int>(smoothness));
    if (quadratic)
      std::printf(", quadratic");
    std::printf(")\n");
    for (const auto& problem : problems)
      std::printf("  %s\n", problem.c_str());
    std::printf("%s", random.Describe().c_str());
    std::fflush(stdout);
  }
  if (processes > 0)
  {
    std::printf("streamed on %d processes %s %dD seeds %llu..%llu: %llu of %llu images differ from one process; "
                "%llu of %llu slabs shorter than the image\n",
      processes, family.c_str(), dimension, static_cast<unsigned long long>(first),
      static_cast<unsigned long long>(first + count - 1), static_cast<unsigned long long>(failures),
      static_cast<unsigned long long>(count), static_cast<unsigned long long>(shortSlabs),
      static_cast<unsigned long long>(slabs));
    return failures == 0 ? 0 : 1;
  }
  std::printf("%s%s %dD seeds %llu..%llu: %llu of %llu images violate a guarantee\n",
    curve ? "curved " : quadratic ? "quadratic " : streamed ? "streamed " : decimate ? "decimated " : "",
    family.c_str(), dimension, static_cast<unsigned long long>(first), static_cast<unsigned long long>(first + count - 1),
    static_cast<unsigned long long>(failures), static_cast<unsigned long long>(count));
  if (curve || curveOrder2)
    std::printf("misclassified pixels: %llu linear, %llu curved\n", static_cast<unsigned long long>(misclassifiedLinear),
      static_cast<unsigned long long>(misclassifiedCurved));
  else if (quadratic)
    std::printf("misclassified voxels: %llu linear, %llu quadratic\n", static_cast<unsigned long long>(misclassifiedLinear),
      static_cast<unsigned long long>(misclassifiedCurved));
  else if (decimate)
    std::printf("cells (background included): %llu before, %llu after decimation\n",
      static_cast<unsigned long long>(cellsBefore), static_cast<unsigned long long>(cellsAfter));
  return failures == 0 ? 0 : 1;
}
