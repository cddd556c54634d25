// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BernsteinCertificate_h
#define labelmesher_BernsteinCertificate_h

/**
 * @file BernsteinCertificate.h
 * What TetraJacobian.h and TriangleJacobian.h share: det J of a curved cell
 * lies between its smallest and largest Bernstein coefficients, so their
 * ratio bounds the scaled Jacobian from below; where that is not conclusive
 * the reference cell is subdivided (the map on each piece is again a cell of
 * the same degree, whose det J is the cell's times the piece's share of the
 * reference measure) and the bound taken over the pieces.
 */

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace labelmesher
{

/// min coefficient / max coefficient as a certified lower bound of
/// min det J / max det J: positive only when the smallest is positive beyond
/// the coefficients' round-off (1e-12 of the largest: they are sums of
/// products of the nodes); 0 when positive but not beyond; otherwise the
/// smallest over the largest absolute one (≤ 0: not proved valid).
inline double BernsteinRatio(double lo, double hi)
{
  constexpr double kRoundOff = 1e-12;
  if (lo > kRoundOff * hi)
    return lo / hi;
  if (lo > 0.0)
    return 0.0;
  const double largest = std::max(std::fabs(lo), std::fabs(hi));
  return largest > 0.0 ? lo / largest : -1.0;
}

/// The bound for the cell with `nodes`, subdividing up to `depth` levels the
/// pieces that hold it below `target`. `extremes(nodes)` gives a cell's
/// smallest and largest coefficients; `refine(nodes, children)` appends the
/// nodes of its pieces, each with `childShare` of its parent's measure.
template <typename Nodes, typename Extremes, typename Refine>
double CertifiedBernsteinRatio(const Nodes& nodes, double target, int depth, double childShare, Extremes&& extremes,
  Refine&& refine)
{
  struct Piece
  {
    Nodes Points;
    double Share;
    double Low, High; ///< its coefficients' extremes, divided by Share
  };
  auto make = [&](const Nodes& points, double share) {
    const std::pair<double, double> e = extremes(points);
    return Piece{ points, share, e.first / share, e.second / share };
  };
  std::vector<Piece> pieces{ make(nodes, 1.0) };
  std::vector<Nodes> children;
  for (int level = 0;; ++level)
  {
    double lo = pieces[0].Low, hi = pieces[0].High;
    for (const Piece& p : pieces)
      lo = std::min(lo, p.Low), hi = std::max(hi, p.High);
    const double ratio = BernsteinRatio(lo, hi);
    if (ratio >= target || level == depth)
      return ratio;
    // Refine the pieces that hold the bound down; the others keep their coefficients.
    std::vector<Piece> next;
    for (const Piece& p : pieces)
    {
      if (p.Low < target * hi)
      {
        children.clear();
        refine(p.Points, children);
        for (const Nodes& child : children)
          next.push_back(make(child, p.Share * childShare));
      }
      else
        next.push_back(p);
    }
    pieces.swap(next);
  }
}

} // namespace labelmesher

#endif
