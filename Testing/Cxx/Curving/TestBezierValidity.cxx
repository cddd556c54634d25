// SPDX-License-Identifier: GPL-2.0-or-later
// Validity of cubic Bézier triangles (dissertation section 4.2): the VTK control
// point order, Table 1 against the cubic's derivatives and finite differences,
// Algorithm 5 on quartics with known minima, and the control-net test and the
// subdivision bounds against dense sampling of det J on random control nets.
#include "Curving/CubicTriangle.h"
#include "Curving/JacobianBound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace labelmesher;

namespace
{

double Area2(const Point2& a, const Point2& b, const Point2& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

const Point2& At(const CubicTriangle& t, int i, int j, int k)
{
  return t.ControlPoints[CubicControlPointIndex(i, j, k)];
}

Point2 RandomPoint(std::mt19937& rng)
{
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  return { coordinate(rng), coordinate(rng) };
}

/// A positively oriented, not too flat random triangle.
CubicTriangle RandomStraightTriangle(std::mt19937& rng)
{
  for (;;)
  {
    const Point2 a = RandomPoint(rng), b = RandomPoint(rng), c = RandomPoint(rng);
    const double area2 = Area2(a, b, c);
    const double longest = std::max({ std::hypot(b[0] - a[0], b[1] - a[1]), std::hypot(c[0] - b[0], c[1] - b[1]),
      std::hypot(a[0] - c[0], a[1] - c[1]) });
    if (std::abs(area2) > 0.3 * longest * longest) // no angle much below 20 degrees
      return area2 > 0 ? StraightCubicTriangle(a, b, c) : StraightCubicTriangle(a, c, b);
  }
}

/// A straight triangle whose edge and interior control points are moved by
/// amplitude times its size: all seven points, one edge (as when a boundary edge
/// is curved), or the interior point only.
CubicTriangle RandomCurvedTriangle(std::mt19937& rng, double amplitude)
{
  CubicTriangle t = RandomStraightTriangle(rng);
  const Point2* p = t.ControlPoints.data();
  const double size = std::sqrt(Area2(p[0], p[1], p[2]));
  std::normal_distribution<double> offset(0.0, amplitude * size);
  std::vector<int> moved;
  switch (std::uniform_int_distribution<int>(0, 2)(rng))
  {
    case 0:
      moved = { 3, 4, 5, 6, 7, 8, 9 };
      break;
    case 1:
    {
      const int edge = std::uniform_int_distribution<int>(0, 2)(rng);
      moved = { 3 + 2 * edge, 4 + 2 * edge };
      break;
    }
    default:
      moved = { 9 };
  }
  for (int index : moved)
    for (int d = 0; d < 2; ++d)
      t.ControlPoints[index][d] += offset(rng);
  return t;
}

const double Amplitudes[] = { 0.03, 0.1, 0.2, 0.35, 0.6 };

/// A random point (u, v, w) of the triangle.
std::array<double, 3> RandomBarycentric(std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double v = unit(rng), w = unit(rng);
  if (v + w > 1.0)
  {
    v = 1.0 - v;
    w = 1.0 - w;
  }
  return { 1.0 - v - w, v, w };
}

struct Sampling
{
  double Minimum = INFINITY;
  double Maximum = -INFINITY;
  /// Smallest det J after refining every local minimum of the grid by pattern
  /// search: an attained value, and in practice the minimum itself.
  double RefinedMinimum = INFINITY;
};

/// det J on the barycentric grid (a, b, c) / n, a + b + c = n.
Sampling SampleJacobian(const CubicTriangle& t, int n = 60)
{
  std::vector<double> grid((n + 1) * (n + 1), INFINITY);
  Sampling s;
  for (int b = 0; b <= n; ++b)
    for (int c = 0; b + c <= n; ++c)
    {
      const double value = EvaluateJacobian(t, double(n - b - c) / n, double(b) / n, double(c) / n);
      grid[b * (n + 1) + c] = value;
      s.Minimum = std::min(s.Minimum, value);
      s.Maximum = std::max(s.Maximum, value);
    }
  // Lattice directions: the triangle's edges are along them, so the search can slide along an edge.
  const int directions[6][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 }, { 1, -1 }, { -1, 1 } };
  const auto inside = [](double v, double w) { return v >= 0.0 && w >= 0.0 && v + w <= 1.0; };
  // Grid local minima, lowest first (a flat det J makes many: keep a few).
  std::vector<std::pair<double, int>> starts;
  for (int b = 0; b <= n; ++b)
    for (int c = 0; b + c <= n; ++c)
    {
      const double value = grid[b * (n + 1) + c];
      bool localMinimum = true;
      for (const auto& d : directions)
      {
        const int bb = b + d[0], cc = c + d[1];
        if (bb >= 0 && cc >= 0 && bb + cc <= n && grid[bb * (n + 1) + cc] < value)
          localMinimum = false;
      }
      if (localMinimum)
        starts.push_back({ value, b * (n + 1) + c });
    }
  std::sort(starts.begin(), starts.end());
  starts.resize(std::min<std::size_t>(starts.size(), 6));
  for (const auto& start : starts)
  {
    // Compass search: grow the step after a success, halve it after a failure.
    double v = double(start.second / (n + 1)) / n, w = double(start.second % (n + 1)) / n, best = start.first;
    double step = 1.0 / n;
    for (int evaluations = 0; step > 1e-10 && evaluations < 3000;)
    {
      bool moved = false;
      for (const auto& d : directions)
      {
        const double vv = v + step * d[0], ww = w + step * d[1];
        if (!inside(vv, ww))
          continue;
        const double trial = EvaluateJacobian(t, 1.0 - vv - ww, vv, ww);
        ++evaluations;
        if (trial < best)
        {
          best = trial;
          v = vv;
          w = ww;
          moved = true;
          break;
        }
      }
      step = moved ? std::min(2.0 * step, 1.0 / n) : 0.5 * step;
    }
    s.RefinedMinimum = std::min(s.RefinedMinimum, best);
  }
  return s;
}

/// The conditions of Theorem 4.2.1 as printed: the six upward control triangles
/// (P_{i+1,j,k}, P_{i,j+1,k}, P_{i,j,k+1}), i + j + k = 2, are not inverted.
bool SixUpwardTrianglesPositive(const CubicTriangle& t)
{
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; i + j <= 2; ++j)
    {
      const int k = 2 - i - j;
      if (!(Area2(At(t, i + 1, j, k), At(t, i, j + 1, k), At(t, i, j, k + 1)) > 0))
        return false;
    }
  return true;
}

