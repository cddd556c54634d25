// SPDX-License-Identifier: GPL-2.0-or-later
// The mesher's exact branch-and-bound test of one side of a Hausdorff bound (no code shared with
// Checks/).
#include "Criteria/DistanceBound.h"

#include "Support/Geometry.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
namespace
{
using namespace geometry;
constexpr double kRoundOff = 1e-9;

/// A parallelogram whose corners, in order, are those of an axis-aligned
/// rectangle [lo, hi] (flat along one axis), as voxel faces are.
bool IsAxisRectangle(const ConvexPiece& piece, Point3& lo, Point3& hi)
{
  const Point3* q = piece.Points;
  int flat = 0;
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::min(q[0][a], q[2][a]);
    hi[a] = std::max(q[0][a], q[2][a]);
    flat += lo[a] == hi[a];
    // Every corner takes the low or high value; q1, q3 are the other diagonal.
    for (int i = 1; i < 4; i += 2)
      if (q[i][a] != lo[a] && q[i][a] != hi[a])
        return false;
    if (q[1][a] + q[3][a] != lo[a] + hi[a])
      return false;
  }
  // q1 is a corner next to both q0 and q2 (not a repeat of either).
  int fromQ0 = 0, fromQ2 = 0;
  for (int a = 0; a < 3; ++a)
  {
    fromQ0 += q[1][a] != q[0][a];
    fromQ2 += q[1][a] != q[2][a];
  }
  return flat == 1 && fromQ0 == 1 && fromQ2 == 1;
}

/// A piece the element is measured against, with its box when it is an
/// axis-aligned rectangle (voxel faces are): then the distance to that box
/// (flat along one axis) is the distance, at a tenth of the cost. Found once
/// per piece: the subdivision measures the same pieces again and again.
struct Target
{
  ConvexPiece Piece;
  bool IsBox = false;
  Point3 Lo{}, Hi{};

  explicit Target(const ConvexPiece& piece)
    : Piece(piece)
  {
    IsBox = piece.Count == 4 && IsAxisRectangle(piece, Lo, Hi); // after Lo and Hi are initialised
  }
};

double SquaredDistanceTo(const Point3& p, const Target& target)
{
  const ConvexPiece& piece = target.Piece;
  if (target.IsBox)
    return SquaredDistanceToBox(p, target.Lo, target.Hi);
  switch (piece.Count)
  {
    case 2:
      return SquaredDistanceToSegment(p, piece.Points[0], piece.Points[1]);
    case 3:
      return SquaredDistanceToTriangle(p, piece.Points[0], piece.Points[1], piece.Points[2]);
    default:
      return std::min(SquaredDistanceToTriangle(p, piece.Points[0], piece.Points[1], piece.Points[2]),
        SquaredDistanceToTriangle(p, piece.Points[0], piece.Points[2], piece.Points[3]));
  }
}

double DistanceTo(const Point3& p, const Target& target)
{
  return std::sqrt(SquaredDistanceTo(p, target));
}

/// The axis along which all points of `piece` share one coordinate, or -1.
int FlatAxis(const ConvexPiece& piece, int dimension)
{
  for (int a = 0; a < dimension; ++a)
  {
    bool flat = true;
    for (int i = 1; i < piece.Count; ++i)
      flat = flat && std::abs(piece.Points[i][a] - piece.Points[0][a]) < kRoundOff;
    if (flat)
      return a;
  }
  return -1;
}

using Polygon2 = std::vector<std::array<double, 2>>;

double Area(const Polygon2& p)
{
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - u[1] * v[0];
  }
  return 0.5 * a;
}

/// Sutherland-Hodgman: `subject` clipped by the convex counter-clockwise `clip`.
Polygon2 Clip(Polygon2 subject, const Polygon2& clip)
{
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e)
  {
    const auto& a = clip[e];
    const auto& b = clip[(e + 1) % clip.size()];
    auto side = [&](const std::array<double, 2>& p) {
      return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    };
    Polygon2 out;
    for (std::size_t i = 0; i < subject.size(); ++i)
    {
      const auto& p = subject[i];
      const auto& q = subject[(i + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0)
        out.push_back(p);
      if ((sp >= 0) != (sq >= 0))
      {
        const double t = sp / (sp - sq);
        out.push_back({ p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]) });
      }
    }
    subject = std::move(out);
  }
  return subject;
}

