// SPDX-License-Identifier: GPL-2.0-or-later
//
// labelmesher_part_balance: how a run shared out over R processes
// (`mpirun -np R labelmesher mesh`, Streaming/StreamedPipeline.h's parts)
// divides its work and what it sends, for R = 2, 4, 8, 16 on this machine of
// two cores. The ranks run one after another in this process, each alone on
// one thread, their messages queued as they would travel (the core's
// PartExchange): so each rank's time is its own work, not a share of an
// oversubscribed core. Rank 0 also joins the parts and runs the last pass,
// after the others' parts arrive; it first plans the parts and sends each
// other rank its assignment, which that rank waits for (counted in its
// seconds). Per R it prints every rank's seconds, the bytes rank 0 assigned
// and the bytes sent to it, the slabs of the image the other ranks hold (mean
// and largest share of its slices), the balance of the ranks that mesh parts (largest over mean),
// and a projection of the run's wall time on R cores: rank 0's joining
// after the slowest rank's meshing (it meshes its own parts meanwhile).
//
//   labelmesher_part_balance --cassini 400 [--ranks 2,4,8,16] [--block-cells N] [--part-blocks N]
//   labelmesher_part_balance FILE.nrrd ...

#include "LabelImageFile.h"
#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"
#include "QueuedPartExchange.h"
#include "Streaming/MeshPart.h"
#include "Streaming/StreamedPipeline.h"
#include "Support/ParallelChunks.h"
#include "SyntheticShapes.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <deque>
#include <exception>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace labelmesher;

namespace
{

std::size_t BytesSent(const testing::QueuedRun& run)
{
  std::size_t bytes = 0;
  for (const auto& [rank, sent] : run.BytesSent)
    bytes += sent;
  return bytes;
}

/// What rank 0 sent the others before they meshed: their assignments (leaves of their parts).
std::size_t BytesAssigned(const testing::QueuedRun& run)
{
  std::size_t bytes = 0;
  for (const auto& [rank, assignment] : run.Assignments)
    bytes += assignment.size();
  return bytes;
}

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// Seconds of rank 0's stages that join the parts: the passes between parts and the last pass.
double JoiningSeconds(const std::vector<StageTiming>& timings)
{
  double joining = 0.0;
  for (const StageTiming& t : timings)
    if (t.Stage.rfind("joining parts: ", 0) == 0 || t.Stage.rfind("last pass: ", 0) == 0)
      joining += t.Seconds;
  return joining;
}

/// The slabs of the image the other ranks hold (slices along its last axis, with the margin),
/// as shares of its slices: their mean and the largest, over the ranks that have parts.
std::pair<double, double> SlabShares(const testing::QueuedRun& run, const LabelImage& image)
{
  const double slices = image.Dimensions[static_cast<std::size_t>(image.SlabAxis())];
  double sum = 0.0, largest = 0.0;
  int counted = 0;
  for (const auto& [rank, bytes] : run.Assignments)
  {
    const PartAssignment assignment = UnpackPartAssignment(bytes);
    if (assignment.Leaves.empty())
      continue;
    const double share = (assignment.SlabEnd - assignment.SlabFirst) / slices;
    sum += share;
    largest = std::max(largest, share);
    ++counted;
  }
  return { counted > 0 ? sum / counted : 0.0, largest };
}

} // namespace