/// The three downward control triangles (P_{m+e1+e2}, P_{m+e2+e3}, P_{m+e1+e3}), |m| = 1.
bool ThreeDownwardTrianglesPositive(const CubicTriangle& t)
{
  const int m[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  for (const auto& e : m)
    if (!(Area2(At(t, e[0] + 1, e[1] + 1, e[2]), At(t, e[0], e[1] + 1, e[2] + 1), At(t, e[0] + 1, e[1], e[2] + 1)) >
          0))
      return false;
  return true;
}

/// Bernstein coefficients of the quartic with power-basis coefficients alpha:
/// beta_k = sum over i <= k of C(k, i) / C(4, i) alpha_i.
std::array<double, 5> PowerToBernstein(const std::array<double, 5>& alpha)
{
  const double binomial[5][5] = { { 1 }, { 1, 1 }, { 1, 2, 1 }, { 1, 3, 3, 1 }, { 1, 4, 6, 4, 1 } };
  std::array<double, 5> beta{};
  for (int k = 0; k <= 4; ++k)
    for (int i = 0; i <= k; ++i)
      beta[k] += binomial[k][i] / binomial[4][i] * alpha[i];
  return beta;
}

double EvaluateBernstein(const std::array<double, 5>& beta, double t)
{
  const double binomial[5] = { 1, 4, 6, 4, 1 };
  double sum = 0.0;
  for (int k = 0; k <= 4; ++k)
    sum += binomial[k] * std::pow(t, k) * std::pow(1.0 - t, 4 - k) * beta[k];
  return sum;
}

/// (t - a)² (t - b)² + c in the power basis: its minimum on [0, 1] is c when a, b are in [0, 1].
std::array<double, 5> DoubleRootsPlusConstant(double a, double b, double c)
{
  const double q[3] = { a * b, -(a + b), 1.0 }; // (t - a)(t - b)
  std::array<double, 5> alpha{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      alpha[i + j] += q[i] * q[j];
  alpha[0] += c;
  return alpha;
}

} // namespace

TEST(CubicTriangle, ControlPointIndexIsVtkBezierTriangleOrder)
{
  // VTK_BEZIER_TRIANGLE, degree 3 (checked against vtkBezierTriangle::EvaluateLocation).
  EXPECT_EQ(CubicControlPointIndex(3, 0, 0), 0);
  EXPECT_EQ(CubicControlPointIndex(0, 3, 0), 1);
  EXPECT_EQ(CubicControlPointIndex(0, 0, 3), 2);
  EXPECT_EQ(CubicControlPointIndex(2, 1, 0), 3);
  EXPECT_EQ(CubicControlPointIndex(1, 2, 0), 4);
  EXPECT_EQ(CubicControlPointIndex(0, 2, 1), 5);
  EXPECT_EQ(CubicControlPointIndex(0, 1, 2), 6);
  EXPECT_EQ(CubicControlPointIndex(1, 0, 2), 7);
  EXPECT_EQ(CubicControlPointIndex(2, 0, 1), 8);
  EXPECT_EQ(CubicControlPointIndex(1, 1, 1), 9);
  EXPECT_THROW(CubicControlPointIndex(2, 2, 0), std::invalid_argument);
  EXPECT_THROW(CubicControlPointIndex(4, -1, 0), std::invalid_argument);
}

TEST(CubicTriangle, EdgesAreTheCubicCurvesOfTheirControlPoints)
{
  // Edge 0→1 is the Bézier curve (0, 3, 4, 1), 1→2 is (1, 5, 6, 2), 2→0 is (2, 7, 8, 0).
  std::mt19937 rng(11);
  const int curves[3][4] = { { 0, 3, 4, 1 }, { 1, 5, 6, 2 }, { 2, 7, 8, 0 } };
  for (int trial = 0; trial < 20; ++trial)
  {
    CubicTriangle t;
    for (Point2& p : t.ControlPoints)
      p = RandomPoint(rng);
    for (int edge = 0; edge < 3; ++edge)
      for (double s : { 0.0, 0.2, 0.5, 0.9, 1.0 })
      {
        double barycentric[3] = { 0, 0, 0 };
        barycentric[edge] = 1.0 - s;
        barycentric[(edge + 1) % 3] = s;
        const Point2 p = EvaluateCubicTriangle(t, barycentric[0], barycentric[1], barycentric[2]);
        const double rest = 1 - s;
        const double weight[4] = { rest * rest * rest, 3 * s * rest * rest, 3 * s * s * rest, s * s * s };
        for (int d = 0; d < 2; ++d)
        {
          double expected = 0.0;
          for (int r = 0; r < 4; ++r)
            expected += weight[r] * t.ControlPoints[curves[edge][r]][d];
          EXPECT_NEAR(p[d], expected, 1e-14);
        }
      }
  }
}

TEST(CubicTriangle, StraightTriangleIsTheAffineMap)
{
  std::mt19937 rng(12);
  for (int trial = 0; trial < 100; ++trial)
  {
    const Point2 a = RandomPoint(rng), b = RandomPoint(rng), c = RandomPoint(rng);
    const CubicTriangle t = StraightCubicTriangle(a, b, c);
    const auto [u, v, w] = RandomBarycentric(rng);
    const Point2 p = EvaluateCubicTriangle(t, u, v, w);
    for (int d = 0; d < 2; ++d)
      EXPECT_NEAR(p[d], u * a[d] + v * b[d] + w * c[d], 1e-14);
  }
}

TEST(CubicTriangle, CornerAnglesOfAStraightCellAreItsInteriorAngles)
{
  // A 3-4-5 right triangle: 90, atan(4/3) = 53.13 and atan(3/4) = 36.87 degrees.
  const CubicTriangle t = StraightCubicTriangle({ 0.0, 0.0 }, { 4.0, 0.0 }, { 0.0, 3.0 });
  EXPECT_NEAR(SmallestCornerAngle(t), std::atan(0.75) * 180.0 / M_PI, 1e-12);
}

TEST(CubicTriangle, CornerAnglesFollowTheTangentsOfCurvedEdges)
{
  // An equilateral cell (60 degrees everywhere) whose edge 0->1 leaves corner 0 bent 20 degrees
  // towards edge 2->0: the corner angle at 0 is 40 degrees, the others are unchanged.
  CubicTriangle t = StraightCubicTriangle({ 0.0, 0.0 }, { 3.0, 0.0 }, { 1.5, 1.5 * std::sqrt(3.0) });
  const double bend = 20.0 * M_PI / 180.0;
  t.ControlPoints[3] = { std::cos(bend), std::sin(bend) };
  EXPECT_NEAR(SmallestCornerAngle(t), 40.0, 1e-9);
  // A tangent that vanishes (the control point on its corner) has no angle.
  t.ControlPoints[3] = t.ControlPoints[0];
  EXPECT_EQ(SmallestCornerAngle(t), 0.0);
}

TEST(JacobianBound, QuarticIndexNumbersTheFifteenMultiIndices)
{
  std::vector<bool> seen(15, false);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; i + j <= 4; ++j)
    {
      const int index = QuarticIndex(i, j, 4 - i - j);
      ASSERT_GE(index, 0);
      ASSERT_LT(index, 15);
      EXPECT_FALSE(seen[index]);
      seen[index] = true;
    }
  EXPECT_THROW(QuarticIndex(1, 1, 1), std::invalid_argument);
}

