// SPDX-License-Identifier: GPL-2.0-or-later
// Turns fitted handles back towards their chords, as little as it takes to keep the corners' bound.
#include "Curving/CornerHandles.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
namespace
{

constexpr double kDegree = 3.14159265358979323846 / 180.0;
/// Kept beyond the bound: untangling bends the cells' other edges a little.
constexpr double kMarginDegrees = 0.1;

/// One handle at a vertex: the control point `Handle` of a piece, next to the vertex, on the edge
/// towards `Towards`.
struct HandleAt
{
  Point2* Handle = nullptr;
  std::int64_t Towards = 0;
};

double Cross(const Point2& a, const Point2& b) { return a[0] * b[1] - a[1] * b[0]; }
double Dot(const Point2& a, const Point2& b) { return a[0] * b[0] + a[1] * b[1]; }

/// The interval of turns (radians, counter-clockwise positive) of the edge v -> w's direction
/// that keeps every cell with that edge at a corner of at least `bound` at v, its other edge
/// straight.
void AllowedTurns(const SimplexMesh& linear, const std::vector<std::size_t>& cellsAtV, std::int64_t v,
  std::int64_t w, double bound, double& lowest, double& highest)
{
  const Point2 p{ linear.Points[v][0], linear.Points[v][1] };
  const Point2 edge{ linear.Points[w][0] - p[0], linear.Points[w][1] - p[1] };
  lowest = -HUGE_VAL;
  highest = HUGE_VAL;
  for (std::size_t c : cellsAtV)
  {
    const std::int64_t* cell = linear.Cell(c);
    if (cell[0] != w && cell[1] != w && cell[2] != w)
      continue;
    const std::int64_t u = cell[0] != v && cell[0] != w ? cell[0] : (cell[1] != v && cell[1] != w ? cell[1] : cell[2]);
    const Point2 other{ linear.Points[u][0] - p[0], linear.Points[u][1] - p[1] };
    const double side = Cross(edge, other);
    const double corner = std::atan2(std::abs(side), Dot(edge, other));
    // Turning the edge towards the other one (its side) narrows the corner.
    if (side > 0.0)
      highest = std::min(highest, corner - bound);
    else
      lowest = std::max(lowest, bound - corner);
  }
}

} // namespace

std::size_t TurnHandlesToKeepCorners(const SimplexMesh& linear, const std::vector<InterfaceChain>& chains,
  std::vector<CurvePiece>& pieces, double bound)
{
  std::vector<std::vector<std::size_t>> cellsAt(linear.Points.size());
  for (std::size_t c = 0; c < linear.NumberOfCells(); ++c)
    for (int k = 0; k < 3; ++k)
      cellsAt[static_cast<std::size_t>(linear.Cell(c)[k])].push_back(c);
  const double limit = (bound + kMarginDegrees) * kDegree;

  std::size_t turned = 0, first = 0;
  for (const InterfaceChain& chain : chains)
  {
    const std::size_t n = chain.Vertices.size();
    const std::size_t segments = chain.Closed ? n : n - 1;
    for (std::size_t i = 0; i < n; ++i)
    {
      // The handles at vertex i: its outgoing segment's first, its incoming segment's second. On
      // an open chain the end vertices have one each (a chain ending where it starts too: its
      // two ends are not joined).
      std::vector<HandleAt> handles;
      if (chain.Closed || i + 1 < n)
        handles.push_back({ &pieces[first + i].Fitted[0], chain.Vertices[(i + 1) % n] });
      if (chain.Closed || i > 0)
      {
        const std::size_t incoming = (i + n - 1) % n;
        handles.push_back({ &pieces[first + incoming].Fitted[1], chain.Vertices[incoming] });
      }
      const std::int64_t v = chain.Vertices[i];
      const Point2 p{ linear.Points[v][0], linear.Points[v][1] };
      double lowest = -HUGE_VAL, highest = HUGE_VAL; // of the one rotation that turns them all
      bool degenerate = false;
      for (const HandleAt& h : handles)
      {
        const Point2 chord{ linear.Points[h.Towards][0] - p[0], linear.Points[h.Towards][1] - p[1] };
        const Point2 handle{ (*h.Handle)[0] - p[0], (*h.Handle)[1] - p[1] };
        degenerate = degenerate || Dot(handle, handle) == 0.0;
        const double now = std::atan2(Cross(chord, handle), Dot(chord, handle)); // the handle's turn
        double low = 0.0, high = 0.0;
        AllowedTurns(linear, cellsAt[static_cast<std::size_t>(v)], v, h.Towards, limit, low, high);
        lowest = std::max(lowest, low - now);
        highest = std::min(highest, high - now);
      }
      if (degenerate || lowest > highest || (lowest <= 0.0 && 0.0 <= highest))
        continue; // no rotation keeps them all, or none is needed
      const double rotation = lowest > 0.0 ? lowest : highest;
      const double cs = std::cos(rotation), sn = std::sin(rotation);
      for (const HandleAt& h : handles)
      {
        const double x = (*h.Handle)[0] - p[0], y = (*h.Handle)[1] - p[1];
        *h.Handle = { p[0] + cs * x - sn * y, p[1] + sn * x + cs * y };
      }
      ++turned;
    }
    first += segments;
  }
  return turned;
}