int main(int argc, char* argv[])
{
  SetMPIStarter(&StartMPI);
  std::vector<int> rankCounts{ 2, 4, 8, 16 };
  StreamingParameters streaming;
  LabelImage image;
  std::string name;
  try
  {
    for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      auto next = [&]() -> std::string {
        if (i + 1 >= argc)
          throw std::invalid_argument(a + " needs a value");
        return argv[++i];
      };
      if (a == "--cassini")
      {
        const int n = std::stoi(next());
        image = testing::MakeCassiniVolume(n);
        name = "cassini" + std::to_string(n);
      }
      else if (a == "--ranks")
      {
        rankCounts.clear();
        std::stringstream list(next());
        for (std::string r; std::getline(list, r, ',');)
          rankCounts.push_back(std::stoi(r));
      }
      else if (a == "--block-cells")
        streaming.BlockCells = std::stoull(next());
      else if (a == "--part-blocks")
        streaming.PartBlocks = std::stoull(next());
      else
      {
        image = testing::ReadLabelImageFile(a).Image;
        name = a.substr(a.find_last_of('/') + 1);
      }
    }
    if (name.empty())
      throw std::invalid_argument("usage: labelmesher_part_balance (--cassini N | FILE) [--ranks 2,4,8,16] "
                                  "[--block-cells N] [--part-blocks N]");
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "labelmesher_part_balance: %s\n", e.what());
    return 2;
  }
  SetThreadLimit(1);
  const MesherParameters mesher;
  const DecimationParameters decimation;

  // One process, for the reference mesh and time.
  auto start = std::chrono::steady_clock::now();
  const StreamedResult one = MeshAndDecimate(image, mesher, decimation, streaming);
  const double oneSeconds = Seconds(start);
  std::printf("%s: %zu blocks in %zu parts of %zu, %zu cells; one process, one thread: %.2f s\n", name.c_str(),
    one.Streaming.Blocks, one.Streaming.Parts, streaming.PartBlocks, one.Decimated.Mesh.NumberOfCells(), oneSeconds);
  std::printf("%6s %9s %9s %9s %8s %12s %12s %10s %9s %10s %9s %s\n", "ranks", "max s", "mean s", "rank0 s",
    "balance", "bytes from 0", "bytes to 0", "joining s", "proj. s", "mean slab", "max slab", "same mesh");
  for (int ranks : rankCounts)
  {
    testing::QueuedRun run;
    // The others start once rank 0 has planned the parts and sent their assignments.
    start = std::chrono::steady_clock::now();
    if (ranks > 1)
    {
      testing::AssignBeforehand(run, ranks, [&](testing::QueuedPartExchange& zero) {
        MeshAndDecimate(image, mesher, decimation, streaming, {}, &zero);
      });
    }
    const double planSeconds = Seconds(start);
    std::vector<double> seconds(static_cast<std::size_t>(ranks), 0.0);
    for (int r = ranks - 1; r >= 0; --r)
    {
      testing::QueuedPartExchange exchange(r, ranks, run);
      start = std::chrono::steady_clock::now();
      const StreamedResult result = MeshAndDecimate(image, mesher, decimation, streaming, {}, &exchange);
      seconds[static_cast<std::size_t>(r)] = Seconds(start) + (r == 0 ? 0.0 : planSeconds);
      if (r == 0)
      {
        const bool same = result.Decimated.Mesh.Points == one.Decimated.Mesh.Points &&
          result.Decimated.Mesh.Connectivity == one.Decimated.Mesh.Connectivity &&
          result.Decimated.Mesh.Materials == one.Decimated.Mesh.Materials;
        // Rank 0 meshes its own parts while the others mesh theirs, then joins: the
        // last pass (and the border passes between parts) waits for the slowest rank.
        const double joining = JoiningSeconds(result.Decimated.Timings);
        const double meshing0 = seconds[0] - joining;
        const double slowest = ranks > 1 ? *std::max_element(seconds.begin() + 1, seconds.end()) : 0.0;
        const double mean = std::accumulate(seconds.begin() + 1, seconds.end(), meshing0) / ranks;
        const double largest = std::max(meshing0, slowest);
        const auto [meanSlab, largestSlab] = SlabShares(run, image);
        std::printf("%6d %9.2f %9.2f %9.2f %8.2f %12zu %12zu %10.2f %9.2f %9.0f%% %8.0f%% %s\n", ranks, largest, mean,
          seconds[0], largest / mean, BytesAssigned(run), BytesSent(run), joining, largest + joining,
          100.0 * meanSlab, 100.0 * largestSlab, same ? "yes" : "NO");
      }
    }
  }
  return 0;
}