TEST(JacobianBound, TableOneMatchesDerivativesAndFiniteDifferences)
{
  std::mt19937 rng(1);
  for (int trial = 0; trial < 300; ++trial)
  {
    const CubicTriangle t = RandomCurvedTriangle(rng, Amplitudes[trial % 5] * 2.0);
    const QuarticTriangle table = JacobianControlValues(t);
    // det J is a sum of cross products of control point differences: scale by the net's extent.
    double extent = 0.0;
    for (const Point2& p : t.ControlPoints)
      for (const Point2& q : t.ControlPoints)
        extent = std::max(extent, std::hypot(p[0] - q[0], p[1] - q[1]));
    const double tolerance = 1e-9 * 9.0 * extent * extent;
    for (int sample = 0; sample < 30; ++sample)
    {
      const auto [u, v, w] = RandomBarycentric(rng);
      const double fromTable = EvaluateQuartic(table, u, v, w);
      const double fromDerivatives = EvaluateJacobian(t, u, v, w);
      // Central differences in x̂ = v and ŷ = w (u = 1 - x̂ - ŷ); for a cubic the error is
      // exactly h² T'''/6, which Richardson extrapolation removes.
      const auto at = [&](double x, double y) { return EvaluateCubicTriangle(t, 1.0 - x - y, x, y); };
      const auto derivative = [&](int direction) {
        const auto central = [&](double h) {
          const Point2 plus = direction == 0 ? at(v + h, w) : at(v, w + h);
          const Point2 minus = direction == 0 ? at(v - h, w) : at(v, w - h);
          return Point2{ (plus[0] - minus[0]) / (2 * h), (plus[1] - minus[1]) / (2 * h) };
        };
        const Point2 coarse = central(1e-2), fine = central(5e-3);
        return Point2{ (4 * fine[0] - coarse[0]) / 3, (4 * fine[1] - coarse[1]) / 3 };
      };
      const Point2 dx = derivative(0), dy = derivative(1);
      const double fromDifferences = dx[0] * dy[1] - dx[1] * dy[0];
      EXPECT_NEAR(fromTable, fromDerivatives, tolerance);
      EXPECT_NEAR(fromTable, fromDifferences, tolerance);
      EXPECT_NEAR(fromDerivatives, fromDifferences, tolerance);
    }
  }
}