std::size_t PullQuadraticsToKeepCorners(const SimplexMesh& linear, std::vector<CurvePiece>& pieces, double bound)
{
  std::vector<std::vector<std::size_t>> cellsAt(linear.Points.size());
  for (std::size_t c = 0; c < linear.NumberOfCells(); ++c)
    for (int k = 0; k < 3; ++k)
      cellsAt[static_cast<std::size_t>(linear.Cell(c)[k])].push_back(c);
  const double limit = (bound + kMarginDegrees) * kDegree;
  std::size_t pulled = 0;
  for (CurvePiece& piece : pieces)
  {
    if (!piece.Quadratic)
      continue;
    const Point2 a{ linear.Points[piece.From][0], linear.Points[piece.From][1] };
    const Point2 b{ linear.Points[piece.To][0], linear.Points[piece.To][1] };
    const Point2 middle{ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]) };
    const Point2 q = NearestQuadraticControl(a, piece.Fitted[0], piece.Fitted[1], b);
    // The turns each end's tangent may make; a straight edge (turn 0) is always allowed, as the
    // linear mesh keeps the bound (the margin aside).
    std::array<double, 2> low{}, high{};
    AllowedTurns(linear, cellsAt[static_cast<std::size_t>(piece.From)], piece.From, piece.To, limit, low[0], high[0]);
    AllowedTurns(linear, cellsAt[static_cast<std::size_t>(piece.To)], piece.To, piece.From, limit, low[1], high[1]);
    auto keeps = [&](double s) {
      const Point2 control{ middle[0] + s * (q[0] - middle[0]), middle[1] + s * (q[1] - middle[1]) };
      for (int end = 0; end < 2; ++end)
      {
        const Point2& v = end == 0 ? a : b;
        const Point2& w = end == 0 ? b : a;
        const Point2 chord{ w[0] - v[0], w[1] - v[1] }, tangent{ control[0] - v[0], control[1] - v[1] };
        const double turn = std::atan2(Cross(chord, tangent), Dot(chord, tangent));
        if (turn < std::min(low[end], 0.0) || turn > std::max(high[end], 0.0))
          return false;
      }
      return true;
    };
    // The largest of 1, 0.9, ..., 0.1, 0 that keeps both ends (the tangents turn towards the chord
    // as the control point moves towards its midpoint).
    int tenths = 10;
    while (tenths > 0 && !keeps(tenths / 10.0))
      --tenths;
    if (tenths == 10)
      continue;
    const double s = tenths / 10.0;
    piece.Fitted = ElevateQuadratic(a, { middle[0] + s * (q[0] - middle[0]), middle[1] + s * (q[1] - middle[1]) }, b);
    ++pulled;
  }
  return pulled;
}

} // namespace labelmesher
