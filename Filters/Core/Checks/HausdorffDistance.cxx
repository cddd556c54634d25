// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file HausdorffDistance.cxx
 * MeasureHausdorff / WithinHausdorff: the fidelity guarantee of the ORD mesh
 * (dissertation section 2.2 and 3.2): both one-sided Hausdorff distances
 * between the mesh boundary and the image boundary, overall and per material.
 *
 * Both boundaries are finite unions of convex pieces ("shapes"): voxel faces
 * (axis-aligned squares; pixel edges in 2D) and mesh boundary facets
 * (triangles; segments in 2D). A one-sided distance h(A, T) = sup_{x in A}
 * d(x, T) is a supremum over a continuum, bounded rigorously by branch and
 * bound over the elements E of A:
 *  - lower bound: max over the corners v of E of d(v, T) (d(., T) at a point);
 *  - upper bound: for one piece P of T, d(., P) is convex, so its maximum on E
 *    is reached at a corner; min over the pieces P near E of max_v d(v, P)
 *    bounds sup_E d(., T) from above;
 *  - exact zero: an element lying in an axis-aligned plane and covered by
 *    coplanar pieces of T (the clipped areas of pairwise non-overlapping
 *    coplanar pieces add up to its area, to 1e-9) is at distance 0. Without
 *    this a voxel face covered by two mesh triangles (or the converse) could
 *    never be certified at h = 0;
 *  - otherwise E is split (triangle and square into 4, segment into 2).
 * The pieces of T sit in a uniform grid (cells of 4 voxels). For an element E
 * with centroid c and corner radius r, the nearest piece to every point of E
 * lies within d(c, T) + 2r of c, so one candidate list, gathered once from the
 * grid (d(c, T) by a ring search), serves E and all its sub-elements; it is
 * pruned again at every level.
 *
 * MeasureHausdorff refines an element until its upper bound is within
 * `tolerance` of the largest lower bound found so far (or a depth/work limit
 * is hit: the result is then still an upper bound, only less tight).
 * WithinHausdorff answers true only when every element is certified, up to
 * 1e-9; an element left undecided at the depth/work limit counts as a failure.
 * Elements are processed by a few threads.
 */

#include "Checks/MeshChecks.h"

#include "Support/Geometry.h"
#include "Checks/MeshIncidence.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

namespace labelmesher
{

namespace
{
using namespace geometry;

constexpr double Eps = 1e-9;
constexpr double Infinity = std::numeric_limits<double>::infinity();

enum class Kind : std::uint8_t
{
  Segment,  ///< P[0], P[1]
  Triangle, ///< P[0], P[1], P[2]
  Box       ///< axis-aligned box P[0] (lo) .. P[1] (hi), flat along at least one axis
};

struct Shape
{
  Point3 P[3];
  Kind K = Kind::Triangle;
  std::int8_t Axis = -1; ///< normal axis of the axis-aligned hyperplane holding it, or -1
  double Plane = 0.0;    ///< coordinate of that hyperplane
};

int FreeAxes(const Shape& s, int* axes)
{
  int n = 0;
  for (int a = 0; a < 3; ++a)
    if (s.P[1][a] > s.P[0][a])
      axes[n++] = a;
  return n;
}

/// Corners of the shape, in cyclic order for polygons.
int Corners(const Shape& s, Point3* out)
{
  switch (s.K)
  {
    case Kind::Segment:
      out[0] = s.P[0];
      out[1] = s.P[1];
      return 2;
    case Kind::Triangle:
      out[0] = s.P[0];
      out[1] = s.P[1];
      out[2] = s.P[2];
      return 3;
    case Kind::Box:
    default:
    {
      int f[3];
      const int nf = FreeAxes(s, f);
      out[0] = s.P[0];
      if (nf == 0)
        return 1;
      out[1] = s.P[0];
      out[1][f[0]] = s.P[1][f[0]];
      if (nf == 1)
        return 2;
      out[2] = out[1];
      out[2][f[1]] = s.P[1][f[1]];
      out[3] = s.P[0];
      out[3][f[1]] = s.P[1][f[1]];
      return 4;
    }
  }
}

void Bounds(const Shape& s, Point3& lo, Point3& hi)
{
  if (s.K == Kind::Box)
  {
    lo = s.P[0];
    hi = s.P[1];
    return;
  }
  const int n = s.K == Kind::Segment ? 2 : 3;
  lo = hi = s.P[0];
  for (int t = 1; t < n; ++t)
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], s.P[t][a]);
      hi[a] = std::max(hi[a], s.P[t][a]);
    }
}

