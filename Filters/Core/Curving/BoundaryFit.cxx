// SPDX-License-Identifier: GPL-2.0-or-later
// Least-squares C1 handles of a chain's cubic path against the image's boundary samples.
#include "Curving/BoundaryFit.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace labelmesher
{
namespace
{

double Distance(const Point2& a, const Point2& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

/// The chain seen as segments: their end vertices and chord lengths.
struct ChainGeometry
{
  const std::vector<Point2>& Vertices;
  bool Closed;
  std::size_t Count() const { return Closed ? Vertices.size() : Vertices.size() - 1; }
  std::size_t Start(std::size_t s) const { return s; }
  std::size_t End(std::size_t s) const { return (s + 1) % Vertices.size(); }
  double Chord(std::size_t s) const { return Distance(Vertices[Start(s)], Vertices[End(s)]); }
};

/// Figure 17a's handle at vertex i per unit chord: t (P_{i+1} − P_{i−1}) / (|P_{i−1}P_i| + |P_iP_{i+1}|),
/// the end vertex of an open chain standing in for its missing neighbour.
Point2 TangentHandle(const std::vector<Point2>& v, bool closed, std::size_t i, double tension)
{
  const std::size_t n = v.size();
  const Point2& previous = i > 0 ? v[i - 1] : (closed ? v[n - 1] : v[0]);
  const Point2& next = i + 1 < n ? v[i + 1] : (closed ? v[0] : v[n - 1]);
  const double around = Distance(previous, v[i]) + Distance(v[i], next);
  if (around <= 0.0)
    return { 0.0, 0.0 };
  return { tension * (next[0] - previous[0]) / around, tension * (next[1] - previous[1]) / around };
}

struct Bernstein
{
  double B0, B1, B2, B3;
  explicit Bernstein(double t)
  {
    const double u = 1.0 - t;
    B0 = u * u * u;
    B1 = 3.0 * u * u * t;
    B2 = 3.0 * u * t * t;
    B3 = t * t * t;
  }
};

/// The segment's control points for handles m.
std::array<Point2, 4> SegmentControlPoints(
  const ChainGeometry& chain, const std::vector<Point2>& m, std::size_t s)
{
  const Point2& a = chain.Vertices[chain.Start(s)];
  const Point2& b = chain.Vertices[chain.End(s)];
  const double c = chain.Chord(s);
  const Point2& ma = m[chain.Start(s)];
  const Point2& mb = m[chain.End(s)];
  return { a, Point2{ a[0] + c * ma[0], a[1] + c * ma[1] }, Point2{ b[0] - c * mb[0], b[1] - c * mb[1] }, b };
}

/// Newton steps on |B(t) − q|² from t, kept in [0, 1].
double Reproject(const std::array<Point2, 4>& p, const Point2& q, double t)
{
  for (int step = 0; step < 3; ++step)
  {
    const double u = 1.0 - t;
    Point2 value, first, second;
    for (int a = 0; a < 2; ++a)
    {
      value[a] = u * u * u * p[0][a] + 3 * u * u * t * p[1][a] + 3 * u * t * t * p[2][a] + t * t * t * p[3][a];
      first[a] = 3 * (u * u * (p[1][a] - p[0][a]) + 2 * u * t * (p[2][a] - p[1][a]) + t * t * (p[3][a] - p[2][a]));
      second[a] = 6 * (u * (p[2][a] - 2 * p[1][a] + p[0][a]) + t * (p[3][a] - 2 * p[2][a] + p[1][a]));
    }
    const double dx = value[0] - q[0], dy = value[1] - q[1];
    const double gradient = dx * first[0] + dy * first[1];
    const double hessian = first[0] * first[0] + first[1] * first[1] + dx * second[0] + dy * second[1];
    if (!(hessian > 0.0))
      break;
    t = std::clamp(t - gradient / hessian, 0.0, 1.0);
  }
  return t;
}

/// One least-squares solve for the handles with the samples at `parameters`.
std::vector<Point2> SolveHandles(const ChainGeometry& chain, const std::vector<BoundarySample>& samples,
  const std::vector<double>& parameters, const std::vector<Point2>& prior, double regularisation)
{
  using Index = Eigen::Index;
  const std::size_t n = chain.Vertices.size();
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::Matrix<double, Eigen::Dynamic, 2> rhs = Eigen::Matrix<double, Eigen::Dynamic, 2>::Zero(static_cast<Index>(n), 2);
  // The pull towards the prior, scaled by the vertex's chords so that it is a
  // squared length in mesh units like the samples' residuals.
  for (std::size_t i = 0; i < n; ++i)
  {
    double chord = 0.0;
    int count = 0;
    for (std::size_t s : { (i + n - 1) % n, i })
    {
      if (s < chain.Count() && (chain.Start(s) == i || chain.End(s) == i))
      {
        chord += chain.Chord(s);
        ++count;
      }
    }
    chord = count > 0 ? chord / count : 1.0;
    const double w = regularisation * chord * chord;
    entries.emplace_back(static_cast<Index>(i), static_cast<Index>(i), w);
    rhs(static_cast<Index>(i), 0) += w * prior[i][0];
    rhs(static_cast<Index>(i), 1) += w * prior[i][1];
  }
  for (std::size_t k = 0; k < samples.size(); ++k)
  {
    const std::size_t s = samples[k].Segment;
    const std::size_t i = chain.Start(s), j = chain.End(s);
    const Point2& a = chain.Vertices[i];
    const Point2& b = chain.Vertices[j];
    const double c = chain.Chord(s);
    const Bernstein w(parameters[k]);
    // B(t) = (B0 + B1) a + (B2 + B3) b + c B1 m_i − c B2 m_j.
    const double alpha = c * w.B1, beta = -c * w.B2;
    const Point2 r{ samples[k].Point[0] - (w.B0 + w.B1) * a[0] - (w.B2 + w.B3) * b[0],
      samples[k].Point[1] - (w.B0 + w.B1) * a[1] - (w.B2 + w.B3) * b[1] };
    const Index ii = static_cast<Index>(i), jj = static_cast<Index>(j);
    entries.emplace_back(ii, ii, alpha * alpha);
    entries.emplace_back(jj, jj, beta * beta);
    entries.emplace_back(ii, jj, alpha * beta);
    entries.emplace_back(jj, ii, alpha * beta);
    for (int d = 0; d < 2; ++d)
    {
      rhs(ii, d) += alpha * r[d];
      rhs(jj, d) += beta * r[d];
    }
  }
  Eigen::SparseMatrix<double> matrix(static_cast<Index>(n), static_cast<Index>(n));
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
  if (solver.info() != Eigen::Success)
    throw std::runtime_error("FitChain: the least-squares system could not be factorised");
  const Eigen::Matrix<double, Eigen::Dynamic, 2> solution = solver.solve(rhs);
  std::vector<Point2> m(n);
  for (std::size_t i = 0; i < n; ++i)
    m[i] = { solution(static_cast<Index>(i), 0), solution(static_cast<Index>(i), 1) };
  return m;
}

/// `h` turned by the smallest angle that leaves it at least 5 degrees inside
/// the forward half-plane of each chord at vertex i; `fallback` when no
/// direction is (a reversal).
Point2 ForwardHandle(const ChainGeometry& chain, std::size_t i, const Point2& h, const Point2& fallback)
{
  constexpr double kMargin = 5.0 * 3.141592653589793 / 180.0;
  constexpr double kQuarter = 0.5 * 3.141592653589793;
  const std::size_t n = chain.Vertices.size();
  std::vector<double> chords; // directions of the chords, each towards the next vertex
  for (std::size_t s : { (i + n - 1) % n, i })
  {
    if (s >= chain.Count() || (chain.Start(s) != i && chain.End(s) != i) || !(chain.Chord(s) > 0.0))
      continue;
    const Point2& a = chain.Vertices[chain.Start(s)];
    const Point2& b = chain.Vertices[chain.End(s)];
    chords.push_back(std::atan2(b[1] - a[1], b[0] - a[0]));
  }
  const double length = std::hypot(h[0], h[1]);
  if (chords.empty() || !(length > 0.0))
    return h;
  auto gap = [](double x, double y) { return std::abs(std::remainder(x - y, 2.0 * 3.141592653589793)); };
  auto forward = [&](double angle) {
    for (double c : chords)
      if (gap(angle, c) > kQuarter - kMargin + 1e-12)
        return false;
    return true;
  };
  const double angle = std::atan2(h[1], h[0]);
  if (forward(angle))
    return h;
  double best = angle, turn = HUGE_VAL;
  for (double c : chords)
    for (double side : { -1.0, 1.0 })
    {
      const double candidate = c + side * (kQuarter - kMargin);
      if (forward(candidate) && gap(candidate, angle) < turn)
      {
        turn = gap(candidate, angle);
        best = candidate;
      }
    }
  if (turn == HUGE_VAL)
    return fallback;
  return { length * std::cos(best), length * std::sin(best) };
}

} // namespace

std::vector<std::array<Point2, 2>> FitChain(const std::vector<Point2>& vertices, bool closed,
  const std::vector<BoundarySample>& samples, const FitOptions& options)
{
  // A closed chain of fewer than three vertices cannot bend (and a triangle mesh does not make one).
  if (vertices.size() < 2 || (closed && vertices.size() < 3))
    return SmoothChain(vertices, closed, { Smoothness::C1, 0.0 });
  const ChainGeometry chain{ vertices, closed };
  std::vector<Point2> prior(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i)
    prior[i] = TangentHandle(vertices, closed, i, options.Tension);

  std::vector<Point2> m = prior;
  if (!samples.empty())
  {
    std::vector<double> parameters(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k)
      parameters[k] = samples[k].Parameter;
    for (int round = 0; round <= options.ParameterCorrections; ++round)
    {
      m = SolveHandles(chain, samples, parameters, prior, options.Regularisation);
      for (std::size_t k = 0; round < options.ParameterCorrections && k < samples.size(); ++k)
        parameters[k] = Reproject(SegmentControlPoints(chain, m, samples[k].Segment), samples[k].Point, parameters[k]);
    }
  }
  // A handle pointing backwards along a chord at its vertex makes the cubic
  // loop or cross its neighbour: it is turned, as little as it takes, to make
  // at least 5 degrees with the perpendiculars of both chords. A handle longer
  // than half a chord can make the cubic loop too; shortening it along its own
  // direction keeps the joint's tangent. (Loops and crossings that remain are
  // the curver's to find: CurveCrossings.h.)
  for (std::size_t i = 0; i < vertices.size(); ++i)
    m[i] = ForwardHandle(chain, i, m[i], prior[i]);
  for (Point2& h : m)
  {
    const double length = std::hypot(h[0], h[1]);
    if (length > 0.5)
      h = { h[0] * 0.5 / length, h[1] * 0.5 / length };
  }
  std::vector<std::array<Point2, 2>> out(chain.Count());
  for (std::size_t s = 0; s < chain.Count(); ++s)
  {
    const auto p = SegmentControlPoints(chain, m, s);
    out[s] = { p[1], p[2] };
  }
  return out;
}

std::vector<std::array<Point2, 2>> FitQuadraticSegments(const std::vector<Point2>& vertices, bool closed,
  const std::vector<BoundarySample>& samples, const std::vector<std::array<Point2, 2>>& initial,
  const FitOptions& options)
{
  const ChainGeometry chain{ vertices, closed };
  std::vector<std::array<Point2, 2>> out(initial.size());
  std::vector<std::vector<const BoundarySample*>> bySegment(initial.size());
  for (const BoundarySample& sample : samples)
    if (sample.Segment < bySegment.size())
      bySegment[sample.Segment].push_back(&sample);
  for (std::size_t s = 0; s < initial.size(); ++s)
  {
    const Point2& a = vertices[chain.Start(s)];
    const Point2& b = vertices[chain.End(s)];
    const Point2 prior = NearestQuadraticControl(a, initial[s][0], initial[s][1], b);
    const double c = chain.Chord(s);
    Point2 q = prior;
    std::vector<double> t;
    for (const BoundarySample* sample : bySegment[s])
      t.push_back(sample->Parameter);
    for (int round = 0; !t.empty() && round <= options.ParameterCorrections; ++round)
    {
      // Normal equations of the one unknown q (both coordinates alike), plus the pull to the prior:
      // a squared length like the samples' residuals (as FitChain's pull per control point moved).
      const double pull = options.Regularisation;
      double weight = pull;
      Point2 sum{ pull * prior[0], pull * prior[1] };
      for (std::size_t k = 0; k < t.size(); ++k)
      {
        const double u = 1.0 - t[k], w = 2.0 * t[k] * u;
        for (int d = 0; d < 2; ++d)
          sum[d] += w * (bySegment[s][k]->Point[d] - u * u * a[d] - t[k] * t[k] * b[d]);
        weight += w * w;
      }
      q = { sum[0] / weight, sum[1] / weight };
      if (round == options.ParameterCorrections)
        break;
      const std::array<Point2, 2> inner = ElevateQuadratic(a, q, b);
      for (std::size_t k = 0; k < t.size(); ++k)
        t[k] = Reproject({ a, inner[0], inner[1], b }, bySegment[s][k]->Point, t[k]);
    }
    // As FitChain shortens handles beyond half a chord (a cubic may loop), q is pulled towards
    // the chord's midpoint until both elevated handles, 2/3 |q - a| and 2/3 |q - b|, are at most
    // that: the curve then bulges by at most 3/8 of its chord.
    const Point2 middle{ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]) };
    for (int k = 0; k < 64 && std::max(Distance(q, a), Distance(q, b)) > 0.75 * c; ++k)
      q = { middle[0] + 0.9 * (q[0] - middle[0]), middle[1] + 0.9 * (q[1] - middle[1]) };
    out[s] = ElevateQuadratic(a, q, b);
  }
  return out;
}

} // namespace labelmesher
