// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file CoplanarCoverage.cxx
 * CoveredByCoplanar: interval coverage for segments on an axis-aligned line
 * (2D meshes); for polygons in an axis-aligned plane, each coplanar target is
 * projected onto the plane's two axes and clipped to the element
 * (Sutherland-Hodgman), and the clipped areas are summed after checking that
 * no two of them overlap.
 */

#include "Checks/CoplanarCoverage.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace labelmesher
{
namespace checks_detail
{

namespace
{

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

/// The shape's corners on axes (u, w), counter-clockwise.
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

bool OffPlaneOf(const Shape& t, const Shape& e)
{
  return t.Axis != e.Axis || std::abs(t.Plane - e.Plane) > RoundOff;
}

/// 1D element on an axis-aligned line (corners c[0], c[1]): interval coverage.
bool SegmentCovered(const Shape& e, const Point3* c, const std::vector<Shape>& targets,
  const std::vector<std::uint32_t>& candidates)
{
  const int b = 1 - e.Axis;
  const double s0 = std::min(c[0][b], c[1][b]), s1 = std::max(c[0][b], c[1][b]);
  const double length = s1 - s0;
  if (!(length > 0))
    return false;
  std::vector<std::pair<double, double>> pieces;
  for (std::uint32_t id : candidates)
  {
    const Shape& t = targets[id];
    if (OffPlaneOf(t, e))
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
  double sum = 0, end = -std::numeric_limits<double>::infinity();
  for (const auto& iv : pieces)
  {
    if (iv.first < end - RoundOff * length)
      return false; // overlapping pieces: the sum proves nothing
    sum += iv.second - iv.first;
    end = std::max(end, iv.second);
  }
  return sum >= length * (1.0 - RoundOff);
}

/// 2D element (3D meshes): clipped areas.
bool PolygonCovered(const Shape& e, const std::vector<Shape>& targets,
  const std::vector<std::uint32_t>& candidates)
{
  const int u = (e.Axis + 1) % 3, w = (e.Axis + 2) % 3;
  const Polygon ep = Project(e, u, w);
  const double area = SignedArea(ep);
  if (!(area > 0))
    return false;
  // Reused across calls: this runs once per element and sub-element.
  thread_local std::vector<Polygon> parts;
  parts.clear();
  double sum = 0;
  for (std::uint32_t id : candidates)
  {
    const Shape& t = targets[id];
    if (OffPlaneOf(t, e))
      continue;
    const Polygon tp = Project(t, u, w);
    if (tp.N < 3)
      continue;
    const Polygon part = Clip(tp, ep);
    if (part.N < 3)
      continue;
    const double a = SignedArea(part);
    if (!(a > RoundOff * area))
      continue;
    for (const Polygon& other : parts)
      if (SignedArea(Clip(part, other)) > RoundOff * area)
        return false; // overlapping pieces: the sum proves nothing
    sum += a;
    parts.push_back(part);
  }
  return sum >= area * (1.0 - RoundOff);
}

} // namespace

bool CoveredByCoplanar(
  const Shape& e, const std::vector<Shape>& targets, const std::vector<std::uint32_t>& candidates)
{
  Point3 c[4];
  const int n = Corners(e, c);
  if (n == 2)
    return SegmentCovered(e, c, targets, candidates);
  if (n < 3)
    return false;
  return PolygonCovered(e, targets, candidates);
}

} // namespace checks_detail
} // namespace labelmesher
