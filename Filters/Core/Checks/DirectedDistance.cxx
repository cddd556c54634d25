// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file DirectedDistance.cxx
 * MeasureDirected / WithinDirected: h(A, T) = sup_{x in A} d(x, T) is a
 * supremum over a continuum, bounded rigorously by branch and bound over the
 * elements E of A:
 *  - lower bound: max over the corners v of E of d(v, T) (d(., T) at a point);
 *  - upper bound: for one piece P of T, d(., P) is convex, so its maximum on E
 *    is reached at a corner; min over the pieces P near E of max_v d(v, P)
 *    bounds sup_E d(., T) from above;
 *  - exact zero: an element lying in an axis-aligned plane and covered by
 *    coplanar pieces of T is at distance 0 (CoplanarCoverage.h);
 *  - otherwise E is split (triangle and square into 4, segment into 2).
 * The pieces of T sit in a uniform grid (ShapeGrid.h, cells of 2 voxels). For
 * an element E with centroid c and corner radius r, the nearest piece to every
 * point of E lies within d(c, T) + 2r of c, so one candidate list, gathered
 * once from the grid (d(c, T) by a ring search), serves E and all its
 * sub-elements; it is pruned again at every level.
 *
 * Measuring refines an element until its upper bound is within `tolerance` of
 * the largest lower bound found so far (or a depth/work limit is hit).
 * Certifying stops at the first element whose lower bound exceeds h. Elements
 * are processed by a few threads.
 */

#include "Checks/DirectedDistance.h"

#include "Checks/CoplanarCoverage.h"
#include "Checks/ShapeGrid.h"
#include "Support/ParallelChunks.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

namespace labelmesher
{
namespace checks_detail
{

namespace
{

constexpr double Infinity = std::numeric_limits<double>::infinity();

template <class Body>
void ParallelFor(std::size_t n, Body&& body)
{
  ParallelChunks(n, 256, body);
}

void AtomicMax(std::atomic<double>& a, double v)
{
  double cur = a.load(std::memory_order_relaxed);
  while (v > cur && !a.compare_exchange_weak(cur, v, std::memory_order_relaxed))
  {
  }
}

class DirectedDistance
{
public:
  DirectedDistance(const std::vector<Shape>& elements, const std::vector<Shape>& targets)
    : Elements(elements)
    , Targets(targets)
    , Boxes(BoxesOf(targets))
    , Grid(targets.size(), GridCells::Voxels, [this](std::size_t i, Point3& lo, Point3& hi) {
      lo = Boxes[i][0];
      hi = Boxes[i][1];
    })
  {
  }

  /// Upper bound on h(elements, targets), tight to tolerance (unless a limit is hit).
  double Measure(double tolerance)
  {
    if (Elements.empty())
      return 0.0;
    if (Targets.empty())
      return Infinity;
    tolerance = std::max(tolerance, 0.0);
    // Pass 1: bounds of every element; the largest lower bound is achieved.
    std::vector<double> ub(Elements.size());
    std::atomic<double> globalLB{ 0.0 };
    std::vector<Workspace> workspaces(MaxThreads(), Workspace(Targets.size()));
    ParallelFor(Elements.size(), [&](unsigned t, std::size_t b, std::size_t e) {
      Workspace& ws = workspaces[t];
      double localLB = 0.0;
      for (std::size_t i = b; i < e; ++i)
      {
        if (Gather(Elements[i], ws, ws.Cands))
        {
          ub[i] = 0.0; // covered
          continue;
        }
        const Bounds2 ev = Evaluate(Elements[i], ws.Cands, false);
        localLB = std::max(localLB, ev.Lower);
        ub[i] = ev.Upper;
      }
      AtomicMax(globalLB, localLB);
    });
    // Pass 2: refine the elements whose upper bound is not yet tight.
    std::atomic<double> result{ 0.0 };
    ParallelFor(Elements.size(), [&](unsigned t, std::size_t b, std::size_t e) {
      Workspace& ws = workspaces[t];
      double localResult = 0.0;
      for (std::size_t i = b; i < e; ++i)
      {
        if (ub[i] <= globalLB.load(std::memory_order_relaxed) + tolerance)
        {
          localResult = std::max(localResult, ub[i]);
          continue;
        }
        Gather(Elements[i], ws, ws.Cands);
        Refine(Elements[i], ws.Cands, 0, tolerance, globalLB, localResult, ws);
      }
      AtomicMax(result, localResult);
    });
    return result.load();
  }

