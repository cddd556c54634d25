// SPDX-License-Identifier: GPL-2.0-or-later
// Boundary curves proven not to meet away from shared vertices: hull and cone tests with subdivision.
#include "Curving/CurveCrossings.h"

#include "Support/BoxBins.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace labelmesher
{
namespace
{

constexpr double kTwoPi = 6.283185307179586;

/// A piece of one curve with the vertex ids at its ends (-1 inside a curve).
struct Arc
{
  std::array<Point2, 4> P;
  std::int64_t Start = -1;
  std::int64_t End = -1;
  std::size_t Curve = 0;
};

Point2 Middle(const Point2& a, const Point2& b) { return { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]) }; }

std::pair<Arc, Arc> Split(const Arc& a)
{
  const auto& p = a.P;
  const Point2 p01 = Middle(p[0], p[1]), p12 = Middle(p[1], p[2]), p23 = Middle(p[2], p[3]);
  const Point2 p012 = Middle(p01, p12), p123 = Middle(p12, p23), mid = Middle(p012, p123);
  return { Arc{ { p[0], p01, p012, mid }, a.Start, -1, a.Curve }, Arc{ { mid, p123, p23, p[3] }, -1, a.End, a.Curve } };
}

double DistanceToChord(const Point2& q, const Point2& a, const Point2& b)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double l2 = dx * dx + dy * dy;
  const double t = l2 > 0.0 ? std::clamp(((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(a[0] + t * dx - q[0], a[1] + t * dy - q[1]);
}

/// Cuts an arc into pieces within `flatness` of their chords; each cut point
/// gets a new id (from `nextId`), so that the two pieces it joins are tested
/// like curves meeting at a vertex: that is what finds a curve's own loops.
void Cut(const Arc& a, double flatness, int depth, std::int64_t& nextId, std::vector<Arc>& out)
{
  if (depth >= 16 ||
    std::max(DistanceToChord(a.P[1], a.P[0], a.P[3]), DistanceToChord(a.P[2], a.P[0], a.P[3])) <= flatness)
  {
    out.push_back(a);
    return;
  }
  auto [left, right] = Split(a);
  left.End = right.Start = nextId++;
  Cut(left, flatness, depth + 1, nextId, out);
  Cut(right, flatness, depth + 1, nextId, out);
}

/// A line strictly separates the two control polygons (their hulls are
/// disjoint): in 2D it can be taken normal to an edge of one hull, and every
/// hull edge joins two of the points.
bool HullsDisjoint(const std::array<Point2, 4>& a, const std::array<Point2, 4>& b)
{
  for (const auto* set : { &a, &b })
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
      {
        const double nx = (*set)[j][1] - (*set)[i][1], ny = (*set)[i][0] - (*set)[j][0];
        if (nx == 0.0 && ny == 0.0)
          continue;
        double aLo = HUGE_VAL, aHi = -HUGE_VAL, bLo = HUGE_VAL, bHi = -HUGE_VAL;
        for (int k = 0; k < 4; ++k)
        {
          const double pa = nx * a[k][0] + ny * a[k][1], pb = nx * b[k][0] + ny * b[k][1];
          aLo = std::min(aLo, pa);
          aHi = std::max(aHi, pa);
          bLo = std::min(bLo, pb);
          bHi = std::max(bHi, pb);
        }
        if (aHi < bLo || bHi < aLo)
          return true;
      }
  return false;
}

/// The smallest arc of directions from `apex` holding the arc's other control
/// points: start angle in [0, 2 pi) and length; false when a point is the apex.
bool DirectionArc(const Arc& a, const Point2& apex, double& start, double& length)
{
  std::vector<double> angles;
  for (const Point2& p : a.P)
  {
    const double dx = p[0] - apex[0], dy = p[1] - apex[1];
    if (dx == 0.0 && dy == 0.0)
      continue;
    double t = std::atan2(dy, dx);
    angles.push_back(t < 0.0 ? t + kTwoPi : t);
  }
  // The apex is one of the points; the hull lies in the cone of the others' directions.
  if (angles.empty())
    return false;
  std::sort(angles.begin(), angles.end());
  // The arc is the circle less its largest gap.
  double gap = angles.front() + kTwoPi - angles.back();
  std::size_t after = 0;
  for (std::size_t k = 1; k < angles.size(); ++k)
    if (angles[k] - angles[k - 1] > gap)
    {
      gap = angles[k] - angles[k - 1];
      after = k;
    }
  start = angles[after];
  length = kTwoPi - gap;
  return true;
}

bool InArc(double angle, double start, double length)
{
  double d = angle - start;
  while (d < 0.0)
    d += kTwoPi;
  return d <= length;
}

/// Two arcs ending at one vertex meet only there when their direction arcs
/// are convex cones (< pi) and disjoint.
bool ConesDisjoint(const Arc& a, const Arc& b, std::int64_t vertex)
{
  const Point2& apex = a.Start == vertex ? a.P[0] : a.P[3];
  double sa, la, sb, lb;
  if (!DirectionArc(a, apex, sa, la) || !DirectionArc(b, apex, sb, lb))
    return false;
  return la < 0.5 * kTwoPi && lb < 0.5 * kTwoPi && !InArc(sb, sa, la) && !InArc(sa, sb, lb);
}

std::int64_t SharedVertex(const Arc& a, const Arc& b)
{
  for (std::int64_t v : { a.Start, a.End })
    if (v >= 0 && (v == b.Start || v == b.End))
      return v;
  return -1;
}

bool ProvenApart(const Arc& a, const Arc& b, int depth, int maxDepth)
{
  if (HullsDisjoint(a.P, b.P))
    return true;
  const std::int64_t shared = SharedVertex(a, b);
  if (shared >= 0 && ConesDisjoint(a, b, shared))
    return true;
  if (depth >= maxDepth)
    return false;
  const auto [a0, a1] = Split(a);
  const auto [b0, b1] = Split(b);
  for (const Arc* x : { &a0, &a1 })
    for (const Arc* y : { &b0, &b1 })
      if (!ProvenApart(*x, *y, depth + 1, maxDepth))
        return false;
  return true;
}

} // namespace

std::set<std::size_t> MeetingCurves(const std::vector<BoundaryCurve>& curves, double flatness, int maxDepth)
{
  std::int64_t nextId = 0;
  for (const BoundaryCurve& curve : curves)
    nextId = std::max({ nextId, curve.From + 1, curve.To + 1 });
  std::vector<Arc> arcs;
  for (std::size_t c = 0; c < curves.size(); ++c)
    Cut(Arc{ curves[c].ControlPoints, curves[c].From, curves[c].To, c }, flatness, 0, nextId, arcs);

  BoxBins bins(4.0);
  for (std::size_t i = 0; i < arcs.size(); ++i)
  {
    BoxBins::Point lo{ HUGE_VAL, HUGE_VAL }, hi{ -HUGE_VAL, -HUGE_VAL };
    for (const Point2& p : arcs[i].P)
      for (int d = 0; d < 2; ++d)
      {
        lo[d] = std::min(lo[d], p[d]);
        hi[d] = std::max(hi[d], p[d]);
      }
    bins.Insert(i, lo, hi);
  }
  std::set<std::size_t> meeting;
  std::set<std::pair<std::size_t, std::size_t>> tested;
  bins.ForEachBin([&](const std::vector<std::size_t>& members) {
    for (std::size_t i = 0; i < members.size(); ++i)
      for (std::size_t j = i + 1; j < members.size(); ++j)
      {
        const Arc& a = arcs[members[i]];
        const Arc& b = arcs[members[j]];
        // Pieces of one curve are tested too (its loops); consecutive ones
        // share their cut point like curves sharing a vertex.
        if (meeting.count(a.Curve) && meeting.count(b.Curve))
          continue;
        if (!tested.insert({ std::min(members[i], members[j]), std::max(members[i], members[j]) }).second)
          continue;
        if (!ProvenApart(a, b, 0, maxDepth))
        {
          meeting.insert(a.Curve);
          meeting.insert(b.Curve);
        }
      }
  });
  return meeting;
}

} // namespace labelmesher