TEST(JacobianBound, StraightTriangleHasTwiceItsAreaEverywhere)
{
  std::mt19937 rng(2);
  int positive = 0, negative = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    const Point2 a = RandomPoint(rng), b = RandomPoint(rng), c = RandomPoint(rng);
    const double area2 = Area2(a, b, c);
    if (std::abs(area2) < 1e-3)
      continue;
    const CubicTriangle t = StraightCubicTriangle(a, b, c);
    const double tolerance = 1e-12;
    for (double value : JacobianControlValues(t).Values)
      EXPECT_NEAR(value, area2, tolerance);
    const auto [u, v, w] = RandomBarycentric(rng);
    EXPECT_NEAR(EvaluateJacobian(t, u, v, w), area2, tolerance);

    const JacobianBounds bounds = BoundJacobian(t);
    EXPECT_NEAR(bounds.Lower, area2, tolerance);
    EXPECT_NEAR(bounds.Upper, area2, tolerance);
    EXPECT_NEAR(bounds.MinimumFound, area2, tolerance);
    const Validity expected = area2 > 0 ? Validity::Valid : Validity::Invalid;
    EXPECT_EQ(bounds.Result, expected);
    EXPECT_EQ(ClassifyValidity(t), expected);
    EXPECT_EQ(HasUntwistedControlNet(t), area2 > 0);
    if (area2 > 0)
    {
      EXPECT_NEAR(bounds.ScaledJacobian(), 1.0, 1e-12);
      ++positive;
    }
    else
      ++negative;
  }
  EXPECT_GT(positive, 50);
  EXPECT_GT(negative, 50);
}