double SqDist(const Point3& p, const Shape& s)
{
  switch (s.K)
  {
    case Kind::Segment:
      return SquaredDistanceToSegment(p, s.P[0], s.P[1]);
    case Kind::Triangle:
      return SquaredDistanceToTriangle(p, s.P[0], s.P[1], s.P[2]);
    case Kind::Box:
    default:
      return SquaredDistanceToBox(p, s.P[0], s.P[1]);
  }
}

/// Records the axis-aligned hyperplane (line in 2D) holding the shape, if any.
void SetPlane(Shape& s, int dimension)
{
  Point3 c[4];
  const int n = Corners(s, c);
  s.Axis = -1;
  for (int a = 0; a < dimension; ++a)
  {
    bool flat = true;
    for (int t = 1; t < n && flat; ++t)
      flat = std::abs(c[t][a] - c[0][a]) <= Eps;
    if (flat)
    {
      s.Axis = static_cast<std::int8_t>(a);
      s.Plane = c[0][a];
      return;
    }
  }
}

int Subdivide(const Shape& s, Shape* out)
{
  auto mid = [](const Point3& a, const Point3& b) {
    return Point3{ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
  };
  int n = 0;
  switch (s.K)
  {
    case Kind::Segment:
    {
      const Point3 m = mid(s.P[0], s.P[1]);
      out[0] = s;
      out[0].P[1] = m;
      out[1] = s;
      out[1].P[0] = m;
      n = 2;
      break;
    }
    case Kind::Triangle:
    {
      const Point3 &a = s.P[0], &b = s.P[1], &c = s.P[2];
      const Point3 ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      const Point3 tri[4][3] = { { a, ab, ca }, { ab, b, bc }, { ca, bc, c }, { ab, bc, ca } };
      for (int t = 0; t < 4; ++t)
      {
        out[t] = s;
        for (int q = 0; q < 3; ++q)
          out[t].P[q] = tri[t][q];
      }
      n = 4;
      break;
    }
    case Kind::Box:
    default:
    {
      int f[3];
      const int nf = FreeAxes(s, f);
      const Point3 m = mid(s.P[0], s.P[1]);
      n = 1 << nf;
      for (int t = 0; t < n; ++t)
      {
        out[t] = s;
        for (int q = 0; q < nf; ++q)
        {
          const int a = f[q];
          if (t & (1 << q))
            out[t].P[0][a] = m[a];
          else
            out[t].P[1][a] = m[a];
        }
      }
      break;
    }
  }
  return n;
}

// ---------------------------------------------------------------------------
// Coplanar coverage (exact-zero detection).

using Point2 = std::array<double, 2>;

/// Convex polygon with at most 12 corners (a triangle or square clipped by a
/// triangle or square has at most 8).
struct Polygon
{
  std::array<Point2, 12> P;
  int N = 0;
  void Push(const Point2& p)
  {
    if (N < 12)
      P[N++] = p;
  }
};

double SignedArea(const Polygon& p)
{
  double s = 0;
  for (int i = 0; i < p.N; ++i)
  {
    const Point2 &a = p.P[i], &b = p.P[(i + 1) % p.N];
    s += a[0] * b[1] - a[1] * b[0];
  }
  return 0.5 * s;
}

/// Sutherland-Hodgman: subject clipped by the convex counter-clockwise `clip`.
Polygon Clip(const Polygon& subject, const Polygon& clip)
{
  Polygon out = subject, in;
  for (int e = 0; e < clip.N && out.N > 0; ++e)
  {
    const Point2 &a = clip.P[e], &b = clip.P[(e + 1) % clip.N];
    auto side = [&](const Point2& p) {
      return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    };
    in = out;
    out.N = 0;
    for (int i = 0; i < in.N; ++i)
    {
      const Point2 &p = in.P[i], &q = in.P[(i + 1) % in.N];
      const double sp = side(p), sq = side(q);
      if (sp >= 0)
        out.Push(p);
      if ((sp >= 0) != (sq >= 0))
      {
        const double t = sp / (sp - sq);
        out.Push({ p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) });
      }
    }
  }
  return out;
}

