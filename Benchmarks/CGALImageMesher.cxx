// SPDX-License-Identifier: GPL-2.0-or-later
// The only translation unit that includes CGAL (Mesh_3 is heavy to compile).
#include "CGALImageMesher.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Image_3.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>
#include <CGAL/refine_mesh_3.h>

#include <CGAL/Mesh_3/initialize_triangulation_from_labeled_image.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace labelmesher
{
namespace benchmarks
{

namespace
{

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using MeshDomain = CGAL::Labeled_mesh_domain_3<K>;
using Tr = CGAL::Mesh_triangulation_3<MeshDomain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr>;
using MeshCriteria = CGAL::Mesh_criteria_3<Tr>;
using Clock = std::chrono::steady_clock;

/// CGAL's mesher and its initialisation print progress to std::cout; keep the
/// comparison's own output readable.
class SilenceStdout
{
public:
  SilenceStdout()
    : Saved(std::cout.rdbuf(Sink.rdbuf()))
  {
  }
  ~SilenceStdout() { std::cout.rdbuf(Saved); }

private:
  std::ostringstream Sink;
  std::streambuf* Saved;
};

/// The image padded by one background voxel on each side, as a CGAL::Image_3
/// with unit spacing and zero origin (see CGALImageMesher.h).
template <typename Word>
CGAL::Image_3 MakePaddedImage(const LabelImage& image)
{
  const auto& d = image.Dimensions;
  const int nx = d[0] + 2, ny = d[1] + 2, nz = d[2] + 2;
  _image* raw = ::_createImage(nx, ny, nz, 1, 1.0, 1.0, 1.0, sizeof(Word), WK_FIXED, SGN_UNSIGNED);
  if (!raw)
    throw std::runtime_error("CGAL: cannot allocate the image");
  Word* data = static_cast<Word*>(raw->data);
  std::memset(data, 0, sizeof(Word) * std::size_t(nx) * ny * nz);
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
        data[(std::size_t(k + 1) * ny + (j + 1)) * nx + (i + 1)] = static_cast<Word>(image.At(i, j, k));
  return CGAL::Image_3(raw); // takes ownership
}

SimplexMesh ToSimplexMesh(const C3t3& c3t3)
{
  SimplexMesh mesh;
  mesh.Dimension = 3;
  const Tr& tr = c3t3.triangulation();
  std::unordered_map<Tr::Vertex_handle, std::int64_t> ids;
  auto id = [&](Tr::Vertex_handle v) {
    auto [it, inserted] = ids.emplace(v, std::int64_t(mesh.Points.size()));
    if (inserted)
    {
      const auto& p = tr.point(v); // weighted point
      // Undo the one-voxel padding.
      mesh.Points.push_back({ CGAL::to_double(p.x()) - 1.0, CGAL::to_double(p.y()) - 1.0,
        CGAL::to_double(p.z()) - 1.0 });
    }
    return it->second;
  };
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
  {
    std::int64_t v[4] = { id(c->vertex(0)), id(c->vertex(1)), id(c->vertex(2)), id(c->vertex(3)) };
    // CGAL's cells are positively oriented; check in our convention anyway.
    const auto& a = mesh.Points[std::size_t(v[0])];
    const auto& b = mesh.Points[std::size_t(v[1])];
    const auto& cc = mesh.Points[std::size_t(v[2])];
    const auto& dd = mesh.Points[std::size_t(v[3])];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double w[3] = { cc[0] - a[0], cc[1] - a[1], cc[2] - a[2] };
    const double t[3] = { dd[0] - a[0], dd[1] - a[1], dd[2] - a[2] };
    const double det = u[0] * (w[1] * t[2] - w[2] * t[1]) - u[1] * (w[0] * t[2] - w[2] * t[0]) +
      u[2] * (w[0] * t[1] - w[1] * t[0]);
    if (det < 0)
      std::swap(v[2], v[3]);
    mesh.Connectivity.insert(mesh.Connectivity.end(), v, v + 4);
    mesh.Materials.push_back(static_cast<std::int32_t>(c3t3.subdomain_index(c)));
  }
  return mesh;
}

template <typename Word>
CGALMeshResult Mesh(const LabelImage& image, const CGALMeshOptions& options)
{
  CGALMeshResult result;
  const CGAL::Image_3 cgalImage = MakePaddedImage<Word>(image);

  CGAL::get_default_random() = CGAL::Random(options.Seed);
  CGAL::Random domainRandom(options.Seed);

  SilenceStdout silence;
  auto stage = [&](const char* name, Clock::time_point start) {
    const double s = std::chrono::duration<double>(Clock::now() - start).count();
    result.Timings.emplace_back(name, s);
    result.Seconds += s;
  };

  auto start = Clock::now();
  namespace p = CGAL::parameters;
  MeshDomain domain = MeshDomain::create_labeled_image_mesh_domain(cgalImage,
    p::relative_error_bound = options.RelativeErrorBound, p::p_rng = &domainRandom);
  MeshCriteria criteria(p::facet_angle = options.FacetAngle, p::facet_size = options.FacetSize,
    p::facet_distance = options.FacetDistance, p::cell_radius_edge_ratio = options.CellRadiusEdgeRatio,
    p::cell_size = options.CellSize);
  stage("domain", start);

  C3t3 c3t3;
  start = Clock::now();
  if (options.SeedComponents)
  {
    initialize_triangulation_from_labeled_image(c3t3, domain, cgalImage, criteria, Word());
    result.InitialPoints = c3t3.triangulation().number_of_vertices();
    stage("seed", start);
    start = Clock::now();
    CGAL::refine_mesh_3(c3t3, domain, criteria, p::no_perturb(), p::no_exude());
  }
  else
  {
    // CGAL's own random initial points (Construct_initial_points of the domain).
    c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, p::no_perturb(), p::no_exude());
  }
  stage("refine", start);

  if (options.Optimise)
  {
    // What make_mesh_3 / refine_mesh_3 run by default after refinement, split
    // out for timing: perturb, then exude, both without time limit.
    start = Clock::now();
    CGAL::perturb_mesh_3(c3t3, domain);
    stage("perturb", start);
    start = Clock::now();
    CGAL::exude_mesh_3(c3t3);
    stage("exude", start);
  }

  result.Mesh = ToSimplexMesh(c3t3);
  return result;
}

} // namespace

CGALMeshResult MeshWithCGAL(const LabelImage& image, const CGALMeshOptions& options)
{
  if (image.Dimension() != 3)
    throw std::invalid_argument("MeshWithCGAL: 3D images only (CGAL Mesh_3)");
  std::int32_t maxLabel = 0;
  image.WithLabels([&](const auto* labels) {
    for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
      maxLabel = std::max<std::int32_t>(maxLabel, labels[v]);
  });
  if (maxLabel <= 255)
    return Mesh<unsigned char>(image, options);
  if (maxLabel <= 65535)
    return Mesh<unsigned short>(image, options);
  throw std::invalid_argument("MeshWithCGAL: labels above 65535 are not supported");
}

} // namespace benchmarks
} // namespace labelmesher