TEST(JacobianBound, AlgorithmFiveOnQuarticsWithKnownMinima)
{
  int neededSubdivision = 0;
  for (double a : { 0.0, 0.2, 0.45, 0.7, 1.0 })
    for (double b : { 0.1, 0.45, 0.8, 1.0 })
      for (double c : { 0.1, 1e-3, 1e-6, 0.0, -1e-6, -1e-3, -0.1 })
      {
        if (c == 0.0 && a == b && a < 1.0)
          continue; // (t - a)^4 touches 0 by less than the rounding of its control values
        const std::array<double, 5> alpha = DoubleRootsPlusConstant(a, b, c);
        const std::array<double, 5> beta = PowerToBernstein(alpha);
        for (double t : { 0.0, 0.3, a, b, 1.0 }) // the conversion is exact
          EXPECT_NEAR(EvaluateBernstein(beta, t),
            alpha[0] + t * (alpha[1] + t * (alpha[2] + t * (alpha[3] + t * alpha[4]))), 1e-14);
        // Minimum c, attained at a: positive exactly when c > 0 (c = 0 touches zero).
        EXPECT_EQ(IsQuarticCurvePositive(beta), c > 0) << "a " << a << " b " << b << " c " << c;
        if (c > 0 && *std::min_element(beta.begin(), beta.end()) <= 0)
          ++neededSubdivision;
      }
  EXPECT_GT(neededSubdivision, 10); // the convex hull alone would not have proven these

  // Non-positive end values are attained values.
  EXPECT_FALSE(IsQuarticCurvePositive({ 0.0, 1, 1, 1, 1 }));
  EXPECT_FALSE(IsQuarticCurvePositive({ 1, 1, 1, 1, -1e-300 }));
  EXPECT_TRUE(IsQuarticCurvePositive({ 1e-300, 1, 1, 1, 1e-300 }));

  // A depth limit that runs out gives the conservative answer.
  const std::array<double, 5> nearlyTouching = PowerToBernstein(DoubleRootsPlusConstant(0.3, 0.7, 1e-9));
  ASSERT_LT(*std::min_element(nearlyTouching.begin(), nearlyTouching.end()), 0.0);
  EXPECT_FALSE(IsQuarticCurvePositive(nearlyTouching, 2));
  EXPECT_TRUE(IsQuarticCurvePositive(nearlyTouching, 40));
}