Polygon Project(const Shape& s, int u, int w)
{
  Point3 c[4];
  const int n = Corners(s, c);
  Polygon p;
  for (int t = 0; t < n; ++t)
    p.Push({ c[t][u], c[t][w] });
  if (SignedArea(p) < 0)
    std::reverse(p.P.begin(), p.P.begin() + p.N);
  return p;
}

/// True if the flat element e is covered by coplanar candidates (see file comment).
bool Covered(const Shape& e, const std::vector<Shape>& targets, const std::vector<std::uint32_t>& cands)
{
  Point3 c[4];
  const int n = Corners(e, c);
  if (n == 2)
  {
    // 1D element on an axis-aligned line (2D meshes): interval coverage.
    const int b = 1 - e.Axis;
    const double s0 = std::min(c[0][b], c[1][b]), s1 = std::max(c[0][b], c[1][b]);
    const double length = s1 - s0;
    if (!(length > 0))
      return false;
    std::vector<std::pair<double, double>> pieces;
    for (std::uint32_t id : cands)
    {
      const Shape& t = targets[id];
      if (t.Axis != e.Axis || std::abs(t.Plane - e.Plane) > Eps)
        continue;
      Point3 tc[4];
      const int tn = Corners(t, tc);
      if (tn != 2)
        continue;
      const double t0 = std::max(s0, std::min(tc[0][b], tc[1][b]));
      const double t1 = std::min(s1, std::max(tc[0][b], tc[1][b]));
      if (t1 > t0)
        pieces.emplace_back(t0, t1);
    }
    std::sort(pieces.begin(), pieces.end());
    double sum = 0, end = -Infinity;
    for (const auto& iv : pieces)
    {
      if (iv.first < end - Eps * length)
        return false; // overlapping pieces: the sum proves nothing
      sum += iv.second - iv.first;
      end = std::max(end, iv.second);
    }
    return sum >= length * (1.0 - Eps);
  }
  if (n < 3)
    return false;
  const int u = (e.Axis + 1) % 3, w = (e.Axis + 2) % 3;
  const Polygon ep = Project(e, u, w);
  const double area = SignedArea(ep);
  if (!(area > 0))
    return false;
  thread_local std::vector<Polygon> parts;
  parts.clear();
  double sum = 0;
  for (std::uint32_t id : cands)
  {
    const Shape& t = targets[id];
    if (t.Axis != e.Axis || std::abs(t.Plane - e.Plane) > Eps)
      continue;
    const Polygon tp = Project(t, u, w);
    if (tp.N < 3)
      continue;
    const Polygon part = Clip(tp, ep);
    if (part.N < 3)
      continue;
    const double a = SignedArea(part);
    if (!(a > Eps * area))
      continue;
    for (const Polygon& other : parts)
      if (SignedArea(Clip(part, other)) > Eps * area)
        return false; // overlapping pieces: the sum proves nothing
    sum += a;
    parts.push_back(part);
  }
  return sum >= area * (1.0 - Eps);
}

// ---------------------------------------------------------------------------
// Uniform grid over the target pieces.