  /// True only if h(elements, targets) <= h is certified (up to RoundOff).
  bool Within(double h)
  {
    if (Elements.empty())
      return true;
    if (Targets.empty())
      return false;
    std::atomic<bool> ok{ true };
    std::vector<Workspace> workspaces(MaxThreads(), Workspace(Targets.size()));
    ParallelFor(Elements.size(), [&](unsigned t, std::size_t b, std::size_t e) {
      Workspace& ws = workspaces[t];
      for (std::size_t i = b; i < e && ok.load(std::memory_order_relaxed); ++i)
      {
        if (Gather(Elements[i], ws, ws.Cands))
          continue; // covered: distance 0
        if (!Certify(Elements[i], ws.Cands, 0, h, ws))
          ok = false;
      }
    });
    return ok.load();
  }

private:
  struct Bounds2
  {
    double Lower, Upper;
  };
  /// One per thread, reused across chunks: the stamps span every target.
  struct Workspace
  {
    explicit Workspace(std::size_t n)
      : Stamp(n, 0)
    {
    }
    std::vector<std::uint32_t> Stamp;
    std::uint32_t Tick = 0;
    std::vector<std::uint32_t> Cands;
  };

  static constexpr int MaxDepthPolygon = 14; ///< 4^14 sub-elements at most (work budget below)
  static constexpr int MaxDepthSegment = 40;
  /// Candidate distance evaluations: 200 million, and 2,000 more per element,
  /// so that a mesh of millions of faces whose distance reaches its bound in
  /// many places is refined to the tolerance there (a fixed budget ran out
  /// on the first pass over a decimated whole-body mouse).
  long long WorkBudget() const { return 200000000LL + 2000LL * static_cast<long long>(Elements.size()); }

  static std::vector<std::array<Point3, 2>> BoxesOf(const std::vector<Shape>& shapes)
  {
    std::vector<std::array<Point3, 2>> boxes(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i)
      BoundingBox(shapes[i], boxes[i][0], boxes[i][1]);
    return boxes;
  }

  int MaxDepth(const Shape& s) const
  {
    Point3 c[4];
    return Corners(s, c) == 2 ? MaxDepthSegment : MaxDepthPolygon;
  }

  double SqBoxDistance(const Point3& p, std::uint32_t id) const
  {
    return geometry::SquaredDistanceToBox(p, Boxes[id][0], Boxes[id][1]);
  }

  /// Targets whose bounding box meets the ball (c, R), from the grid.
  void GatherBall(const Point3& c, double R, Workspace& ws, std::vector<std::uint32_t>& out) const
  {
    const Point3 lo = { c[0] - R, c[1] - R, c[2] - R }, hi = { c[0] + R, c[1] + R, c[2] + R };
    if (++ws.Tick == 0)
    {
      std::fill(ws.Stamp.begin(), ws.Stamp.end(), 0);
      ws.Tick = 1;
    }
    out.clear();
    Grid.ForEachInBox(lo, hi, [&](std::uint32_t id) {
      if (ws.Stamp[id] == ws.Tick)
        return;
      ws.Stamp[id] = ws.Tick;
      if (SqBoxDistance(c, id) <= R * R)
        out.push_back(id);
    });
  }

  /// Candidate targets for an element: every target that can be the nearest
  /// one to a point of the element. Returns true instead (and `out` is not
  /// usable) if the element is covered by coplanar targets: those meet the
  /// ball of radius r around the centre, a much smaller search.
  bool Gather(const Shape& e, Workspace& ws, std::vector<std::uint32_t>& out) const
  {
    Point3 c;
    double r;
    CentreAndRadius(e, c, r);
    if (e.Axis >= 0)
    {
      GatherBall(c, r * (1 + 1e-12) + RoundOff, ws, out);
      if (CoveredByCoplanar(e, Targets, out))
        return true;
    }
    const double dc =
      std::sqrt(Grid.NearestSq(c, [&](std::uint32_t id) { return SquaredDistance(c, Targets[id]); }));
    GatherBall(c, (dc + 2 * r) * (1 + 1e-12) + RoundOff, ws, out);
    return false;
  }