TEST(JacobianBound, AlgorithmFiveAgreesWithSamplingOnRandomQuartics)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> value(-0.5, 1.5);
  int positive = 0, notPositive = 0;
  for (int trial = 0; trial < 1500; ++trial)
  {
    const std::array<double, 5> beta{ value(rng), value(rng), value(rng), value(rng), value(rng) };
    double sampledMinimum = INFINITY;
    for (int s = 0; s <= 1000; ++s)
      sampledMinimum = std::min(sampledMinimum, EvaluateBernstein(beta, s / 1000.0));
    if (IsQuarticCurvePositive(beta))
    {
      EXPECT_GT(sampledMinimum, 0.0);
      ++positive;
    }
    else
    {
      // false means a non-positive value was found, or a minimum within rounding of 0.
      EXPECT_LT(sampledMinimum, 1e-6);
      ++notPositive;
    }
  }
  EXPECT_GT(positive, 200);
  EXPECT_GT(notPositive, 200);
}

TEST(JacobianBound, SixPositiveControlTrianglesDoNotProveValidity)
{
  // Counterexample to Theorem 4.2.1 as printed: all nine control triangles
  // (six upward, three downward) are positive, yet det J < 0 somewhere.
  const CubicTriangle straight = StraightCubicTriangle({ 0, 0 }, { 3, 0 }, { 0, 3 });
  ASSERT_TRUE(SixUpwardTrianglesPositive(straight));
  ASSERT_TRUE(ThreeDownwardTrianglesPositive(straight));
  CubicTriangle t = straight;
  t.ControlPoints[CubicControlPointIndex(2, 1, 0)] = { -0.5, -1.0 };
  t.ControlPoints[CubicControlPointIndex(2, 0, 1)] = { 0.5, 0.5 };
  EXPECT_TRUE(SixUpwardTrianglesPositive(t));
  EXPECT_TRUE(ThreeDownwardTrianglesPositive(t));
  const Sampling s = SampleJacobian(t);
  EXPECT_LT(s.Minimum, 0.0);
  EXPECT_FALSE(HasUntwistedControlNet(t));
  EXPECT_EQ(ClassifyValidity(t), Validity::Invalid);
  const JacobianBounds bounds = BoundJacobian(t);
  EXPECT_EQ(bounds.Result, Validity::Invalid);
  EXPECT_LE(bounds.MinimumFound, 0.0);
}

TEST(JacobianBound, UntwistedControlNetImpliesPositiveJacobian)
{
  std::mt19937 rng(4);
  int untwisted = 0, twisted = 0, printedTheoremWrong = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    const CubicTriangle t = RandomCurvedTriangle(rng, Amplitudes[trial % 5]);
    const Sampling s = SampleJacobian(t, 30);
    if (HasUntwistedControlNet(t))
    {
      EXPECT_GT(s.Minimum, 0.0) << "trial " << trial;
      EXPECT_GT(s.RefinedMinimum, 0.0) << "trial " << trial;
      ++untwisted;
    }
    else
      ++twisted;
    if (SixUpwardTrianglesPositive(t) && s.Minimum <= 0.0)
      ++printedTheoremWrong;
  }
  EXPECT_GT(untwisted, 500);
  EXPECT_GT(twisted, 500);
  // Not rare: why HasUntwistedControlNet also requires non-negative mixed terms.
  EXPECT_GT(printedTheoremWrong, 10);
}

