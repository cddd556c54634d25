// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file JacobianBound.cxx
 * Validity of cubic Bézier triangles (dissertation section 4.2).
 *
 * With x̂ = v, ŷ = w and u = 1 - x̂ - ŷ, ∂/∂x̂ = ∂/∂v - ∂/∂u and ∂/∂ŷ = ∂/∂w - ∂/∂u,
 * and both directional derivatives are quadratic Bézier triangles:
 *   T_x̂ = 3 sum over |m| = 2 of B²_m (P_{m+e2} - P_{m+e1}),
 *   T_ŷ = 3 sum over |m| = 2 of B²_m (P_{m+e3} - P_{m+e1}),
 * so det J = T_x̂ × T_ŷ = 9 sum over m, n of B²_m B²_n (D1_m × D2_n) is a quartic
 * (Table 1). The diagonal terms D1_m × D2_m are twice the signed areas of the six
 * upward control triangles; the mixed terms are not controlled by those areas,
 * which is why Theorem 4.2.1 (section 4.2.2) needs the pair condition of
 * HasUntwistedControlNet: its proof assumes that de Casteljau steps keep the
 * control triangles counter-clockwise, which fails (TestBezierValidity has a net
 * with all nine control triangles positive and det J < 0 somewhere).
 */

#include "Curving/JacobianBound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace labelmesher
{

namespace
{

using Quartic = std::array<double, 15>;
using Barycentric = std::array<double, 3>;

Point2 Sub(const Point2& a, const Point2& b) { return { a[0] - b[0], a[1] - b[1] }; }

double Cross(const Point2& a, const Point2& b) { return a[0] * b[1] - a[1] * b[0]; }

/// The storage index of (i, j, k) for any degree: rows of constant i, k increasing.
constexpr int TriangleIndex(int j, int k) { return (j + k) * (j + k + 1) / 2 + k; }

constexpr int Corner0 = TriangleIndex(0, 0); // 400
constexpr int Corner1 = TriangleIndex(4, 0); // 040
constexpr int Corner2 = TriangleIndex(0, 4); // 004

const double Factorial[5] = { 1.0, 1.0, 2.0, 6.0, 24.0 };

double QuarticBasis(int i, int j, int k, double u, double v, double w)
{
  return 24.0 / (Factorial[i] * Factorial[j] * Factorial[k]) * std::pow(u, i) * std::pow(v, j) * std::pow(w, k);
}

/// The blossom of a quartic at four barycentric points: de Casteljau with a
/// different point at each level. In place: (i, j, k) only reads indices >= its own.
double Blossom(Quartic values, const std::array<Barycentric, 4>& points)
{
  for (int level = 0; level < 4; ++level)
  {
    const Barycentric& b = points[level];
    const int degree = 3 - level;
    for (int d = 0; d <= degree; ++d)
      for (int k = 0; k <= d; ++k)
      {
        const int j = d - k;
        values[TriangleIndex(j, k)] = b[0] * values[TriangleIndex(j, k)] + b[1] * values[TriangleIndex(j + 1, k)] +
          b[2] * values[TriangleIndex(j, k + 1)];
      }
  }
  return values[0];
}

/// Linear maps from a quartic's control values to those of its four midpoint
/// sub-triangles (change of basis by blossoming), and the Bernstein weights at the
/// Greville points (i, j, k) / 4 where the function is sampled.
struct SubdivisionTables
{
  double Child[4][15][15];
  double Greville[15][15];
};

SubdivisionTables BuildTables()
{
  const Barycentric e1{ 1, 0, 0 }, e2{ 0, 1, 0 }, e3{ 0, 0, 1 };
  const Barycentric m12{ 0.5, 0.5, 0 }, m13{ 0.5, 0, 0.5 }, m23{ 0, 0.5, 0.5 };
  // Corners of the children; the middle one keeps the orientation (x ↦ (1 - x) / 2).
  const Barycentric corners[4][3] = { { e1, m12, m13 }, { m12, e2, m23 }, { m13, m23, e3 }, { m23, m13, m12 } };
  SubdivisionTables tables{};
  for (int c = 0; c < 4; ++c)
    for (int j = 0; j <= 4; ++j)
      for (int k = 0; j + k <= 4; ++k)
      {
        const int i = 4 - j - k;
        std::array<Barycentric, 4> points;
        int n = 0;
        for (int r = 0; r < i; ++r)
          points[n++] = corners[c][0];
        for (int r = 0; r < j; ++r)
          points[n++] = corners[c][1];
        for (int r = 0; r < k; ++r)
          points[n++] = corners[c][2];
        for (int column = 0; column < 15; ++column)
        {
          Quartic unit{};
          unit[column] = 1.0;
          tables.Child[c][TriangleIndex(j, k)][column] = Blossom(unit, points);
        }
      }
  for (int j = 0; j <= 4; ++j)
    for (int k = 0; j + k <= 4; ++k)
      for (int jj = 0; jj <= 4; ++jj)
        for (int kk = 0; jj + kk <= 4; ++kk)
          tables.Greville[TriangleIndex(j, k)][TriangleIndex(jj, kk)] =
            QuarticBasis(4 - jj - kk, jj, kk, (4 - j - k) / 4.0, j / 4.0, k / 4.0);
  return tables;
}

const SubdivisionTables& Tables()
{
  static const SubdivisionTables tables = BuildTables();
  return tables;
}

/// Relative size of the rounding errors of subdivided control values.
constexpr double RoundingFloor = 1e-12;

/// det J below this fraction of the largest |control value| counts as zero.
constexpr double kDegenerateJacobian = 1e-9;

enum class CurveSign
{
  Positive,
  NonPositiveFound,
  Unknown
};

/// Algorithm 5, reporting why it did not prove positivity. Unlike the printed
/// algorithm it visits the right half even when the left one is undecided, so a
/// non-positive value there is still found.
CurveSign QuarticCurveSign(const std::array<double, 5>& p, int depth, double threshold = 0.0)
{
  if (*std::min_element(p.begin(), p.end()) > threshold)
    return CurveSign::Positive;
  if (p[0] <= threshold || p[4] <= threshold) // end values are attained
    return CurveSign::NonPositiveFound;
  if (depth <= 0)
    return CurveSign::Unknown;
  // de Casteljau at t = 1/2.
  const double p01 = 0.5 * (p[0] + p[1]), p12 = 0.5 * (p[1] + p[2]), p23 = 0.5 * (p[2] + p[3]),
               p34 = 0.5 * (p[3] + p[4]);
  const double p012 = 0.5 * (p01 + p12), p123 = 0.5 * (p12 + p23), p234 = 0.5 * (p23 + p34);
  const double p0123 = 0.5 * (p012 + p123), p1234 = 0.5 * (p123 + p234);
  const double p01234 = 0.5 * (p0123 + p1234);
  const CurveSign left = QuarticCurveSign({ p[0], p01, p012, p0123, p01234 }, depth - 1, threshold);
  if (left == CurveSign::NonPositiveFound)
    return left;
  const CurveSign right = QuarticCurveSign({ p01234, p1234, p234, p34, p[4] }, depth - 1, threshold);
  if (right == CurveSign::NonPositiveFound)
    return right;
  return left == CurveSign::Positive && right == CurveSign::Positive ? CurveSign::Positive : CurveSign::Unknown;
}

/// Recursive 4-way subdivision of the quartic det J. Leaves cover the triangle,
/// so their control values bound det J (convex hull property); corner values and
/// Greville samples are attained. A patch is a leaf once it can no longer lower
/// the bound by more than the tolerance and its sign question is settled.
class QuarticRefinement
{
public:
  /// signOnly: refine only until it is known whether min det J exceeds
  /// `threshold` (for ClassifyValidity).
  QuarticRefinement(double relativeTolerance, bool signOnly, double threshold)
    : Threshold(threshold)
    , RelativeTolerance(relativeTolerance)
    , SignOnly(signOnly)
  {
  }

  double Threshold;

  double Lower = std::numeric_limits<double>::infinity();
  double Upper = -std::numeric_limits<double>::infinity();
  double MinimumFound = std::numeric_limits<double>::infinity();
  double MaximumFound = -std::numeric_limits<double>::infinity();

  void Refine(const Quartic& values, int depth)
  {
    const SubdivisionTables& tables = Tables();
    int argmin = 0;
    double maximum = values[0];
    for (int c = 1; c < 15; ++c)
    {
      argmin = values[c] < values[argmin] ? c : argmin;
      maximum = std::max(maximum, values[c]);
    }
    const double minimum = values[argmin];
    Attain(values[Corner0]);
    Attain(values[Corner1]);
    Attain(values[Corner2]);
    if (!Settled(minimum))
    {
      // The smallest control value sits near the patch minimum: sampling there
      // lowers MinimumFound early, which lets more patches settle.
      double sample = 0.0;
      for (int c = 0; c < 15; ++c)
        sample += tables.Greville[argmin][c] * values[c];
      Attain(sample);
    }
    if (depth <= 0 || Settled(minimum))
    {
      Lower = std::min(Lower, minimum);
      Upper = std::max(Upper, maximum);
      return;
    }

    Quartic children[4];
    double childMinimum[4];
    for (int c = 0; c < 4; ++c)
    {
      childMinimum[c] = std::numeric_limits<double>::infinity();
      for (int row = 0; row < 15; ++row)
      {
        double sum = 0.0;
        for (int column = 0; column < 15; ++column)
          sum += tables.Child[c][row][column] * values[column];
        children[c][row] = sum;
        childMinimum[c] = std::min(childMinimum[c], sum);
      }
    }
    // Lowest first: finds small attained values sooner.
    int order[4] = { 0, 1, 2, 3 };
    std::sort(order, order + 4, [&](int a, int b) { return childMinimum[a] < childMinimum[b]; });
    for (int c : order)
      Refine(children[c], depth - 1);
  }

private:
  double RelativeTolerance;
  bool SignOnly;

  void Attain(double value)
  {
    MinimumFound = std::min(MinimumFound, value);
    MaximumFound = std::max(MaximumFound, value);
  }

  bool Settled(double patchMinimum) const
  {
    const bool signKnown = patchMinimum > Threshold || MinimumFound <= Threshold;
    if (SignOnly || !signKnown)
      return signKnown;
    // An attained value is at most Upper, so this tolerance never exceeds tolerance * |Upper|;
    // the floor stops a constant det J from being refined on rounding noise.
    const double tolerance = std::max(RelativeTolerance * std::max(MaximumFound, 0.0),
      RoundingFloor * std::max(std::abs(MinimumFound), std::abs(MaximumFound)));
    return patchMinimum >= MinimumFound - tolerance;
  }
};

Validity ResultOf(const QuarticRefinement& refinement)
{
  if (refinement.MinimumFound <= refinement.Threshold)
    return Validity::Invalid;
  return refinement.Lower > refinement.Threshold ? Validity::Valid : Validity::Undecided;
}

/// The smallest det J a valid cell may have: a Jacobian that vanishes to within
/// rounding of the control values (e.g. at a corner where two curved edges
/// leave along one tangent) is degenerate, not positive.
double DegenerateJacobian(const Quartic& values)
{
  double scale = 0.0;
  for (double v : values)
    scale = std::max(scale, std::abs(v));
  return kDegenerateJacobian * scale;
}

/// A proven lower bound of det J from the control net, or -inf when the net
/// test of HasUntwistedControlNet fails: det J >= 9 sum_m (B²_m)² D_m with every
/// D_m = D1_m × D2_m > 0, and sum_m (B²_m)² >= (sum_m B²_m)² / 6 = 1/6.
double ControlNetLowerBound(const CubicTriangle& triangle)
{
  const auto P = [&](int i, int j, int k) -> const Point2& {
    return triangle.ControlPoints[CubicControlPointIndex(i, j, k)];
  };
  Point2 d1[6], d2[6];
  double smallest = std::numeric_limits<double>::infinity();
  int m = 0;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; i + j <= 2; ++j, ++m)
    {
      const int k = 2 - i - j;
      d1[m] = Sub(P(i, j + 1, k), P(i + 1, j, k));
      d2[m] = Sub(P(i, j, k + 1), P(i + 1, j, k));
      const double area2 = Cross(d1[m], d2[m]);
      if (!(area2 > 0.0))
        return -std::numeric_limits<double>::infinity();
      smallest = std::min(smallest, area2);
    }
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b)
      if (!(Cross(d1[a], d2[b]) + Cross(d1[b], d2[a]) >= 0.0))
        return -std::numeric_limits<double>::infinity();
  return 1.5 * smallest;
}

} // namespace

