// SPDX-License-Identifier: GPL-2.0-or-later
// C1 and C2 cubic Bézier paths through a chain's vertices (section 4.1, Figure 17).
#include "Curving/SmoothBoundary.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cmath>
#include <stdexcept>

namespace labelmesher
{
namespace
{
Point2 Add(const Point2& a, const Point2& b) { return { a[0] + b[0], a[1] + b[1] }; }
Point2 Sub(const Point2& a, const Point2& b) { return { a[0] - b[0], a[1] - b[1] }; }
Point2 Scale(const Point2& a, double s) { return { a[0] * s, a[1] * s }; }
double Distance(const Point2& a, const Point2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

/// Control points at 1/3 and 2/3 of every segment: the straight path.
std::vector<std::array<Point2, 2>> StraightPath(const std::vector<Point2>& vertices, bool closed)
{
  const std::size_t n = vertices.size();
  const std::size_t segments = closed ? n : (n > 0 ? n - 1 : 0);
  std::vector<std::array<Point2, 2>> out(segments);
  for (std::size_t s = 0; s < segments; ++s)
  {
    const Point2& a = vertices[s];
    const Point2& b = vertices[(s + 1) % n];
    out[s] = { Add(a, Scale(Sub(b, a), 1.0 / 3.0)), Add(a, Scale(Sub(b, a), 2.0 / 3.0)) };
  }
  return out;
}

/// Figure 17a. The tangent at P_i is P_{i+1} − P_{i−1}; the handle towards a
/// neighbour is that tangent scaled by t and by the share of the neighbour's
/// chord in |P_{i−1}P_i| + |P_iP_{i+1}| (the translated segment through Q_i).
/// At the ends of an open chain the end vertex stands in for its missing
/// neighbour, which leaves the handle on the end chord: P_0 + t·(P_1 − P_0).
std::vector<std::array<Point2, 2>> TangentPath(const std::vector<Point2>& vertices, bool closed, double tension)
{
  const std::size_t n = vertices.size();
  auto previous = [&](std::size_t i) -> const Point2& {
    return i > 0 ? vertices[i - 1] : (closed ? vertices[n - 1] : vertices[0]);
  };
  auto next = [&](std::size_t i) -> const Point2& {
    return i + 1 < n ? vertices[i + 1] : (closed ? vertices[0] : vertices[n - 1]);
  };
  // The handle at vertex i along the tangent, for a chord of length `chord`.
  auto handle = [&](std::size_t i, double chord) {
    const double around = Distance(previous(i), vertices[i]) + Distance(vertices[i], next(i));
    if (around <= 0.0)
      return Point2{ 0.0, 0.0 }; // repeated vertices: no tangent, a straight handle
    return Scale(Sub(next(i), previous(i)), tension * chord / around);
  };
  const std::size_t segments = closed ? n : n - 1;
  std::vector<std::array<Point2, 2>> out(segments);
  for (std::size_t s = 0; s < segments; ++s)
  {
    const std::size_t e = (s + 1) % n;
    const double chord = Distance(vertices[s], vertices[e]);
    out[s] = { Add(vertices[s], handle(s, chord)), Sub(vertices[e], handle(e, chord)) };
  }
  return out;
}

/// Figure 17c: the B-spline points B of the interpolating cubic spline
/// (uniform parameter), 6 S_i = B_{i−1} + 4 B_i + B_{i+1}; periodic when
/// closed, B_0 = S_0 and B_n = S_n (zero second derivative) when open. The
/// matrix is tridiagonal (cyclic when closed), symmetric and strictly
/// diagonally dominant, so LDLT needs no pivoting and fills in O(n).
std::vector<Point2> BSplinePoints(const std::vector<Point2>& vertices, bool closed)
{
  const std::size_t n = vertices.size();
  std::vector<Point2> b(vertices);
  // Unknowns: all B when closed, the inner ones when open.
  const std::size_t first = closed ? 0 : 1;
  const std::size_t count = closed ? n : n - 2;
  using Index = Eigen::Index;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * count);
  Eigen::Matrix<double, Eigen::Dynamic, 2> rhs(static_cast<Index>(count), 2);
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::size_t i = first + k;
    const Index row = static_cast<Index>(k);
    Point2 r = Scale(vertices[i], 6.0);
    entries.emplace_back(row, row, 4.0);
    if (closed)
    {
      entries.emplace_back(row, static_cast<Index>((k + 1) % n), 1.0);
      entries.emplace_back(row, static_cast<Index>((k + n - 1) % n), 1.0);
    }
    else
    {
      // Known end points move to the right-hand side.
      if (k > 0)
        entries.emplace_back(row, row - 1, 1.0);
      else
        r = Sub(r, vertices[0]);
      if (k + 1 < count)
        entries.emplace_back(row, row + 1, 1.0);
      else
        r = Sub(r, vertices[n - 1]);
    }
    rhs(row, 0) = r[0];
    rhs(row, 1) = r[1];
  }
  Eigen::SparseMatrix<double> matrix(static_cast<Index>(count), static_cast<Index>(count));
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("SmoothChain: the B-spline system could not be factorised");
  const Eigen::Matrix<double, Eigen::Dynamic, 2> solution = solver.solve(rhs);
  for (std::size_t k = 0; k < count; ++k)
    b[first + k] = { solution(static_cast<Index>(k), 0), solution(static_cast<Index>(k), 1) };
  return b;
}

/// Each segment's inner control points at 1/3 and 2/3 of B_i B_{i+1}, which
/// makes every joint S_i the midpoint of an A-frame (Figure 17b).
std::vector<std::array<Point2, 2>> SplinePath(const std::vector<Point2>& vertices, bool closed)
{
  const std::vector<Point2> b = BSplinePoints(vertices, closed);
  const std::size_t n = vertices.size();
  const std::size_t segments = closed ? n : n - 1;
  std::vector<std::array<Point2, 2>> out(segments);
  for (std::size_t s = 0; s < segments; ++s)
  {
    const Point2& p = b[s];
    const Point2& q = b[(s + 1) % n];
    out[s] = { Add(p, Scale(Sub(q, p), 1.0 / 3.0)), Add(p, Scale(Sub(q, p), 2.0 / 3.0)) };
  }
  return out;
}

} // namespace

std::vector<std::array<Point2, 2>> SmoothChain(
  const std::vector<Point2>& vertices, bool closed, const SmoothingOptions& options)
{
  // Too short to bend: one open segment, or a closed chain of at most two
  // vertices (which a triangle mesh does not produce).
  if (vertices.size() < 3)
    return StraightPath(vertices, closed);
  if (options.Continuity == Smoothness::C1)
    return TangentPath(vertices, closed, options.Tension);
  return SplinePath(vertices, closed);
}

} // namespace labelmesher