Polygon2 Project(const ConvexPiece& piece, int axis)
{
  const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
  Polygon2 p;
  for (int i = 0; i < piece.Count; ++i)
    p.push_back({ piece.Points[i][u], piece.Points[i][v] });
  if (Area(p) < 0)
    std::reverse(p.begin(), p.end());
  return p;
}

/// The element lies in an axis-aligned plane (3D) and coplanar pieces, which
/// do not overlap, cover it: its distance to them is 0.
bool CoveredExactly(const ConvexPiece& element, const std::vector<Target>& targets)
{
  const int axis = element.Count >= 3 ? FlatAxis(element, 3) : -1;
  if (axis < 0)
    return false;
  const Polygon2 subject = Project(element, axis);
  const double target = Area(subject);
  double covered = 0.0;
  for (const Target& t : targets)
  {
    const ConvexPiece& piece = t.Piece;
    if (piece.Count < 3 || FlatAxis(piece, 3) != axis ||
      std::abs(piece.Points[0][axis] - element.Points[0][axis]) > kRoundOff)
      continue;
    const Polygon2 overlap = Clip(subject, Project(piece, axis));
    if (overlap.size() >= 3)
      covered += std::abs(Area(overlap));
  }
  return covered >= target * (1.0 - 1e-12) - 1e-15;
}

/// 2D analogue: a segment on a line that collinear segments cover.
bool CoveredExactlyOnLine(const ConvexPiece& element, const std::vector<Target>& targets)
{
  if (element.Count != 2)
    return false;
  for (int along = 0; along < 2; ++along)
  {
    const int across = 1 - along;
    if (std::abs(element.Points[0][across] - element.Points[1][across]) > kRoundOff)
      continue;
    const double lo = std::min(element.Points[0][along], element.Points[1][along]);
    const double hi = std::max(element.Points[0][along], element.Points[1][along]);
    double covered = 0.0;
    for (const Target& t : targets)
    {
      const ConvexPiece& piece = t.Piece;
      if (piece.Count != 2 || std::abs(piece.Points[0][across] - element.Points[0][across]) > kRoundOff ||
        std::abs(piece.Points[1][across] - element.Points[0][across]) > kRoundOff)
        continue;
      const double a = std::max(lo, std::min(piece.Points[0][along], piece.Points[1][along]));
      const double b = std::min(hi, std::max(piece.Points[0][along], piece.Points[1][along]));
      covered += std::max(0.0, b - a);
    }
    return covered >= (hi - lo) * (1.0 - 1e-12) - 1e-15;
  }
  return false;
}

std::vector<ConvexPiece> Subdivide(const ConvexPiece& e)
{
  auto mid = [](const Point3& a, const Point3& b) { return Scale(Add(a, b), 0.5); };
  const Point3* p = e.Points;
  switch (e.Count)
  {
    case 2:
    {
      const Point3 m = mid(p[0], p[1]);
      return { ConvexPiece{ 2, { p[0], m } }, ConvexPiece{ 2, { m, p[1] } } };
    }
    case 3:
    {
      const Point3 a = mid(p[0], p[1]), b = mid(p[1], p[2]), c = mid(p[2], p[0]);
      return { ConvexPiece{ 3, { p[0], a, c } }, ConvexPiece{ 3, { a, p[1], b } }, ConvexPiece{ 3, { c, b, p[2] } },
        ConvexPiece{ 3, { a, b, c } } };
    }
    default:
    {
      const Point3 a = mid(p[0], p[1]), b = mid(p[1], p[2]), c = mid(p[2], p[3]), d = mid(p[3], p[0]);
      const Point3 o = mid(a, c);
      return { ConvexPiece{ 4, { p[0], a, o, d } }, ConvexPiece{ 4, { a, p[1], b, o } },
        ConvexPiece{ 4, { o, b, p[2], c } }, ConvexPiece{ 4, { d, o, c, p[3] } } };
    }
  }
}

