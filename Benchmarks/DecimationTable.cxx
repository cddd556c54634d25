// SPDX-License-Identifier: GPL-2.0-or-later
//
// labelmesher_decimation_table: the dissertation's Table 2 (section 5.1.1) on our
// Cassini volume: foreground tetrahedra after mesher and decimator for
// h(I,M), h(M,I) in {0, 1, 2} and the angle in {5, 10, 15, 19.47} degrees, next
// to the dissertation's ORD counts, as a Markdown table (and the seconds each
// decimation took). The Cassini shape is our reconstruction
// (Testing/Cxx/Support/SyntheticShapes.h): the text gives no formula, so the
// comparison is of orders of magnitude, not of exact counts.
//
//   labelmesher_decimation_table [--cassini N] [--order shortest|queue] [--no-relocate] [--distances H1,H2]...
//
// N defaults to 400 (the table's size). The mesh of each pair of distances is
// made once and decimated at each angle. --distances (repeatable) keeps only
// those rows, in the order given, for the full size, where the whole table
// takes hours.

#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"
#include "BenchmarkSupport.h"
#include "Decimation/MeshDecimator.h"
#include "LabelOctreeMesher.h"
#include "SyntheticShapes.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

using namespace labelmesher;

namespace
{

/// Table 2's ORD column: tetrahedra for (h(I,M), h(M,I)) in row order
/// (0,0) (0,1) (0,2) (1,0) (1,1) (1,2) (2,0) (2,1) (2,2), angles 5, 10, 15, 19.47.
const long kDissertation[9][4] = {
  { 1804020, 1985280, 2198280, 2799217 },
  { 1772499, 1990606, 2338183, 3419832 },
  { 19294, 50621, 198320, 866719 },
  { 2536685, 2877747, 3263521, 4253085 },
  { 1769593, 1990916, 2329039, 3414341 },
  { 17004, 48846, 193271, 856591 },
  { 2031825, 2232203, 2454476, 3137021 },
  { 1747493, 1925185, 2186278, 3029784 },
  { 16826, 43744, 193687, 855199 },
};
const double kAngles[4] = { 5.0, 10.0, 15.0, 19.47 };

std::string Thousands(long n)
{
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i)
  {
    if (i > 0 && (digits.size() - i) % 3 == 0)
      out += ',';
    out += digits[i];
  }
  return out;
}

} // namespace

int main(int argc, char** argv)
{
  labelmesher::SetMPIStarter(&labelmesher::StartMPI); // the core starts nothing itself
  int n = 400;
  MergeOrder order = MergeOrder::ShortestEdgeFirst;
  bool relocate = true;
  std::vector<int> rows; // in the order asked for; all nine by default
  const char* usage = "usage: %s [--cassini N] [--order shortest|queue] [--no-relocate] [--distances H1,H2]...\n";
  for (int a = 1; a < argc; ++a)
  {
    if (!std::strcmp(argv[a], "--cassini") && a + 1 < argc)
      n = std::atoi(argv[++a]);
    else if (!std::strcmp(argv[a], "--order") && a + 1 < argc)
    {
      const std::string value = argv[++a];
      if (value != "shortest" && value != "queue")
      {
        std::fprintf(stderr, "--order expects shortest or queue\n");
        return 2;
      }
      order = value == "queue" ? MergeOrder::Queue : MergeOrder::ShortestEdgeFirst;
    }
    else if (!std::strcmp(argv[a], "--no-relocate"))
      relocate = false;
    else if (!std::strcmp(argv[a], "--distances") && a + 1 < argc)
    {
      int h1 = -1, h2 = -1;
      if (std::sscanf(argv[++a], "%d,%d", &h1, &h2) != 2 || h1 < 0 || h1 > 2 || h2 < 0 || h2 > 2)
      {
        std::fprintf(stderr, "--distances expects H1,H2 with each in {0, 1, 2}\n");
        return 2;
      }
      rows.push_back(3 * h1 + h2);
    }
    else
    {
      std::fprintf(stderr, usage, argv[0]);
      return 2;
    }
  }
  if (n < 16 || n > 2048)
  {
    std::fprintf(stderr, "--cassini expects a side between 16 and 2048 voxels\n");
    return 2;
  }
  const LabelImage image = testing::MakeCassiniVolume(n);
  std::printf("Cassini %d^3, %s first, %s; cells: foreground tetrahedra, ours / dissertation's ORD "
              "(decimation seconds)\n\n",
    n, order == MergeOrder::Queue ? "queue order" : "shortest edge",
    relocate ? "interior vertices relocated" : "merges only");
  std::printf("| h(I,M) | h(M,I) | initial |");
  for (double angle : kAngles)
    std::printf(" %g deg |", angle);
  std::printf("\n|---|---|---|---|---|---|---|\n");
  if (rows.empty())
    for (int row = 0; row < 9; ++row)
      rows.push_back(row);
  for (const int row : rows)
  {
    const double h1 = row / 3, h2 = row % 3;
    MesherParameters mesher;
    mesher.ImageToMeshDistance = h1;
    mesher.MeshToImageDistance = h2;
    const SimplexMesh initial = MeshLabelImage(image, mesher).Mesh;
    const long initialForeground = long(benchmarks::ForegroundCells(initial));
    std::printf("| %g | %g | %s |", h1, h2, Thousands(initialForeground).c_str());
    for (int column = 0; column < 4; ++column)
    {
      DecimationParameters parameters;
      parameters.ImageToMeshDistance = h1;
      parameters.MeshToImageDistance = h2;
      parameters.MinimumAngle = kAngles[column];
      parameters.Order = order;
      parameters.RelocateInteriorVertices = relocate;
      const auto start = std::chrono::steady_clock::now();
      const DecimationResult result = DecimateMesh(image, initial, parameters);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const long foreground = long(benchmarks::ForegroundCells(result.Mesh));
      std::printf(" %s / %s (%.1f s) |", Thousands(foreground).c_str(), Thousands(kDissertation[row][column]).c_str(),
        seconds);
      std::fflush(stdout);
    }
    std::printf("\n");
  }
  return 0;
}
