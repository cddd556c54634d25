// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file MeshConformity.cxx
 * MeasureConformity: is the mesh a simplicial complex with a closed boundary?
 * (dissertation section 3.2: the mesh is conforming and its boundary is a
 * closed surface.)
 *
 * Passes:
 *  1. (parallel over ranges of vertices) distinct facets and edges, visited
 *     from their smallest vertex (MeshIncidence.h): count the facets used by
 *     more than two cells; keep the facets used by one cell (the mesh
 *     boundary); look for hanging vertices on every edge and, in 3D, every
 *     triangle: a uniform grid of the points (ShapeGrid.h, about one point
 *     per cell) gives the points near its bounding box, flagged if within
 *     Tolerance of it but farther than Tolerance from its vertices and, for
 *     triangles, from its edges (so "strictly inside"). Nothing relies on the
 *     points lying on a lattice.
 *  2. watertightness: sort the edges (3D) / vertices (2D) of the boundary
 *     facets and count those not used by exactly two boundary facets.
 */

#include "Checks/MeshChecks.h"

#include "Support/Geometry.h"
#include "Checks/MeshIncidence.h"
#include "Checks/ShapeGrid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace labelmesher
{

namespace
{
using namespace geometry;
using checks_detail::VertexIncidence;

constexpr double Tolerance = 1e-9;
} // namespace

ConformityReport MeasureConformity(const SimplexMesh& mesh)
{
  ConformityReport report;
  const VertexIncidence incidence = checks_detail::BuildVertexIncidence(mesh);
  const auto& P = mesh.Points;
  const bool is3D = mesh.Dimension == 3;
  if (P.empty())
    return report;
  const checks_detail::ShapeGrid grid(P.size(), checks_detail::GridCells::OnePerItem,
    [&](std::size_t i, Point3& lo, Point3& hi) { lo = hi = P[i]; });
  std::unique_ptr<std::atomic<std::uint8_t>[]> hanging(new std::atomic<std::uint8_t>[P.size()]);
  for (std::size_t v = 0; v < P.size(); ++v)
    hanging[v].store(0, std::memory_order_relaxed);
  const double tol2 = Tolerance * Tolerance;
  // Points used by no cell are not mesh vertices.
  auto used = [&](std::int64_t v) { return incidence.Offsets[v] != incidence.Offsets[v + 1]; };
  auto isHanging = [&](std::int64_t v) { return hanging[v].load(std::memory_order_relaxed) != 0; };
  auto box = [&](std::initializer_list<const Point3*> pts, Point3& lo, Point3& hi) {
    lo = hi = **pts.begin();
    for (const Point3* p : pts)
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], (*p)[a] - Tolerance);
        hi[a] = std::max(hi[a], (*p)[a] + Tolerance);
      }
  };
  auto inBox = [](const Point3& p, const Point3& lo, const Point3& hi) {
    return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] &&
      p[2] <= hi[2];
  };
  auto allCells = [](int, int, int) { return true; };

  // Hanging vertices strictly inside edge (a, b).
  auto checkEdge = [&](std::int64_t a, std::int64_t b) {
    const Point3 &pa = P[a], &pb = P[b];
    Point3 lo, hi;
    box({ &pa, &pb }, lo, hi);
    grid.ForEachInBox(lo, hi, allCells, [&](std::int64_t v) {
      const Point3& p = P[v];
      if (!inBox(p, lo, hi) || v == a || v == b || isHanging(v) || !used(v))
        return;
      if (SquaredDistanceToSegment(p, pa, pb) <= tol2 && Dot(Sub(p, pa), Sub(p, pa)) > tol2 &&
        Dot(Sub(p, pb), Sub(p, pb)) > tol2)
        hanging[v].store(1, std::memory_order_relaxed);
    });
  };
  // Hanging vertices strictly inside triangle t (not on its edges).
  auto checkTriangle = [&](const std::array<std::int64_t, 3>& t) {
    const Point3 &pa = P[t[0]], &pb = P[t[1]], &pc = P[t[2]];
    const Point3 n = Cross(Sub(pb, pa), Sub(pc, pa));
    const double nn = Norm(n);
    if (nn == 0.0)
      return; // degenerate: only its edges can hold a vertex
    Point3 lo, hi;
    box({ &pa, &pb, &pc }, lo, hi);
    // Skip grid cells that the triangle's plane (thickened by Tolerance) misses.
    auto nearPlane = [&](int i, int j, int k) {
      Point3 clo, chi;
      grid.CellBox(i, j, k, clo, chi);
      for (int q = 0; q < 3; ++q)
      {
        clo[q] = std::max(clo[q], lo[q]);
        chi[q] = std::min(chi[q], hi[q]);
      }
      double smin = 0, smax = 0;
      for (int q = 0; q < 3; ++q)
      {
        const double u = n[q] * (clo[q] - pa[q]), w = n[q] * (chi[q] - pa[q]);
        smin += std::min(u, w);
        smax += std::max(u, w);
      }
      return smin <= Tolerance * nn && smax >= -Tolerance * nn;
    };
    grid.ForEachInBox(lo, hi, nearPlane, [&](std::int64_t v) {
      const Point3& p = P[v];
      if (!inBox(p, lo, hi) || v == t[0] || v == t[1] || v == t[2] || isHanging(v) || !used(v))
        return;
      if (std::abs(Dot(Sub(p, pa), n)) > Tolerance * nn)
        return;
      if (SquaredDistanceToTriangle(p, pa, pb, pc) <= tol2 &&
        SquaredDistanceToSegment(p, pa, pb) > tol2 && SquaredDistanceToSegment(p, pb, pc) > tol2 &&
        SquaredDistanceToSegment(p, pc, pa) > tol2)
        hanging[v].store(1, std::memory_order_relaxed);
    });
  };

  // One parallel pass over vertex ranges: every facet and edge is visited from
  // its smallest vertex, so the ranges see disjoint facets and edges.
  struct Local
  {
    std::size_t OverShared = 0;
    std::vector<std::array<std::int64_t, 3>> Boundary;
  };
  std::vector<Local> locals(checks_detail::MaxThreads());
  checks_detail::ParallelChunks(P.size(), 4096, [&](unsigned thread, std::size_t b, std::size_t e) {
    Local& local = locals[thread];
    checks_detail::ForEachFacet(mesh, incidence, b, e,
      [&](const std::array<std::int64_t, 3>& facet, const std::uint32_t*, std::size_t count) {
        if (count > 2)
          ++local.OverShared;
        if (count == 1)
          local.Boundary.push_back(facet);
        if (is3D)
          checkTriangle(facet);
      });
    checks_detail::ForEachEdge(mesh, incidence, b, e, checkEdge);
  });

  // Watertightness: edges (3D) / vertices (2D) of the boundary facets.
  std::vector<std::pair<std::int64_t, std::int64_t>> keys;
  for (const Local& local : locals)
  {
    report.OverSharedFaces += local.OverShared;
    for (const auto& f : local.Boundary)
    {
      if (is3D)
      {
        keys.emplace_back(f[0], f[1]);
        keys.emplace_back(f[0], f[2]);
        keys.emplace_back(f[1], f[2]);
      }
      else
      {
        keys.emplace_back(f[0], -1);
        keys.emplace_back(f[1], -1);
      }
    }
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size();)
  {
    std::size_t j = i;
    while (j < keys.size() && keys[j] == keys[i])
      ++j;
    if (j - i != 2)
      ++report.NonManifoldBoundaryEdges;
    i = j;
  }
  for (std::size_t v = 0; v < P.size(); ++v)
    report.HangingVertices += hanging[v].load(std::memory_order_relaxed);
  return report;
}

} // namespace labelmesher