int QuarticIndex(int i, int j, int k)
{
  if (i < 0 || j < 0 || k < 0 || i + j + k != 4)
    throw std::invalid_argument("QuarticIndex: multi-index must satisfy i + j + k = 4");
  return TriangleIndex(j, k);
}

QuarticTriangle JacobianControlValues(const CubicTriangle& triangle)
{
  const auto P = [&](int i, int j, int k) -> const Point2& {
    return triangle.ControlPoints[CubicControlPointIndex(i, j, k)];
  };
  // Section 4.2.1: T_x̂ = 3 (u² a1 + v² b1 + w² c1 + 2uw d1 + 2uv e1 + 2vw f1), T_ŷ likewise.
  const Point2 a1 = Sub(P(2, 1, 0), P(3, 0, 0)), a2 = Sub(P(2, 0, 1), P(3, 0, 0));
  const Point2 b1 = Sub(P(0, 3, 0), P(1, 2, 0)), b2 = Sub(P(0, 2, 1), P(1, 2, 0));
  const Point2 c1 = Sub(P(0, 1, 2), P(1, 0, 2)), c2 = Sub(P(0, 0, 3), P(1, 0, 2));
  const Point2 d1 = Sub(P(1, 1, 1), P(2, 0, 1)), d2 = Sub(P(1, 0, 2), P(2, 0, 1));
  const Point2 e1 = Sub(P(1, 2, 0), P(2, 1, 0)), e2 = Sub(P(1, 1, 1), P(2, 1, 0));
  const Point2 f1 = Sub(P(0, 2, 1), P(1, 1, 1)), f2 = Sub(P(0, 1, 2), P(1, 1, 1));
  // Symmetrised products: X(p, q) = p1 × q2 + q1 × p2.
  const auto X = [](const Point2& p1, const Point2& p2, const Point2& q1, const Point2& q2) {
    return Cross(p1, q2) + Cross(q1, p2);
  };
  // Table 1 (checked against an independent expansion: no correction needed).
  QuarticTriangle q;
  auto& v = q.Values;
  v[QuarticIndex(4, 0, 0)] = 9.0 * Cross(a1, a2);
  v[QuarticIndex(0, 4, 0)] = 9.0 * Cross(b1, b2);
  v[QuarticIndex(0, 0, 4)] = 9.0 * Cross(c1, c2);
  v[QuarticIndex(2, 2, 0)] = 1.5 * (X(a1, a2, b1, b2) + 4.0 * Cross(e1, e2));
  v[QuarticIndex(2, 0, 2)] = 1.5 * (X(a1, a2, c1, c2) + 4.0 * Cross(d1, d2));
  v[QuarticIndex(0, 2, 2)] = 1.5 * (X(b1, b2, c1, c2) + 4.0 * Cross(f1, f2));
  v[QuarticIndex(3, 0, 1)] = 4.5 * X(a1, a2, d1, d2);
  v[QuarticIndex(3, 1, 0)] = 4.5 * X(a1, a2, e1, e2);
  v[QuarticIndex(1, 3, 0)] = 4.5 * X(b1, b2, e1, e2);
  v[QuarticIndex(0, 3, 1)] = 4.5 * X(b1, b2, f1, f2);
  v[QuarticIndex(1, 0, 3)] = 4.5 * X(c1, c2, d1, d2);
  v[QuarticIndex(0, 1, 3)] = 4.5 * X(c1, c2, f1, f2);
  v[QuarticIndex(2, 1, 1)] = 1.5 * (X(a1, a2, f1, f2) + 2.0 * X(d1, d2, e1, e2));
  v[QuarticIndex(1, 2, 1)] = 1.5 * (X(b1, b2, d1, d2) + 2.0 * X(e1, e2, f1, f2));
  v[QuarticIndex(1, 1, 2)] = 1.5 * (X(c1, c2, e1, e2) + 2.0 * X(d1, d2, f1, f2));
  return q;
}

