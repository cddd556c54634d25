// SPDX-License-Identifier: GPL-2.0-or-later
// Triangulates one square face of a leaf from its corner labels and split points (section 3.1.2).
#include "Fill/FaceTriangulation.h"

#include "Support/Geometry.h"
#include "Octree/LatticeLabels.h"

#include <stdexcept>

namespace labelmesher
{
namespace
{

const FacePoint kCorner[4] = { { 0, 0 }, { 4, 0 }, { 0, 4 }, { 4, 4 } };
const FacePoint kMidpoint[4] = { { 2, 0 }, { 4, 2 }, { 2, 4 }, { 0, 2 } };
const FacePoint kCentre{ 2, 2 };
// Counter-clockwise: corner 0, edge 0, corner 1, edge 1, corner 3, edge 2, corner 2, edge 3.
const int kRingCorner[4] = { 0, 1, 3, 2 };

long long Cross2(const FacePoint& o, const FacePoint& p, const FacePoint& q)
{
  return static_cast<long long>(p.A - o.A) * (q.B - o.B) - static_cast<long long>(p.B - o.B) * (q.A - o.A);
}

struct RingPoint
{
  FacePoint Point;
  int Corner = -1; ///< face corner index, or -1 for an edge midpoint
};

std::vector<RingPoint> Ring(unsigned midpointMask)
{
  std::vector<RingPoint> ring;
  for (int i = 0; i < 4; ++i)
  {
    ring.push_back({ kCorner[kRingCorner[i]], kRingCorner[i] });
    if (midpointMask & (1u << i))
      ring.push_back({ kMidpoint[i], -1 });
  }
  return ring;
}

/// Fan of a convex polygon (counter-clockwise) from its vertex `apex`; empty if
/// that would leave a polygon vertex hanging on a fan edge (collinear points).
std::vector<FaceTriangle> FanFromVertex(const std::vector<FacePoint>& polygon, std::size_t apex, int side)
{
  std::vector<FaceTriangle> out;
  const std::size_t n = polygon.size();
  for (std::size_t t = 1; t + 1 < n; ++t)
  {
    const FacePoint& p = polygon[(apex + t) % n];
    const FacePoint& q = polygon[(apex + t + 1) % n];
    if (Cross2(polygon[apex], p, q) == 0)
      return {};
    out.push_back({ { polygon[apex], p, q }, side });
  }
  return out;
}

/// Fan of a convex polygon from an interior point.
std::vector<FaceTriangle> FanFromPoint(const std::vector<FacePoint>& polygon, const FacePoint& centre, int side)
{
  std::vector<FaceTriangle> out;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const FacePoint& p = polygon[i];
    const FacePoint& q = polygon[(i + 1) % polygon.size()];
    if (Cross2(centre, p, q) == 0)
      continue; // centre on this side of the polygon: that side is split there
    out.push_back({ { centre, p, q }, side });
  }
  return out;
}

bool StrictlyInside(const std::vector<FacePoint>& polygon, const FacePoint& p)
{
  for (std::size_t i = 0; i < polygon.size(); ++i)
    if (Cross2(polygon[i], polygon[(i + 1) % polygon.size()], p) <= 0)
      return false;
  return true;
}

bool OnBoundary(const std::vector<FacePoint>& polygon, const FacePoint& p)
{
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const FacePoint& a = polygon[i];
    const FacePoint& b = polygon[(i + 1) % polygon.size()];
    if (Cross2(a, b, p) == 0 && std::min(a.A, b.A) <= p.A && p.A <= std::max(a.A, b.A) &&
      std::min(a.B, b.B) <= p.B && p.B <= std::max(a.B, b.B))
      return true;
  }
  return false;
}

std::vector<std::vector<FaceTriangle>> PieceCandidates(const std::vector<FacePoint>& piece, int side)
{
  std::vector<std::vector<FaceTriangle>> candidates;
  if (StrictlyInside(piece, kCentre))
    candidates.push_back(FanFromPoint(piece, kCentre, side));
  for (std::size_t v = 0; v < piece.size(); ++v)
  {
    auto fan = FanFromVertex(piece, v, side);
    if (!fan.empty())
      candidates.push_back(std::move(fan));
  }
  return candidates;
}

