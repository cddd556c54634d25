// SPDX-License-Identifier: GPL-2.0-or-later
// labelmesher_compare_cgal: meshes one label image with CGAL 5.5 Mesh_3
// (labelled image domain, every connected component seeded, fixed random seed)
// and with LabelMesher's whole pipeline, MeshAndDecimate (mesher and decimator
// block by block, Streaming/StreamedPipeline.h; h(I,M) = h(M,I) = 2, 15 degrees), measures both meshes with the same checks
// (MeshChecks.h) in the same index space, and prints them side by side with
// ratios ours/CGAL, peak memory included. Reading and writing files are left
// out on both sides (as the dissertation's timings leave them out). See
// Benchmarks/README.md.
//
//   labelmesher_compare_cgal [options] (FILE.nrrd | --cassini N)
//     --facet-distance D  CGAL facet_distance in voxels          (1)
//     --facet-size S      CGAL facet_size in voxels               (4)
//     --cell-size S       CGAL cell_size in voxels                (8)
//     --facet-angle A     CGAL facet_angle in degrees             (30)
//     --cell-ratio R      CGAL cell_radius_edge_ratio             (3)
//     --no-optimise       CGAL: no_perturb, no_exude (default: perturb + exude)
//     --no-seeding        CGAL: its default random initial points
//     --seed S            CGAL::get_default_random() = CGAL::Random(S)   (0)
//     --h H               our h(I,M) = h(M,I) in voxels            (2)
//     --min-angle DEG     our decimation angle in degrees         (15)
//     --no-decimate       ours: the initial mesh only (MeshLabelImage)
//     --block-cells N     ours: initial cells per block (1000000; 0: one block)
//     --order 2           ours: also the quadratic mesh (Quadratic/QuadraticCurver.h), its
//                         time and its misclassified voxels (cells refined at step 1/4)
//     --name NAME         label for the SUMMARY line
// Misclassified voxels (centre in a cell of another material, or in none with a non-zero label:
// Checks/QuadraticVolume.h) are counted by the same check for both. The last lines are
// machine-readable:
//   SUMMARY name t_ours t_cgal cells_ours cells_cgal mindih_ours mindih_cgal
//           hIM_ours hIM_cgal hMI_ours hMI_cgal topo_ours topo_cgal peakMiB_ours peakMiB_cgal
//   ACCURACY name voxels misclassified_ours misclassified_cgal misclassified_quadratic t_quadratic
//           (the last two -1 without --order 2)
#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"
#include "BenchmarkSupport.h"
#include "CGALImageMesher.h"
#include "Decimation/MeshDecimator.h"
#include "LabelOctreeMesher.h"
#include "Streaming/StreamedPipeline.h"
#include "Checks/MeshChecks.h"
#include "Checks/QuadraticVolume.h"
#include "Quadratic/QuadraticCurver.h"
#include "SyntheticShapes.h"
#include "LabelImageFile.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace labelmesher;

namespace
{

struct Measured
{
  double Seconds = 0.0;
  double PeakMiB = 0.0; ///< resident memory at the peak, less what the process held before
  std::size_t Misclassified = 0; ///< voxels (MeasureVoxelAccuracy)
  std::vector<std::pair<std::string, double>> Timings;
  std::size_t Cells = 0;    ///< foreground cells (label != 0)
  std::size_t Vertices = 0; ///< vertices used by foreground cells
  QualityReport Quality;    ///< over foreground cells
  std::map<std::int32_t, QualityReport> QualityPerLabel;
  std::map<std::int32_t, std::size_t> CellsPerLabel;
  HausdorffReport Distances;
  std::map<std::int32_t, TopologyComparison> Topology;
  std::size_t TopologyMatches = 0;
};

/// Cells of `mesh` whose material satisfies `keep`, with their points re-indexed.
template <class Keep>
SimplexMesh SubMesh(const SimplexMesh& mesh, Keep keep)
{
  SimplexMesh sub;
  sub.Dimension = mesh.Dimension;
  std::vector<std::int64_t> map(mesh.Points.size(), -1);
  const int nv = mesh.VerticesPerCell();
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    if (!keep(mesh.Materials[c]))
      continue;
    const std::int64_t* cell = mesh.Cell(c);
    for (int v = 0; v < nv; ++v)
    {
      auto& m = map[std::size_t(cell[v])];
      if (m < 0)
      {
        m = std::int64_t(sub.Points.size());
        sub.Points.push_back(mesh.Points[std::size_t(cell[v])]);
      }
      sub.Connectivity.push_back(m);
    }
    sub.Materials.push_back(mesh.Materials[c]);
  }
  return sub;
}