double EvaluateJacobian(const CubicTriangle& triangle, double u, double v, double w)
{
  // Homogeneous partial derivatives ∂T/∂u = 3 sum over |m| = 2 of B²_m P_{m+e1}, etc.
  const double pu[3] = { 1.0, u, u * u }, pv[3] = { 1.0, v, v * v }, pw[3] = { 1.0, w, w * w };
  Point2 du{ 0, 0 }, dv{ 0, 0 }, dw{ 0, 0 };
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; i + j <= 2; ++j)
    {
      const int k = 2 - i - j;
      const double basis = 2.0 / (Factorial[i] * Factorial[j] * Factorial[k]) * pu[i] * pv[j] * pw[k];
      const Point2& pi = triangle.ControlPoints[CubicControlPointIndex(i + 1, j, k)];
      const Point2& pj = triangle.ControlPoints[CubicControlPointIndex(i, j + 1, k)];
      const Point2& pk = triangle.ControlPoints[CubicControlPointIndex(i, j, k + 1)];
      for (int d = 0; d < 2; ++d)
      {
        du[d] += 3.0 * basis * pi[d];
        dv[d] += 3.0 * basis * pj[d];
        dw[d] += 3.0 * basis * pk[d];
      }
    }
  return Cross(Sub(dv, du), Sub(dw, du));
}