TEST(JacobianBound, BoundsAndClassificationAgreeWithDenseSampling)
{
  std::mt19937 rng(5);
  const JacobianBoundOptions options;
  int valid = 0, invalid = 0, undecided = 0, validNeedingSubdivision = 0;
  const int trials = 1500;
  for (int trial = 0; trial < trials; ++trial)
  {
    const CubicTriangle t = RandomCurvedTriangle(rng, Amplitudes[trial % 5]);
    const Sampling s = SampleJacobian(t);
    const double tiny = 1e-12 * std::max(std::abs(s.Minimum), std::abs(s.Maximum));
    const JacobianBounds b = BoundJacobian(t, options);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);

    // Lower <= min det J <= MinimumFound (an attained value), det J <= Upper.
    EXPECT_LE(b.Lower, s.Minimum + tiny);
    EXPECT_LE(b.Lower, b.MinimumFound);
    EXPECT_GE(b.MinimumFound, s.RefinedMinimum - tiny);
    EXPECT_GE(b.Upper, s.Maximum - tiny);
    if (b.Result != Validity::Undecided)
    {
      EXPECT_LE(b.MinimumFound - b.Lower, options.RelativeTolerance * std::abs(b.Upper) + tiny);
    }

    // Valid: det J > 0 at every sample; Invalid: a point with det J <= 0 exists.
    const Validity v = ClassifyValidity(t, options);
    for (Validity r : { b.Result, v })
    {
      if (r == Validity::Valid)
      {
        EXPECT_GT(s.Minimum, 0.0);
      }
      if (r == Validity::Invalid)
      {
        EXPECT_LE(s.RefinedMinimum, tiny);
      }
    }
    if (v != Validity::Undecided && b.Result != Validity::Undecided)
    {
      EXPECT_EQ(v, b.Result);
    }

    const auto& q = JacobianControlValues(t).Values;
    valid += v == Validity::Valid;
    invalid += v == Validity::Invalid;
    undecided += v == Validity::Undecided;
    if (v == Validity::Valid && *std::min_element(q.begin(), q.end()) <= 0)
      ++validNeedingSubdivision;
  }
  EXPECT_GT(valid, trials / 5);
  EXPECT_GT(invalid, trials / 5);
  EXPECT_LE(undecided, trials / 100);
  EXPECT_GT(validNeedingSubdivision, 10);
}