class ShapeGrid
{
public:
  explicit ShapeGrid(const std::vector<Shape>& shapes)
    : Shapes(shapes)
  {
    Point3 lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
    for (std::size_t i = 0; i < shapes.size(); ++i)
    {
      Point3 l, h;
      Bounds(shapes[i], l, h);
      for (int a = 0; a < 3; ++a)
      {
        lo[a] = i == 0 ? l[a] : std::min(lo[a], l[a]);
        hi[a] = i == 0 ? h[a] : std::max(hi[a], h[a]);
      }
    }
    Lo = lo;
    Size = 2.0;
    constexpr double MaxCells = 16.0 * 1024 * 1024;
    for (;;)
    {
      double cells = 1;
      for (int a = 0; a < 3; ++a)
      {
        N[a] = static_cast<int>(std::floor((hi[a] - lo[a]) / Size)) + 1;
        cells *= N[a];
      }
      if (cells <= MaxCells)
        break;
      Size *= 1.5;
    }
    const std::size_t ncells = static_cast<std::size_t>(N[0]) * N[1] * N[2];
    Start.assign(ncells + 1, 0);
    for (int pass = 0; pass < 2; ++pass)
    {
      std::vector<std::size_t> fill;
      if (pass == 1)
      {
        for (std::size_t c = 0; c < ncells; ++c)
          Start[c + 1] += Start[c];
        Items.resize(Start[ncells]);
        fill.assign(Start.begin(), Start.end() - 1);
      }
      for (std::size_t i = 0; i < shapes.size(); ++i)
      {
        Point3 l, h;
        Bounds(shapes[i], l, h);
        int a0[3], a1[3];
        for (int a = 0; a < 3; ++a)
        {
          a0[a] = Coord(l[a], a);
          a1[a] = Coord(h[a], a);
        }
        for (int k = a0[2]; k <= a1[2]; ++k)
          for (int j = a0[1]; j <= a1[1]; ++j)
            for (int ii = a0[0]; ii <= a1[0]; ++ii)
            {
              const std::size_t c = Cell(ii, j, k);
              if (pass == 0)
                ++Start[c + 1];
              else
                Items[fill[c]++] = static_cast<std::uint32_t>(i);
            }
      }
    }
  }

  int Coord(double x, int a) const
  {
    const double t = std::floor((x - Lo[a]) / Size);
    if (!(t > 0))
      return 0;
    return t >= N[a] - 1 ? N[a] - 1 : static_cast<int>(t);
  }
  std::size_t Cell(int i, int j, int k) const
  {
    return (static_cast<std::size_t>(k) * N[1] + j) * N[0] + i;
  }

  /// Squared distance from p to the union of the shapes (ring search).
  double NearestSq(const Point3& p) const
  {
    int c[3];
    for (int a = 0; a < 3; ++a)
      c[a] = Coord(p[a], a);
    double best = Infinity;
    auto visit = [&](int i, int j, int k) {
      const std::size_t cell = Cell(i, j, k);
      for (std::size_t q = Start[cell]; q < Start[cell + 1]; ++q)
        best = std::min(best, SqDist(p, Shapes[Items[q]]));
    };
    for (int r = 0;; ++r)
    {
      const int k0 = std::max(0, c[2] - r), k1 = std::min(N[2] - 1, c[2] + r);
      const int j0 = std::max(0, c[1] - r), j1 = std::min(N[1] - 1, c[1] + r);
      const int i0 = std::max(0, c[0] - r), i1 = std::min(N[0] - 1, c[0] + r);
      for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j)
        {
          if (std::abs(k - c[2]) == r || std::abs(j - c[1]) == r)
          {
            for (int i = i0; i <= i1; ++i)
              visit(i, j, k);
          }
          else
          {
            if (c[0] - r >= 0)
              visit(c[0] - r, j, k);
            if (r > 0 && c[0] + r < N[0])
              visit(c[0] + r, j, k);
          }
        }
      // Anything not visited yet lies outside the block of radius r.
      double lb = Infinity;
      for (int a = 0; a < 3; ++a)
      {
        if (c[a] - r > 0)
          lb = std::min(lb, p[a] - (Lo[a] + (c[a] - r) * Size));
        if (c[a] + r < N[a] - 1)
          lb = std::min(lb, Lo[a] + (c[a] + r + 1) * Size - p[a]);
      }
      if (lb == Infinity)
        break;
      lb = std::max(lb, 0.0);
      if (best <= lb * lb)
        break;
    }
    return best;
  }

  /// Calls f(shapeId) for the shapes in the grid cells overlapping [lo, hi] (with repeats).
  template <class F>
  void ForEachInBox(const Point3& lo, const Point3& hi, F&& f) const
  {
    int a0[3], a1[3];
    for (int a = 0; a < 3; ++a)
    {
      a0[a] = Coord(lo[a], a);
      a1[a] = Coord(hi[a], a);
    }
    for (int k = a0[2]; k <= a1[2]; ++k)
      for (int j = a0[1]; j <= a1[1]; ++j)
        for (int i = a0[0]; i <= a1[0]; ++i)
        {
          const std::size_t cell = Cell(i, j, k);
          for (std::size_t q = Start[cell]; q < Start[cell + 1]; ++q)
            f(Items[q]);
        }
  }