double EvaluateQuartic(const QuarticTriangle& quartic, double u, double v, double w)
{
  double sum = 0.0;
  for (int j = 0; j <= 4; ++j)
    for (int k = 0; j + k <= 4; ++k)
      sum += QuarticBasis(4 - j - k, j, k, u, v, w) * quartic.Values[TriangleIndex(j, k)];
  return sum;
}

bool IsQuarticCurvePositive(const std::array<double, 5>& controlValues, int maximumDepth)
{
  return QuarticCurveSign(controlValues, maximumDepth) == CurveSign::Positive;
}

bool HasUntwistedControlNet(const CubicTriangle& triangle)
{
  // Theorem 4.2.1 as printed (six positive upward triangles) is not sufficient:
  // det J = 9 sum over m, n of B²_m B²_n (D1_m × D2_n) also has mixed terms. When the
  // diagonal terms (twice the triangle areas) are positive and every mixed term
  // D1_m × D2_n + D1_n × D2_m is non-negative, det J >= 9 sum of (B²_m)² D1_m × D2_m > 0.
  return ControlNetLowerBound(triangle) > 0.0;
}

JacobianBounds BoundJacobian(const CubicTriangle& triangle, const JacobianBoundOptions& options)
{
  const QuarticTriangle quartic = JacobianControlValues(triangle);
  QuarticRefinement refinement(options.RelativeTolerance, false, DegenerateJacobian(quartic.Values));
  refinement.Refine(quartic.Values, options.MaximumDepth);
  JacobianBounds bounds;
  bounds.Lower = refinement.Lower;
  bounds.Upper = refinement.Upper;
  bounds.MinimumFound = refinement.MinimumFound;
  bounds.Result = ResultOf(refinement);
  return bounds;
}