void Measure(const LabelImage& image, const SimplexMesh& mesh, Measured& out)
{
  const SimplexMesh foreground = SubMesh(mesh, [](std::int32_t m) { return m != 0; });
  out.Cells = foreground.NumberOfCells();
  out.Vertices = foreground.Points.size();
  out.Quality = MeasureQuality(foreground);
  std::set<std::int32_t> labels(foreground.Materials.begin(), foreground.Materials.end());
  for (std::int32_t l : labels)
  {
    const SimplexMesh part = SubMesh(foreground, [l](std::int32_t m) { return m == l; });
    out.CellsPerLabel[l] = part.NumberOfCells();
    out.QualityPerLabel[l] = MeasureQuality(part);
  }
  out.Distances = MeasureHausdorff(image, mesh);
  out.Misclassified = MeasureVoxelAccuracy(image, mesh).Misclassified;
  out.Topology = CompareTopology(image, mesh);
  for (const auto& [label, t] : out.Topology)
    out.TopologyMatches += t.Matches();
}

std::string Fixed(double v, int digits = 3)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}
std::string Ratio(double ours, double theirs)
{
  if (theirs == 0.0)
    return ours == 0.0 ? "1" : "inf";
  return Fixed(ours / theirs, 3);
}

void Row(const std::string& what, const std::string& ours, const std::string& cgal, const std::string& ratio)
{
  std::printf("  %-26s %16s %16s %10s\n", what.c_str(), ours.c_str(), cgal.c_str(), ratio.c_str());
}

[[noreturn]] void Usage(const char* message)
{
  std::fprintf(stderr,
    "error: %s\nusage: labelmesher_compare_cgal [--facet-distance D] [--facet-size S] [--cell-size S]\n"
    "  [--facet-angle A] [--cell-ratio R] [--no-optimise] [--no-seeding] [--seed S] [--h H]\n"
    "  [--min-angle DEG] [--no-decimate] [--name NAME] (FILE.nrrd | --cassini N)\n",
    message);
  std::exit(2);
}

} // namespace

