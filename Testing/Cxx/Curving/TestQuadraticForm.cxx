// SPDX-License-Identifier: GPL-2.0-or-later
//
// Quadratic triangles in the cubic curver's form (Curving/QuadraticForm.h): degree elevation
// reproduces the quadratic curve at every parameter, the nearest quadratic of an elevated one is
// itself, MakeQuadraticForm leaves quadratic meshes alone and makes any mesh quadratic without
// moving a vertex, and the mid-node is the curve's middle.

#include "Curving/CubicTriangle.h"
#include "Curving/CurvedMesh.h"
#include "Curving/QuadraticForm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace labelmesher
{
namespace
{

Point2 Quadratic(const Point2& a, const Point2& q, const Point2& b, double t)
{
  const double s = 1.0 - t;
  return { s * s * a[0] + 2 * s * t * q[0] + t * t * b[0], s * s * a[1] + 2 * s * t * q[1] + t * t * b[1] };
}

Point2 Cubic(const Point2& a, const Point2& c1, const Point2& c2, const Point2& b, double t)
{
  const double s = 1.0 - t;
  const double w0 = s * s * s, w1 = 3 * s * s * t, w2 = 3 * s * t * t, w3 = t * t * t;
  return { w0 * a[0] + w1 * c1[0] + w2 * c2[0] + w3 * b[0], w0 * a[1] + w1 * c1[1] + w2 * c2[1] + w3 * b[1] };
}

double Distance(const Point2& p, const Point2& q) { return std::hypot(p[0] - q[0], p[1] - q[1]); }

TEST(QuadraticForm, ElevationIsTheSameCurveAndProjectsBack)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Point2 a{ coordinate(random), coordinate(random) }, q{ coordinate(random), coordinate(random) },
      b{ coordinate(random), coordinate(random) };
    const auto inner = ElevateQuadratic(a, q, b);
    for (double t = 0.0; t <= 1.0; t += 0.125)
      EXPECT_LT(Distance(Quadratic(a, q, b, t), Cubic(a, inner[0], inner[1], b, t)), 1e-12);
    EXPECT_LT(Distance(NearestQuadraticControl(a, inner[0], inner[1], b), q), 1e-12);
    EXPECT_LT(Distance(CubicMidpoint(a, inner[0], inner[1], b), Quadratic(a, q, b, 0.5)), 1e-12);
  }
}

TEST(QuadraticForm, NearestQuadraticIsTheLeastSquaresOne)
{
  // Moving q any way from the nearest one moves the elevated inner points farther from the cubic's.
  const Point2 a{ 0, 0 }, c1{ 1, 2 }, c2{ 3, -1 }, b{ 4, 0 };
  const Point2 q = NearestQuadraticControl(a, c1, c2, b);
  auto misfit = [&](const Point2& control) {
    const auto inner = ElevateQuadratic(a, control, b);
    return std::pow(Distance(inner[0], c1), 2) + std::pow(Distance(inner[1], c2), 2);
  };
  for (const Point2& step : { Point2{ 1e-3, 0 }, Point2{ -1e-3, 0 }, Point2{ 0, 1e-3 }, Point2{ 0, -1e-3 } })
    EXPECT_GT(misfit({ q[0] + step[0], q[1] + step[1] }), misfit(q));
}

TEST(QuadraticForm, MakesEveryCellQuadraticWithoutMovingVertices)
{
  // Two triangles sharing an edge, with every control point perturbed.
  SimplexMesh linear;
  linear.Dimension = 2;
  linear.Points = { { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, { 4, 4, 0 } };
  linear.Connectivity = { 0, 1, 2, 1, 3, 2 };
  linear.Materials = { 1, 2 };
  CurvedMesh mesh = MakeStraightCurvedMesh(linear);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (std::size_t p = static_cast<std::size_t>(mesh.NumberOfVertices); p < mesh.ControlPoints.size(); ++p)
    mesh.ControlPoints[p] = { mesh.ControlPoints[p][0] + jitter(random), mesh.ControlPoints[p][1] + jitter(random) };
  EXPECT_GT(DistanceFromQuadraticForm(mesh.Cell(0)), 1e-3);
  const std::vector<Point2> before = mesh.ControlPoints;
  MakeQuadraticForm(mesh);
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
    EXPECT_LT(DistanceFromQuadraticForm(mesh.Cell(c)), 1e-12);
  for (std::int64_t v = 0; v < mesh.NumberOfVertices; ++v)
    EXPECT_EQ(mesh.ControlPoints[static_cast<std::size_t>(v)], before[static_cast<std::size_t>(v)]);
  // Quadratic already: nothing moves beyond rounding.
  const std::vector<Point2> quadratic = mesh.ControlPoints;
  MakeQuadraticForm(mesh);
  for (std::size_t p = 0; p < quadratic.size(); ++p)
    EXPECT_LT(Distance(mesh.ControlPoints[p], quadratic[p]), 1e-12);
}

} // namespace
} // namespace labelmesher