Validity ClassifyValidity(const CubicTriangle& triangle, const JacobianBoundOptions& options)
{
  const QuarticTriangle quartic = JacobianControlValues(triangle);
  const Quartic& p = quartic.Values;
  const double threshold = DegenerateJacobian(p);
  if (ControlNetLowerBound(triangle) > threshold)
    return Validity::Valid;
  if (*std::min_element(p.begin(), p.end()) > threshold)
    return Validity::Valid;
  if (p[Corner0] <= threshold || p[Corner1] <= threshold || p[Corner2] <= threshold)
    return Validity::Invalid;
  // Algorithm 5 on the boundary curves can only find an invalid cell: positive
  // boundary curves do not bound the interior control values P211, P121, P112.
  const std::array<double, 5> curves[3] = {
    { p[QuarticIndex(4, 0, 0)], p[QuarticIndex(3, 1, 0)], p[QuarticIndex(2, 2, 0)], p[QuarticIndex(1, 3, 0)],
      p[QuarticIndex(0, 4, 0)] },
    { p[QuarticIndex(0, 4, 0)], p[QuarticIndex(0, 3, 1)], p[QuarticIndex(0, 2, 2)], p[QuarticIndex(0, 1, 3)],
      p[QuarticIndex(0, 0, 4)] },
    { p[QuarticIndex(0, 0, 4)], p[QuarticIndex(1, 0, 3)], p[QuarticIndex(2, 0, 2)], p[QuarticIndex(3, 0, 1)],
      p[QuarticIndex(4, 0, 0)] }
  };
  for (const auto& curve : curves)
    if (QuarticCurveSign(curve, options.MaximumDepth, threshold) == CurveSign::NonPositiveFound)
      return Validity::Invalid;
  QuarticRefinement refinement(0.0, true, threshold);
  refinement.Refine(p, options.MaximumDepth);
  return ResultOf(refinement);
}

} // namespace labelmesher