  /// Candidates of a sub-element, from those of its parent.
  void Prune(const Shape& e, const std::vector<std::uint32_t>& in, std::vector<std::uint32_t>& out) const
  {
    Point3 c;
    double r;
    CentreAndRadius(e, c, r);
    double best = Infinity;
    for (std::uint32_t id : in)
      best = std::min(best, SquaredDistance(c, Targets[id]));
    const double R = (std::sqrt(best) + 2 * r) * (1 + 1e-12) + RoundOff;
    out.clear();
    for (std::uint32_t id : in)
      if (SqBoxDistance(c, id) <= R * R)
        out.push_back(id);
  }

  Bounds2 Evaluate(const Shape& e, const std::vector<std::uint32_t>& cands, bool tryCover = true)
  {
    Work.fetch_add(static_cast<long long>(cands.size()), std::memory_order_relaxed);
    if (tryCover && e.Axis >= 0 && CoveredByCoplanar(e, Targets, cands))
      return { 0.0, 0.0 };
    Point3 c[4];
    const int n = Corners(e, c);
    double lower[4] = { Infinity, Infinity, Infinity, Infinity };
    double upper = Infinity;
    for (std::uint32_t id : cands)
    {
      const Shape& t = Targets[id];
      double worst = 0;
      for (int q = 0; q < n; ++q)
      {
        const double d = SquaredDistance(c[q], t);
        lower[q] = std::min(lower[q], d);
        worst = std::max(worst, d);
      }
      upper = std::min(upper, worst);
    }
    double lo = 0;
    for (int q = 0; q < n; ++q)
      lo = std::max(lo, lower[q]);
    return { std::sqrt(lo), std::sqrt(upper) };
  }

  bool OverBudget() const { return Work.load(std::memory_order_relaxed) > WorkBudget(); }

  void Refine(const Shape& e, const std::vector<std::uint32_t>& cands, int depth, double tolerance,
    std::atomic<double>& globalLB, double& result, Workspace& ws)
  {
    const Bounds2 ev = Evaluate(e, cands);
    AtomicMax(globalLB, ev.Lower);
    if (ev.Upper <= globalLB.load(std::memory_order_relaxed) + tolerance || depth >= MaxDepth(e) ||
      OverBudget())
    {
      result = std::max(result, ev.Upper);
      return;
    }
    Shape children[4];
    const int n = Subdivide(e, children);
    std::vector<std::uint32_t> sub;
    for (int t = 0; t < n; ++t)
    {
      Prune(children[t], cands, sub);
      Refine(children[t], sub, depth + 1, tolerance, globalLB, result, ws);
    }
  }

  bool Certify(const Shape& e, const std::vector<std::uint32_t>& cands, int depth, double h, Workspace& ws)
  {
    const Bounds2 ev = Evaluate(e, cands);
    if (ev.Upper <= h + RoundOff)
      return true;
    if (ev.Lower > h + RoundOff || depth >= MaxDepth(e) || OverBudget())
      return false;
    Shape children[4];
    const int n = Subdivide(e, children);
    std::vector<std::uint32_t> sub;
    for (int t = 0; t < n; ++t)
    {
      Prune(children[t], cands, sub);
      if (!Certify(children[t], sub, depth + 1, h, ws))
        return false;
    }
    return true;
  }

  const std::vector<Shape>& Elements;
  const std::vector<Shape>& Targets;
  /// Bounding boxes of the targets; declared before Grid, which is built from them.
  const std::vector<std::array<Point3, 2>> Boxes;
  const ShapeGrid Grid;
  std::atomic<long long> Work{ 0 };
};

} // namespace

double MeasureDirected(
  const std::vector<Shape>& elements, const std::vector<Shape>& targets, double tolerance)
{
  return DirectedDistance(elements, targets).Measure(tolerance);
}

bool WithinDirected(const std::vector<Shape>& elements, const std::vector<Shape>& targets, double h)
{
  return DirectedDistance(elements, targets).Within(h);
}

} // namespace checks_detail
} // namespace labelmesher
