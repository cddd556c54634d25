// SPDX-License-Identifier: GPL-2.0-or-later
//
// The quadratic triangle's validity certificate (Quadratic/TriangleJacobian.h),
// against det J computed independently: from central differences of points of
// the map (exact for a quadratic map's first derivatives up to round-off) on a
// dense barycentric lattice. Straight cells have every coefficient equal to
// twice their area; the coefficients bound every sampled det J; a certified
// ratio never exceeds the sampled one, and subdivision tightens it.

#include "Quadratic/TriangleJacobian.h"
#include "Support/Geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

namespace labelmesher
{
using namespace geometry;
namespace
{

std::array<Point3, 6> StraightTriangle(const Point3& a, const Point3& b, const Point3& c)
{
  std::array<Point3, 6> n{ a, b, c };
  for (int e = 0; e < 3; ++e)
    n[static_cast<std::size_t>(3 + e)] = Scale(Add(n[kTriangleEdges[e][0]], n[kTriangleEdges[e][1]]), 0.5);
  return n;
}

/// det J at barycentric (1 − u − v, u, v) from points of the map: the map is quadratic, so a
/// central difference is its derivative exactly (up to round-off).
double SampledDeterminant(const std::array<Point3, 6>& nodes, double u, double v)
{
  constexpr double h = 1e-3;
  auto at = [&](double s, double t) { return EvaluateQuadraticTriangle(nodes, { 1.0 - s - t, s, t }); };
  const Point3 du = Scale(Sub(at(u + h, v), at(u - h, v)), 0.5 / h);
  const Point3 dv = Scale(Sub(at(u, v + h), at(u, v - h)), 0.5 / h);
  return du[0] * dv[1] - du[1] * dv[0];
}

/// min det J / max det J over the lattice of step 1/n, and the smallest and largest det J.
double SampledRatio(const std::array<Point3, 6>& nodes, int n, double& smallest, double& largest)
{
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
    {
      const double d = SampledDeterminant(nodes, double(i) / n, double(j) / n);
      lo = std::min(lo, d), hi = std::max(hi, d);
    }
  smallest = lo, largest = hi;
  return hi > 0.0 ? lo / hi : -1.0;
}

TEST(TriangleJacobian, StraightCellHasTwiceItsAreaEverywhere)
{
  const auto nodes = StraightTriangle({ 0, 0, 0 }, { 3, 0.5, 0 }, { 1, 2, 0 });
  const double twiceArea = 3.0 * 2.0 - 0.5 * 1.0;
  for (double c : TriangleJacobianCoefficients(nodes))
    EXPECT_NEAR(c, twiceArea, 1e-12);
  EXPECT_NEAR(CertifiedTriangleScaledJacobian(nodes), 1.0, 1e-12);
  // Clockwise: negative everywhere, not valid.
  EXPECT_LT(CertifiedTriangleScaledJacobian(StraightTriangle({ 0, 0, 0 }, { 1, 2, 0 }, { 3, 0.5, 0 })), 0.0);
}

TEST(TriangleJacobian, CoefficientsBoundSampledDeterminants)
{
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> offset(-0.08, 0.08);
  int valid = 0, refinedValid = 0, invalid = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    auto nodes = StraightTriangle({ 0, 0, 0 }, { 1, 0, 0 }, { 0.3, 0.9, 0 });
    for (int e = 3; e < 6; ++e)
      for (int a = 0; a < 2; ++a)
        nodes[static_cast<std::size_t>(e)][static_cast<std::size_t>(a)] += offset(random) * (trial % 6 + 1);
    const auto c = TriangleJacobianCoefficients(nodes);
    const double lo = *std::min_element(c.begin(), c.end()), hi = *std::max_element(c.begin(), c.end());
    double smallest = 0.0, largest = 0.0;
    const double ratio = SampledRatio(nodes, 12, smallest, largest);
    EXPECT_GE(smallest, lo - 1e-9) << trial;
    EXPECT_LE(largest, hi + 1e-9) << trial;
    const double certified = CertifiedTriangleScaledJacobian(nodes);
    if (certified > 0.0)
    {
      ++valid;
      EXPECT_GT(smallest, 0.0) << trial;
      EXPECT_GE(ratio, certified - 1e-9) << trial;
    }
    const double refined = CertifiedTriangleScaledJacobian(nodes, 1.0, 3);
    if (certified > 0.0)
      EXPECT_GE(refined, certified - 1e-12) << trial;
    if (refined > 0.0)
    {
      ++refinedValid;
      EXPECT_GT(smallest, 0.0) << trial;
      EXPECT_GE(ratio, refined - 1e-9) << trial;
    }
    invalid += smallest <= 0.0 ? 1 : 0;
  }
  EXPECT_GT(valid, 300);
  EXPECT_GT(invalid, 300);
  EXPECT_GT(refinedValid, valid);
  std::cout << "[ jacobian ] quadratic triangles proved valid: " << valid << " whole, " << refinedValid
            << " with 3 levels of subdivision; " << invalid << " sampled invalid of 3000\n";
}

} // namespace
} // namespace labelmesher