int main(int argc, char** argv)
{
  labelmesher::SetMPIStarter(&labelmesher::StartMPI); // the core starts nothing itself
  benchmarks::CGALMeshOptions cgal;
  double h = 2.0, minimumAngle = 15.0;
  bool decimate = true;
  int order = 1;
  StreamingParameters streaming;
  int cassini = 0;
  std::string file, name;
  for (int a = 1; a < argc; ++a)
  {
    const std::string arg = argv[a];
    auto value = [&]() -> double {
      if (a + 1 >= argc)
        Usage(("missing value after " + arg).c_str());
      return std::atof(argv[++a]);
    };
    if (arg == "--facet-distance")
      cgal.FacetDistance = value();
    else if (arg == "--facet-size")
      cgal.FacetSize = value();
    else if (arg == "--cell-size")
      cgal.CellSize = value();
    else if (arg == "--facet-angle")
      cgal.FacetAngle = value();
    else if (arg == "--cell-ratio")
      cgal.CellRadiusEdgeRatio = value();
    else if (arg == "--no-optimise" || arg == "--no-optimize")
      cgal.Optimise = false;
    else if (arg == "--no-seeding")
      cgal.SeedComponents = false;
    else if (arg == "--seed")
      cgal.Seed = static_cast<unsigned>(value());
    else if (arg == "--h")
      h = value();
    else if (arg == "--min-angle")
      minimumAngle = value();
    else if (arg == "--no-decimate")
      decimate = false;
    else if (arg == "--order")
      order = static_cast<int>(value());
    else if (arg == "--block-cells")
      streaming.BlockCells = static_cast<std::size_t>(value());
    else if (arg == "--cassini")
      cassini = static_cast<int>(value());
    else if (arg == "--name")
    {
      if (a + 1 >= argc)
        Usage("missing value after --name");
      name = argv[++a];
    }
    else if (!arg.empty() && arg[0] == '-')
      Usage(("unknown option " + arg).c_str());
    else
      file = arg;
  }
  if ((cassini > 0) == !file.empty())
    Usage("give exactly one input: a label image file or --cassini N");

  LabelImage image;
  try
  {
    if (cassini > 0)
    {
      image = testing::MakeCassiniVolume(cassini);
      if (name.empty())
        name = "cassini" + std::to_string(cassini);
    }
    else
    {
      image = testing::ReadLabelImageFile(file).Image;
      if (name.empty())
        name = std::filesystem::path(file).stem().string();
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }

  std::map<std::int32_t, std::size_t> voxelsPerLabel;
  image.WithLabels([&](const auto* labels) {
    for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
      ++voxelsPerLabel[labels[v]];
  });
  std::printf("input %s: %d x %d x %d voxels, %zu labels besides 0\n", name.c_str(), image.Dimensions[0],
    image.Dimensions[1], image.Dimensions[2], voxelsPerLabel.size() - (voxelsPerLabel.count(0) ? 1 : 0));
  if (decimate)
    std::printf("ours: MeshAndDecimate (blocks of %zu initial cells), h(I,M) = h(M,I) = %g voxels, %g degrees\n",
      streaming.BlockCells, h, minimumAngle);
  else
    std::printf("ours: MeshLabelImage h(I,M) = h(M,I) = %g voxels (not decimated)\n", h);
  std::printf("CGAL: Mesh_3 labelled image, facet_angle %g, facet_size %g, facet_distance %g, "
              "cell_radius_edge_ratio %g, cell_size %g, %s, %s, seed %u\n",
    cgal.FacetAngle, cgal.FacetSize, cgal.FacetDistance, cgal.CellRadiusEdgeRatio, cgal.CellSize,
    cgal.Optimise ? "perturb+exude" : "no_perturb+no_exude",
    cgal.SeedComponents ? "every component seeded" : "default random initial points", cgal.Seed);
  std::fflush(stdout);

  Measured ours, theirs;
  double quadraticSeconds = -1.0;
  long long quadraticMisclassified = -1;
  try
  {
    MesherParameters parameters;
    parameters.ImageToMeshDistance = h;
    parameters.MeshToImageDistance = h;
    // MPI and p4est start once per process (about 0.3 s): not part of meshing
    // this image, so started on a tiny image first, as CGAL has no such cost.
    MeshLabelImage(testing::MakeSphere(8, 3.0), parameters);
    benchmarks::ResetPeakRss();
    const double before = benchmarks::RssMiB();
    const auto start = std::chrono::steady_clock::now();
    SimplexMesh mesh;
    if (decimate)
    {
      DecimationParameters decimation;
      decimation.ImageToMeshDistance = decimation.MeshToImageDistance = h;
      decimation.MinimumAngle = minimumAngle;
      StreamedResult streamed = MeshAndDecimate(image, parameters, decimation, streaming);
      for (const auto& t : streamed.Decimated.Timings)
        ours.Timings.emplace_back(t.Stage, t.Seconds);
      mesh = std::move(streamed.Decimated.Mesh);
    }
    else
    {
      MesherResult result = MeshLabelImage(image, parameters);
      for (const auto& t : result.Timings)
        ours.Timings.emplace_back(t.Stage, t.Seconds);
      mesh = std::move(result.Mesh);
    }
    ours.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ours.PeakMiB = benchmarks::PeakRssMiB() - before;
    Measure(image, mesh, ours);
    if (order == 2)
    {
      QuadraticParameters quadratic;
      quadratic.ImageToMeshDistance = quadratic.MeshToImageDistance = h;
      quadratic.MinimumCornerAngle = minimumAngle; // the corners keep the decimator's angle
      const auto curveStart = std::chrono::steady_clock::now();
      const QuadraticResult curved = CurveQuadratic(mesh, image, quadratic);
      quadraticSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - curveStart).count();
      quadraticMisclassified =
        static_cast<long long>(MeasureVoxelAccuracy(image, RefineQuadraticMesh(curved.Mesh, 4)).Misclassified);
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "error: MeshLabelImage: %s\n", e.what());
    return 1;
  }
  try
  {
    benchmarks::ResetPeakRss();
    const double before = benchmarks::RssMiB();
    benchmarks::CGALMeshResult result = benchmarks::MeshWithCGAL(image, cgal);
    theirs.PeakMiB = benchmarks::PeakRssMiB() - before;
    theirs.Seconds = result.Seconds;
    theirs.Timings = result.Timings;
    Measure(image, result.Mesh, theirs);
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "error: CGAL: %s\n", e.what());
    return 1;
  }

  auto stages = [](const Measured& m) {
    std::string s;
    for (const auto& [stage, seconds] : m.Timings)
      s += (s.empty() ? "" : ", ") + stage + " " + Fixed(seconds, 3);
    return s;
  };
  std::printf("\nstages ours [s]: %s\nstages CGAL [s]: %s\n\n", stages(ours).c_str(), stages(theirs).c_str());
  std::printf("  %-26s %16s %16s %10s\n", "overall", "LabelMesher", "CGAL", "ours/CGAL");
  Row("time [s]", Fixed(ours.Seconds), Fixed(theirs.Seconds), Ratio(ours.Seconds, theirs.Seconds));
  Row("tetrahedra (label != 0)", std::to_string(ours.Cells), std::to_string(theirs.Cells),
    Ratio(double(ours.Cells), double(theirs.Cells)));
  Row("vertices", std::to_string(ours.Vertices), std::to_string(theirs.Vertices),
    Ratio(double(ours.Vertices), double(theirs.Vertices)));
  Row("min dihedral [deg]", Fixed(ours.Quality.MinimumAngle, 2), Fixed(theirs.Quality.MinimumAngle, 2),
    Ratio(ours.Quality.MinimumAngle, theirs.Quality.MinimumAngle));
  Row("max dihedral [deg]", Fixed(ours.Quality.MaximumAngle, 2), Fixed(theirs.Quality.MaximumAngle, 2),
    Ratio(ours.Quality.MaximumAngle, theirs.Quality.MaximumAngle));
  Row("inverted cells", std::to_string(ours.Quality.InvertedCells), std::to_string(theirs.Quality.InvertedCells), "");
  Row("h(I,M) [voxels]", Fixed(ours.Distances.Overall.ImageToMesh), Fixed(theirs.Distances.Overall.ImageToMesh),
    Ratio(ours.Distances.Overall.ImageToMesh, theirs.Distances.Overall.ImageToMesh));
  Row("h(M,I) [voxels]", Fixed(ours.Distances.Overall.MeshToImage), Fixed(theirs.Distances.Overall.MeshToImage),
    Ratio(ours.Distances.Overall.MeshToImage, theirs.Distances.Overall.MeshToImage));
  Row("peak memory [MiB]", Fixed(ours.PeakMiB, 1), Fixed(theirs.PeakMiB, 1), Ratio(ours.PeakMiB, theirs.PeakMiB));
  Row("misclassified voxels", std::to_string(ours.Misclassified), std::to_string(theirs.Misclassified),
    Ratio(double(ours.Misclassified), double(theirs.Misclassified)));
  if (order == 2)
  {
    Row("  quadratic (ours)", std::to_string(quadraticMisclassified), std::to_string(theirs.Misclassified),
      Ratio(double(quadraticMisclassified), double(theirs.Misclassified)));
    Row("  quadratic time [s]", Fixed(quadraticSeconds), "", "");
  }
  Row("labels with image topology", std::to_string(ours.TopologyMatches) + "/" + std::to_string(ours.Topology.size()),
    std::to_string(theirs.TopologyMatches) + "/" + std::to_string(theirs.Topology.size()), "");

  std::printf("\n  per label: tetrahedra | min dihedral [deg] | h(I,M) | h(M,I) | components, Euler (image -> mesh); "
              "ours / CGAL\n");
  std::set<std::int32_t> labels;
  for (const auto& [l, n] : voxelsPerLabel)
    if (l != 0)
      labels.insert(l);
  auto topo = [](const Measured& m, std::int32_t l) {
    auto it = m.Topology.find(l);
    if (it == m.Topology.end())
      return std::string("-");
    const auto& t = it->second;
    return std::to_string(t.Image.Components) + "," + std::to_string(t.Image.EulerCharacteristic) + "->" +
      std::to_string(t.Mesh.Components) + "," + std::to_string(t.Mesh.EulerCharacteristic) +
      (t.Matches() ? "" : " !");
  };
  auto dist = [](const Measured& m, std::int32_t l) {
    auto it = m.Distances.PerMaterial.find(l);
    return it == m.Distances.PerMaterial.end() ? DistanceReport{ -1, -1 } : it->second;
  };
  auto count = [](const std::map<std::int32_t, std::size_t>& c, std::int32_t l) {
    auto it = c.find(l);
    return it == c.end() ? std::size_t(0) : it->second;
  };
  auto minAngle = [](const Measured& m, std::int32_t l) {
    auto it = m.QualityPerLabel.find(l);
    return it == m.QualityPerLabel.end() ? std::string("-") : Fixed(it->second.MinimumAngle, 2);
  };
  for (std::int32_t l : labels)
  {
    const DistanceReport a = dist(ours, l), b = dist(theirs, l);
    std::printf("  %5d (%zu vox): %zu / %zu | %s / %s | %s / %s | %s / %s | %s / %s\n", l, voxelsPerLabel[l],
      count(ours.CellsPerLabel, l), count(theirs.CellsPerLabel, l), minAngle(ours, l).c_str(),
      minAngle(theirs, l).c_str(), Fixed(a.ImageToMesh).c_str(), Fixed(b.ImageToMesh).c_str(),
      Fixed(a.MeshToImage).c_str(), Fixed(b.MeshToImage).c_str(), topo(ours, l).c_str(), topo(theirs, l).c_str());
  }

  std::printf("\nSUMMARY %s %.6g %.6g %zu %zu %.6g %.6g %.6g %.6g %.6g %.6g %zu/%zu %zu/%zu %.1f %.1f\n", name.c_str(),
    ours.Seconds, theirs.Seconds, ours.Cells, theirs.Cells, ours.Quality.MinimumAngle, theirs.Quality.MinimumAngle,
    ours.Distances.Overall.ImageToMesh, theirs.Distances.Overall.ImageToMesh, ours.Distances.Overall.MeshToImage,
    theirs.Distances.Overall.MeshToImage, ours.TopologyMatches, ours.Topology.size(), theirs.TopologyMatches,
    theirs.Topology.size(), ours.PeakMiB, theirs.PeakMiB);
  std::printf("ACCURACY %s %zu %zu %zu %lld %.6g\n", name.c_str(), image.NumberOfVoxels(), ours.Misclassified,
    theirs.Misclassified, quadraticMisclassified, quadraticSeconds);
  return 0;
}