TEST(JacobianBound, PositiveBoundaryCurvesDoNotProveValidity)
{
  // F(x, y) = (x, -y + 3x²y + y³) has det DF = 3(x² + y²) - 1 < 0 only on the disc of
  // radius 1/√3. On the triangle of inradius 1 around it det J > 0 on the boundary,
  // so Algorithm 5 proves the three boundary curves positive (contrary to section
  // 4.2.1, that does not make the cell valid). The control points are the blossom
  // of F at the corners: F composed with the affine map of the reference triangle.
  const double root3 = std::sqrt(3.0);
  const Point2 corner[3] = { { 0, -2 }, { root3, 1 }, { -root3, 1 } };
  const auto blossom = [](const Point2& p, const Point2& q, const Point2& r) {
    return Point2{ (p[0] + q[0] + r[0]) / 3,
      -(p[1] + q[1] + r[1]) / 3 + p[0] * q[0] * r[1] + p[0] * r[0] * q[1] + q[0] * r[0] * p[1] + p[1] * q[1] * r[1] };
  };
  CubicTriangle t;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j)
    {
      std::vector<Point2> arguments(i, corner[0]);
      arguments.insert(arguments.end(), j, corner[1]);
      arguments.insert(arguments.end(), 3 - i - j, corner[2]);
      t.ControlPoints[CubicControlPointIndex(i, j, 3 - i - j)] = blossom(arguments[0], arguments[1], arguments[2]);
    }
  const double area2 = Area2(corner[0], corner[1], corner[2]);
  const QuarticTriangle q = JacobianControlValues(t);
  std::mt19937 rng(6);
  for (int sample = 0; sample < 100; ++sample)
  {
    const auto [u, v, w] = RandomBarycentric(rng);
    const double x = u * corner[0][0] + v * corner[1][0] + w * corner[2][0];
    const double y = u * corner[0][1] + v * corner[1][1] + w * corner[2][1];
    const Point2 p = EvaluateCubicTriangle(t, u, v, w);
    EXPECT_NEAR(p[0], x, 1e-12);
    EXPECT_NEAR(p[1], -y + 3 * x * x * y + y * y * y, 1e-12);
    const double expected = (3 * (x * x + y * y) - 1) * area2;
    EXPECT_NEAR(EvaluateJacobian(t, u, v, w), expected, 1e-12 * area2);
    EXPECT_NEAR(EvaluateQuartic(q, u, v, w), expected, 1e-12 * area2);
  }

  const auto& c = q.Values;
  const auto curve = [&](int a, int b, int d, int e, int f) {
    return std::array<double, 5>{ c[a], c[b], c[d], c[e], c[f] };
  };
  EXPECT_TRUE(IsQuarticCurvePositive(curve(QuarticIndex(4, 0, 0), QuarticIndex(3, 1, 0), QuarticIndex(2, 2, 0),
    QuarticIndex(1, 3, 0), QuarticIndex(0, 4, 0))));
  EXPECT_TRUE(IsQuarticCurvePositive(curve(QuarticIndex(0, 4, 0), QuarticIndex(0, 3, 1), QuarticIndex(0, 2, 2),
    QuarticIndex(0, 1, 3), QuarticIndex(0, 0, 4))));
  EXPECT_TRUE(IsQuarticCurvePositive(curve(QuarticIndex(0, 0, 4), QuarticIndex(1, 0, 3), QuarticIndex(2, 0, 2),
    QuarticIndex(3, 0, 1), QuarticIndex(4, 0, 0))));

  EXPECT_EQ(ClassifyValidity(t), Validity::Invalid);
  // The minimum, -area2, is at the centre; the maximum, 11 area2, at the corners.
  const JacobianBoundOptions options;
  const JacobianBounds bounds = BoundJacobian(t, options);
  const double tiny = 1e-12 * area2;
  EXPECT_EQ(bounds.Result, Validity::Invalid);
  EXPECT_LE(bounds.Lower, -area2 + tiny);
  EXPECT_GE(bounds.MinimumFound, -area2 - tiny);
  EXPECT_LE(bounds.MinimumFound - bounds.Lower, options.RelativeTolerance * std::abs(bounds.Upper) + tiny);
  EXPECT_GE(bounds.Upper, 11 * area2 - tiny);
}

TEST(JacobianBound, TangentEdgesAtACornerAreNotValid)
{
  // Two curved edges leaving corner 0 along one line (as on an ear of a smooth
  // boundary): det J = 0 at the corner, which rounding may turn into +1e-17.
  // Such a cell must never be classified valid.
  for (double angle = 0.05; angle < 3.1; angle += 0.1)
  {
    const Point2 a{ 0.1, 0.7 };
    const Point2 b{ a[0] + 3.0 * std::cos(angle + 0.5), a[1] + 3.0 * std::sin(angle + 0.5) };
    const Point2 c{ a[0] + 3.0 * std::cos(angle + 2.0), a[1] + 3.0 * std::sin(angle + 2.0) };
    CubicTriangle t = StraightCubicTriangle(a, b, c);
    const Point2 d{ std::cos(angle), std::sin(angle) };
    t.ControlPoints[CubicControlPointIndex(2, 1, 0)] = { a[0] + 0.7 * d[0], a[1] + 0.7 * d[1] };
    t.ControlPoints[CubicControlPointIndex(2, 0, 1)] = { a[0] - 1.3 * d[0], a[1] - 1.3 * d[1] };
    EXPECT_NEAR(EvaluateJacobian(t, 1.0, 0.0, 0.0), 0.0, 1e-12) << angle;
    EXPECT_NE(ClassifyValidity(t), Validity::Valid) << angle;
    EXPECT_NE(BoundJacobian(t).Result, Validity::Valid) << angle;
    EXPECT_FALSE(HasUntwistedControlNet(t) && ClassifyValidity(t) == Validity::Valid) << angle;
  }
}
