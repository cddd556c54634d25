// SPDX-License-Identifier: GPL-2.0-or-later
// Curved interface pieces at a scale, and their certified polylines.
#include "Curving/CurvePieces.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
namespace
{

double DistanceToSegment(const Point2& p, const Point2& a, const Point2& b)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length2 = dx * dx + dy * dy;
  const double t = length2 > 0.0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

Point2 Middle(const Point2& a, const Point2& b) { return { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]) }; }

void Flatten(const std::array<Point2, 4>& p, double epsilon, int depth, std::vector<Point2>& out)
{
  // Depth 20 splits a piece into a million: only a non-finite input gets there.
  if (depth >= 20 ||
    std::max(DistanceToSegment(p[1], p[0], p[3]), DistanceToSegment(p[2], p[0], p[3])) <= epsilon)
  {
    out.push_back(p[3]);
    return;
  }
  const Point2 p01 = Middle(p[0], p[1]), p12 = Middle(p[1], p[2]), p23 = Middle(p[2], p[3]);
  const Point2 p012 = Middle(p01, p12), p123 = Middle(p12, p23);
  const Point2 mid = Middle(p012, p123);
  Flatten({ p[0], p01, p012, mid }, epsilon, depth + 1, out);
  Flatten({ mid, p123, p23, p[3] }, epsilon, depth + 1, out);
}

} // namespace

std::array<Point2, 4> CurvePiece::ControlPoints(const SimplexMesh& linear) const
{
  const Point2 a{ linear.Points[From][0], linear.Points[From][1] };
  const Point2 b{ linear.Points[To][0], linear.Points[To][1] };
  std::array<Point2, 4> p{ a, a, b, b };
  for (int k = 0; k < 2; ++k)
  {
    const Point2& end = k == 0 ? a : b;
    const double w = (k + 1) / 3.0;
    const Point2 third{ a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]) };
    if (Scale > 0.0 && Quadratic)
    {
      // Both inner points move with the one quadratic control point: from the thirds (its
      // midpoint) towards the fitted ones, so that the piece stays a quadratic.
      p[k + 1] = { third[0] + Scale * (Fitted[k][0] - third[0]), third[1] + Scale * (Fitted[k][1] - third[1]) };
    }
    else if (Scale > 0.0)
    {
      p[k + 1] = { end[0] + Scale * (Fitted[k][0] - end[0]), end[1] + Scale * (Fitted[k][1] - end[1]) };
    }
    else
    {
      p[k + 1] = third;
    }
  }
  return p;
}

bool ShortenPiece(CurvePiece& piece)
{
  if (piece.Scale <= 0.0)
    return false;
  piece.Scale = piece.Scale > 0.25 ? 0.5 * piece.Scale : 0.0;
  return true;
}

std::vector<Point2> FlattenCubic(const std::array<Point2, 4>& controlPoints, double epsilon)
{
  std::vector<Point2> out{ controlPoints[0] };
  Flatten(controlPoints, epsilon, 0, out);
  return out;
}

} // namespace labelmesher