/// The crossed-face table entry for the corner signs (see the header); empty
/// when the face is not crossed or is a saddle.
std::vector<FaceTriangle> BuildCrossed(unsigned negative, unsigned zero)
{
  auto sign = [&](int q) { return ((zero >> q) & 1u) ? 0 : (((negative >> q) & 1u) ? -1 : 1); };
  const std::array<int, 4> ringSigns{ sign(kRingCorner[0]), sign(kRingCorner[1]), sign(kRingCorner[2]),
    sign(kRingCorner[3]) };
  std::array<int, 8> where{};
  if (RingTransitions(ringSigns, where) != 2)
    return {};
  // The ring with the two transition points: corners, and the midpoints of
  // crossed sides (ring positions: 2 i corner kRingCorner[i], 2 i + 1 side i).
  struct Stop
  {
    FacePoint Point;
    int Corner; ///< face corner, or -1 for a midpoint
    bool Transition;
  };
  std::vector<Stop> ring;
  for (int position = 0; position < 8; ++position)
  {
    const bool transition = position == where[0] || position == where[1];
    if (position % 2 == 0)
      ring.push_back({ kCorner[kRingCorner[position / 2]], kRingCorner[position / 2], transition });
    else if (transition)
      ring.push_back({ kMidpoint[position / 2], -1, true });
  }
  std::size_t cut[2], found = 0;
  for (std::size_t i = 0; i < ring.size(); ++i)
    if (ring[i].Transition)
      cut[found++] = i;
  std::vector<FacePoint> pieces[2];
  int sides[2] = { -1, -1 };
  for (int p = 0; p < 2; ++p)
  {
    for (std::size_t i = cut[p];; i = (i + 1) % ring.size())
    {
      pieces[p].push_back(ring[i].Point);
      if (!ring[i].Transition && ring[i].Corner >= 0 && sign(ring[i].Corner) != 0)
        sides[p] = ring[i].Corner;
      if (i == cut[1 - p])
        break;
    }
    if (sides[p] < 0)
      throw std::logic_error("a crossed-face piece without a labelled corner");
  }

  const double apexHeight = 0.5;
  std::vector<FaceTriangle> best;
  double bestScore = -1.0;
  auto consider = [&](std::vector<FaceTriangle> candidate) {
    const double score = ConedMinimumDihedralAngle(candidate, apexHeight);
    if (score > bestScore + 1e-12) // ties keep the earlier candidate: deterministic
    {
      bestScore = score;
      best = std::move(candidate);
    }
  };
  // The face centre lies on the intersection edge when it joins opposite edges:
  // then it may become a vertex of both pieces at once.
  if (OnBoundary(pieces[0], kCentre) && OnBoundary(pieces[1], kCentre))
  {
    std::vector<FaceTriangle> both = FanFromPoint(pieces[0], kCentre, sides[0]);
    auto second = FanFromPoint(pieces[1], kCentre, sides[1]);
    both.insert(both.end(), second.begin(), second.end());
    consider(both);
  }
  const auto first = PieceCandidates(pieces[0], sides[0]);
  const auto second = PieceCandidates(pieces[1], sides[1]);
  for (const auto& a : first)
    for (const auto& b : second)
    {
      std::vector<FaceTriangle> combined = a;
      combined.insert(combined.end(), b.begin(), b.end());
      consider(combined);
    }
  return best;
}

} // namespace

double ConedMinimumDihedralAngle(const std::vector<FaceTriangle>& triangles, double apexHeight)
{
  double smallest = 180.0;
  const Point3 apex{ 0.5, 0.5, apexHeight };
  for (const FaceTriangle& t : triangles)
  {
    Point3 p[3];
    for (int i = 0; i < 3; ++i)
      p[i] = { t.Points[i].A / 4.0, t.Points[i].B / 4.0, 0.0 };
    smallest = std::min(smallest, geometry::MinimumDihedralAngle(p[0], p[1], p[2], apex));
  }
  return smallest;
}

bool IsCrossedFace(unsigned negative, unsigned zero)
{
  const unsigned labelled = ~zero & 15u;
  return (negative & labelled) != 0 && (~negative & labelled) != 0;
}

std::vector<FaceTriangle> TriangulateFace(FaceKind kind, unsigned midpointMask, unsigned negative, unsigned zero)
{
  switch (kind)
  {
    case FaceKind::Plain:
      return { { { kCorner[0], kCorner[1], kCorner[3] }, 0 }, { { kCorner[0], kCorner[3], kCorner[2] }, 0 } };
    case FaceKind::Split:
    {
      std::vector<FaceTriangle> out;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
        {
          const FacePoint o{ 2 * i, 2 * j };
          out.push_back({ { o, FacePoint{ o.A + 2, o.B }, FacePoint{ o.A + 2, o.B + 2 } }, 0 });
          out.push_back({ { o, FacePoint{ o.A + 2, o.B + 2 }, FacePoint{ o.A, o.B + 2 } }, 0 });
        }
      return out;
    }
    case FaceKind::Fan:
    {
      std::vector<FacePoint> polygon;
      for (const RingPoint& r : Ring(midpointMask))
        polygon.push_back(r.Point);
      return FanFromPoint(polygon, kCentre, 0);
    }
    case FaceKind::Crossed:
    {
      // 81 sign patterns, keyed as negative | zero << 4 (negative bits of
      // 0-corners are ignored).
      static const std::array<std::vector<FaceTriangle>, 256> table = [] {
        std::array<std::vector<FaceTriangle>, 256> t;
        for (unsigned z = 0; z < 16; ++z)
          for (unsigned n = 0; n < 16; ++n)
            if ((n & z) == 0 && IsCrossedFace(n, z))
              t[n | (z << 4)] = BuildCrossed(n, z);
        return t;
      }();
      const unsigned key = (negative & ~zero & 15u) | ((zero & 15u) << 4);
      if (table[key].empty())
        throw std::logic_error("no crossed-face stencil for these corner signs (a saddle)");
      return table[key];
    }
  }
  return {};
}

} // namespace labelmesher