/// The pieces that can matter for `element`: those within h of some point of
/// it, hence within h + rho of its vertex centroid c (rho: the farthest vertex
/// from c), with their distances to c. A generous margin keeps every piece
/// round-off could make matter, so the verdict is the one the whole list
/// gives, only cheaper to reach. (Distances, not their squares: the same
/// pieces in the same order as before the pieces were prepared, since the
/// order reaches the sums of CoveredExactly.)
void Cull(const ConvexPiece& element, const std::vector<Target>& targets, double h,
  std::vector<std::pair<double, std::size_t>>& near)
{
  Point3 c{ 0.0, 0.0, 0.0 };
  for (int i = 0; i < element.Count; ++i)
    c = Add(c, element.Points[i]);
  c = Scale(c, 1.0 / element.Count);
  double rho = 0.0;
  for (int i = 0; i < element.Count; ++i)
    rho = std::max(rho, Distance(c, element.Points[i]));
  const double reach = h + rho + 1e-6;
  near.clear();
  for (std::size_t t = 0; t < targets.size(); ++t)
  {
    const double d = DistanceTo(c, targets[t]);
    if (d <= reach)
      near.emplace_back(d, t);
  }
}

/// The piece is within h of every vertex: then of the whole element (the
/// distance to a convex piece is convex).
bool Covers(const Target& target, const ConvexPiece& element, double h)
{
  for (int i = 0; i < element.Count; ++i)
    if (!(DistanceTo(element.Points[i], target) <= h + kRoundOff)) // a NaN distance proves nothing
      return false;
  return true;
}

bool Within(const ConvexPiece& element, const std::vector<Target>& allTargets, double h, int depth)
{
  // Most of the time is spent on elements among many far pieces (a large
  // merged face, a large leaf): cull before looking closer, and try the
  // nearest piece, which usually proves the element at once, before sorting
  // the others by distance.
  std::vector<Target> culled;
  const bool cull = allTargets.size() > 8;
  if (cull)
  {
    std::vector<std::pair<double, std::size_t>> near;
    Cull(element, allTargets, h, near);
    if (near.empty())
      return false;
    const auto nearest = std::min_element(near.begin(), near.end());
    if (Covers(allTargets[nearest->second], element, h))
      return true;
    std::sort(near.begin(), near.end());
    culled.reserve(near.size());
    for (const auto& entry : near)
      culled.push_back(allTargets[entry.second]);
  }
  const std::vector<Target>& targets = cull ? culled : allTargets;
  if (targets.empty())
    return false;
  for (std::size_t t = cull ? 1 : 0; t < targets.size(); ++t) // culled: the first, the nearest, failed above
    if (Covers(targets[t], element, h))
      return true;
  double worstVertex = 0.0;
  for (int i = 0; i < element.Count; ++i)
  {
    double best = INFINITY;
    for (const Target& target : targets)
      best = std::min(best, SquaredDistanceTo(element.Points[i], target));
    worstVertex = std::max(worstVertex, std::sqrt(best));
  }
  if (worstVertex > h + kRoundOff)
    return false;
  if (worstVertex < kRoundOff && (CoveredExactly(element, targets) || CoveredExactlyOnLine(element, targets)))
    return true;
  if (depth == 0)
    return false;
  for (const ConvexPiece& child : Subdivide(element))
    if (!Within(child, targets, h, depth - 1))
      return false;
  return true;
}

} // namespace

bool WithinDistance(const ConvexPiece& element, const std::vector<ConvexPiece>& pieces, double h, int maxDepth)
{
  if (pieces.empty())
    return false;
  const std::vector<Target> targets(pieces.begin(), pieces.end());
  return Within(element, targets, h, maxDepth);
}

} // namespace labelmesher