private:
  const std::vector<Shape>& Shapes;
  Point3 Lo{ 0, 0, 0 };
  double Size = 4.0;
  int N[3] = { 1, 1, 1 };
  std::vector<std::size_t> Start;
  std::vector<std::uint32_t> Items;
};

// ---------------------------------------------------------------------------
// One direction: sup over the elements of the distance to the targets.

template <class Body>
void ParallelFor(std::size_t n, Body&& body)
{
  checks_detail::ParallelChunks(n, 256, body);
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
    , Grid(targets)
  {
    Boxes.resize(targets.size());
    for (std::size_t i = 0; i < targets.size(); ++i)
      Bounds(targets[i], Boxes[i][0], Boxes[i][1]);
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
    std::vector<Workspace> workspaces(checks_detail::MaxThreads(), Workspace(Targets.size()));
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

  /// True only if h(elements, targets) <= h is certified (up to Eps).
  bool Within(double h)
  {
    if (Elements.empty())
      return true;
    if (Targets.empty())
      return false;
    std::atomic<bool> ok{ true };
    std::vector<Workspace> workspaces(checks_detail::MaxThreads(), Workspace(Targets.size()));
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
  static constexpr long long WorkBudget = 200000000; ///< candidate distance evaluations

  int MaxDepth(const Shape& s) const
  {
    Point3 c[4];
    return Corners(s, c) == 2 ? MaxDepthSegment : MaxDepthPolygon;
  }

  static void CentreAndRadius(const Shape& s, Point3& centre, double& radius)
  {
    Point3 c[4];
    const int n = Corners(s, c);
    centre = { 0, 0, 0 };
    for (int t = 0; t < n; ++t)
      centre = Add(centre, c[t]);
    centre = Scale(centre, 1.0 / n);
    radius = 0;
    for (int t = 0; t < n; ++t)
      radius = std::max(radius, Distance(centre, c[t]));
  }

  double SqBoxDistance(const Point3& p, std::uint32_t id) const
  {
    return SquaredDistanceToBox(p, Boxes[id][0], Boxes[id][1]);
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
      GatherBall(c, r * (1 + 1e-12) + Eps, ws, out);
      if (Covered(e, Targets, out))
        return true;
    }
    const double dc = std::sqrt(Grid.NearestSq(c));
    GatherBall(c, (dc + 2 * r) * (1 + 1e-12) + Eps, ws, out);
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
      best = std::min(best, SqDist(c, Targets[id]));
    const double R = (std::sqrt(best) + 2 * r) * (1 + 1e-12) + Eps;
    out.clear();
    for (std::uint32_t id : in)
      if (SqBoxDistance(c, id) <= R * R)
        out.push_back(id);
  }

  Bounds2 Evaluate(const Shape& e, const std::vector<std::uint32_t>& cands, bool tryCover = true)
  {
    Work.fetch_add(static_cast<long long>(cands.size()), std::memory_order_relaxed);
    if (tryCover && e.Axis >= 0 && Covered(e, Targets, cands))
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
        const double d = SqDist(c[q], t);
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

  bool OverBudget() const { return Work.load(std::memory_order_relaxed) > WorkBudget; }

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
    if (ev.Upper <= h + Eps)
      return true;
    if (ev.Lower > h + Eps || depth >= MaxDepth(e) || OverBudget())
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
  ShapeGrid Grid;
  std::vector<std::array<Point3, 2>> Boxes; ///< bounding boxes of the targets
  std::atomic<long long> Work{ 0 };
};

// ---------------------------------------------------------------------------
// The two boundaries, overall and per material.

struct Boundaries
{
  std::vector<Shape> Image, Mesh; // overall
  std::map<std::int32_t, std::pair<std::vector<Shape>, std::vector<Shape>>> PerMaterial;
};

Boundaries ExtractBoundaries(const LabelImage& image, const SimplexMesh& mesh)
{
  Boundaries b;
  // Image: voxel faces (pixel edges) between different labels.
  const int nx = image.Dimensions[0], ny = image.Dimensions[1], nz = image.Dimensions[2];
  const int dim = image.Dimension();
  if (nx > 0 && ny > 0 && nz > 0 && !image.Labels.empty())
  {
    for (int axis = 0; axis < dim; ++axis)
    {
      const int e[3] = { axis == 0, axis == 1, axis == 2 };
      for (int k = 0; k < nz + e[2]; ++k)
        for (int j = 0; j < ny + e[1]; ++j)
          for (int i = 0; i < nx + e[0]; ++i)
          {
            const std::int32_t A = image.At(i - e[0], j - e[1], k - e[2]);
            const std::int32_t B = image.At(i, j, k);
            if (A == B)
              continue;
            Shape s;
            s.K = Kind::Box;
            const double c[3] = { double(i), double(j), double(k) };
            for (int a = 0; a < 3; ++a)
            {
              if (a == axis)
                s.P[0][a] = s.P[1][a] = c[a] - 0.5;
              else if (a >= dim)
                s.P[0][a] = s.P[1][a] = 0.0;
              else
              {
                s.P[0][a] = c[a] - 0.5;
                s.P[1][a] = c[a] + 0.5;
              }
            }
            s.P[2] = s.P[1];
            s.Axis = static_cast<std::int8_t>(axis);
            s.Plane = c[axis] - 0.5;
            b.Image.push_back(s);
            if (A != 0)
              b.PerMaterial[A].first.push_back(s);
            if (B != 0)
              b.PerMaterial[B].first.push_back(s);
          }
    }
  }
  // Mesh: boundary facets.
  if (mesh.NumberOfCells() > 0)
  {
    const auto incidence = checks_detail::BuildVertexIncidence(mesh);
    const auto records = checks_detail::ExtractMeshBoundary(mesh, incidence);
    const bool is3D = mesh.Dimension == 3;
    for (const auto& r : records)
    {
      Shape s;
      s.K = is3D ? Kind::Triangle : Kind::Segment;
      s.P[0] = mesh.Points[r.Vertices[0]];
      s.P[1] = mesh.Points[r.Vertices[1]];
      s.P[2] = is3D ? mesh.Points[r.Vertices[2]] : s.P[1];
      SetPlane(s, mesh.Dimension);
      if (r.FirstOfFacet)
        b.Mesh.push_back(s);
      b.PerMaterial[r.Material].second.push_back(s);
    }
  }
  return b;
}

/// A material whose boundaries are the overall ones (a single material):
/// its pieces are a subset of the overall ones, so equal counts mean equal sets.
bool SameAsOverall(const Boundaries& b, const std::pair<std::vector<Shape>, std::vector<Shape>>& m)
{
  return m.first.size() == b.Image.size() && m.second.size() == b.Mesh.size();
}

DistanceReport MeasurePair(const std::vector<Shape>& image, const std::vector<Shape>& mesh, double tolerance)
{
  DistanceReport d;
  if (image.empty() != mesh.empty())
  {
    d.ImageToMesh = d.MeshToImage = Infinity;
    return d;
  }
  d.ImageToMesh = DirectedDistance(image, mesh).Measure(tolerance);
  d.MeshToImage = DirectedDistance(mesh, image).Measure(tolerance);
  return d;
}

bool WithinPair(const std::vector<Shape>& image, const std::vector<Shape>& mesh, double imageToMesh,
  double meshToImage)
{
  if (image.empty() != mesh.empty())
    return false;
  return DirectedDistance(image, mesh).Within(imageToMesh) &&
    DirectedDistance(mesh, image).Within(meshToImage);
}

} // namespace

HausdorffReport MeasureHausdorff(const LabelImage& image, const SimplexMesh& mesh, double tolerance)
{
  const Boundaries b = ExtractBoundaries(image, mesh);
  HausdorffReport report;
  report.Overall = MeasurePair(b.Image, b.Mesh, tolerance);
  for (const auto& entry : b.PerMaterial)
    report.PerMaterial[entry.first] = SameAsOverall(b, entry.second)
      ? report.Overall
      : MeasurePair(entry.second.first, entry.second.second, tolerance);
  return report;
}

bool WithinHausdorff(const LabelImage& image, const SimplexMesh& mesh, double imageToMesh, double meshToImage)
{
  const Boundaries b = ExtractBoundaries(image, mesh);
  if (!WithinPair(b.Image, b.Mesh, imageToMesh, meshToImage))
    return false;
  for (const auto& entry : b.PerMaterial)
    if (!SameAsOverall(b, entry.second) &&
      !WithinPair(entry.second.first, entry.second.second, imageToMesh, meshToImage))
      return false;
  return true;
}

} // namespace labelmesher
