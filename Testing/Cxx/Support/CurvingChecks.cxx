// SPDX-License-Identifier: GPL-2.0-or-later
// Independent checks of a curved mesh for the curver's tests (sampled det J, continuity).
#include "CurvingChecks.h"

#include "Mesh/MeshSelection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace labelmesher
{
namespace testing
{
namespace
{

Point2 Sub(const Point2& a, const Point2& b) { return { a[0] - b[0], a[1] - b[1] }; }
double Norm(const Point2& a) { return std::hypot(a[0], a[1]); }

/// |a - b| relative to `scale`: the derivatives at a joint are compared relative
/// to the largest of them, so that (nearly) zero second derivatives on
/// straight chains do not turn rounding noise into a mismatch.
double RelativeMismatch(const Point2& a, const Point2& b, double scale)
{
  return Norm(Sub(a, b)) / std::max(scale, 1e-300);
}

Point2 Unit(const Point2& a)
{
  const double n = Norm(a);
  return n > 0.0 ? Point2{ a[0] / n, a[1] / n } : a;
}

} // namespace

SimplexMesh ForegroundMesh(const SimplexMesh& mesh)
{
  return SelectMaterials(mesh);
}

double SampledMinimumJacobian(const CubicTriangle& triangle, int n)
{
  double minimum = std::numeric_limits<double>::max();
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= n - i; ++j)
    {
      const double v = static_cast<double>(i) / n;
      const double w = static_cast<double>(j) / n;
      minimum = std::min(minimum, EvaluateJacobian(triangle, 1.0 - v - w, v, w));
    }
  }
  return minimum;
}

double SampledJacobianRatio(const CubicTriangle& triangle, int n)
{
  double minimum = std::numeric_limits<double>::max(), maximum = -minimum;
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= n - i; ++j)
    {
      const double v = static_cast<double>(i) / n;
      const double w = static_cast<double>(j) / n;
      const double det = EvaluateJacobian(triangle, 1.0 - v - w, v, w);
      minimum = std::min(minimum, det);
      maximum = std::max(maximum, det);
    }
  }
  return maximum > 0.0 ? minimum / maximum : 0.0;
}

double QuadraticNodesMismatch(const CubicTriangle& triangle, int n)
{
  // Nodes in VTK_QUADRATIC_TRIANGLE order: corners, then the middles of edges 0-1, 1-2, 2-0.
  std::array<Point2, 6> nodes;
  for (int k = 0; k < 3; ++k)
    nodes[static_cast<std::size_t>(k)] = triangle.ControlPoints[static_cast<std::size_t>(k)];
  nodes[3] = EvaluateCubicTriangle(triangle, 0.5, 0.5, 0.0);
  nodes[4] = EvaluateCubicTriangle(triangle, 0.0, 0.5, 0.5);
  nodes[5] = EvaluateCubicTriangle(triangle, 0.5, 0.0, 0.5);
  double largest = 0.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
    {
      const double u = static_cast<double>(i) / n, v = static_cast<double>(j) / n, w = 1.0 - u - v;
      // Lagrange basis of degree 2: l (2 l - 1) at the corners, 4 l l' at the edge middles.
      const std::array<double, 6> basis{ u * (2 * u - 1), v * (2 * v - 1), w * (2 * w - 1), 4 * u * v, 4 * v * w,
        4 * w * u };
      Point2 quadratic{ 0.0, 0.0 };
      for (std::size_t k = 0; k < 6; ++k)
        for (std::size_t a = 0; a < 2; ++a)
          quadratic[a] += basis[k] * nodes[k][a];
      const Point2 cubic = EvaluateCubicTriangle(triangle, u, v, w);
      largest = std::max(largest, std::hypot(quadratic[0] - cubic[0], quadratic[1] - cubic[1]));
    }
  return largest;
}

double SampledCornerAngle(const CubicTriangle& triangle)
{
  // Along an edge from its corner, P(s) - P(0) = a s + b s^2 + c s^3, so
  // (4 (P(t) - P(0)) - (P(2t) - P(0))) / (2t) = a - 2 c t^2: the tangent a to O(t^2).
  constexpr double t = 1e-4;
  auto along = [&triangle](int corner, int toward, double s) {
    double b[3] = { 0.0, 0.0, 0.0 };
    b[corner] += 1.0 - s;
    b[toward] += s;
    return EvaluateCubicTriangle(triangle, b[0], b[1], b[2]);
  };
  double smallest = 180.0;
  for (int corner = 0; corner < 3; ++corner)
  {
    const Point2 p = along(corner, corner, 0.0);
    Point2 tangent[2];
    for (int e = 0; e < 2; ++e)
    {
      const int toward = (corner + 1 + e) % 3;
      const Point2 near = along(corner, toward, t), far = along(corner, toward, 2.0 * t);
      for (int k = 0; k < 2; ++k)
        tangent[e][k] = (4.0 * (near[k] - p[k]) - (far[k] - p[k])) / (2.0 * t);
    }
    const double cross = tangent[0][0] * tangent[1][1] - tangent[0][1] * tangent[1][0];
    const double dot = tangent[0][0] * tangent[1][0] + tangent[0][1] * tangent[1][1];
    smallest = std::min(smallest, std::atan2(std::abs(cross), dot) * 180.0 / 3.14159265358979323846);
  }
  return smallest;
}

JointContinuity MeasureJointContinuity(const SimplexMesh& linear, const CurvedMesh& curved, const Box2& border,
  Smoothness smoothness, const std::vector<CurvePiece>& pieces, bool earCorners)
{
  std::map<std::pair<std::int64_t, std::int64_t>, double> scales;
  for (const CurvePiece& piece : pieces)
    scales[{ std::min(piece.From, piece.To), std::max(piece.From, piece.To) }] = piece.Scale;
  auto pieceScale = [&scales](std::int64_t a, std::int64_t b) {
    const auto it = scales.find({ std::min(a, b), std::max(a, b) });
    return it == scales.end() ? 1.0 : it->second;
  };
  JointContinuity result;
  std::vector<InterfaceChain> chains = ExtractInterfaceChains(linear, border);
  if (earCorners)
    chains = BreakChainsAt(chains, EarVertices(linear, chains));
  for (const InterfaceChain& chain : chains)
  {
    const std::size_t n = chain.Vertices.size();
    for (std::int64_t v : chain.Vertices)
    {
      const Point3& p = linear.Points[static_cast<std::size_t>(v)];
      result.VertexMovement = std::max(result.VertexMovement,
        Norm(Sub(curved.ControlPoints[static_cast<std::size_t>(v)], { p[0], p[1] })));
    }
    // Joint at vertex k between segments (k-1 -> k) and (k -> k+1).
    const std::size_t first = chain.Closed ? 0 : 1;
    const std::size_t last = chain.Closed ? n : n - 1;
    for (std::size_t k = first; k < last; ++k)
    {
      const std::int64_t a = chain.Vertices[(k + n - 1) % n];
      const std::int64_t v = chain.Vertices[k];
      const std::int64_t b = chain.Vertices[(k + 1) % n];
      const auto in = curved.EdgePoints(a, v);
      const auto out = curved.EdgePoints(v, b);
      const Point2& pv = curved.ControlPoints[static_cast<std::size_t>(v)];
      const Point2& in1 = curved.ControlPoints[static_cast<std::size_t>(in[0])];
      const Point2& in2 = curved.ControlPoints[static_cast<std::size_t>(in[1])];
      const Point2& out1 = curved.ControlPoints[static_cast<std::size_t>(out[0])];
      const Point2& out2 = curved.ControlPoints[static_cast<std::size_t>(out[1])];
      // Cubic Bézier end derivatives: 3 (P3 - P2) and 6 (P3 - 2 P2 + P1).
      const Point2 firstIn{ 3.0 * (pv[0] - in2[0]), 3.0 * (pv[1] - in2[1]) };
      const Point2 firstOut{ 3.0 * (out1[0] - pv[0]), 3.0 * (out1[1] - pv[1]) };
      const Point2 secondIn{ 6.0 * (pv[0] - 2.0 * in2[0] + in1[0]), 6.0 * (pv[1] - 2.0 * in2[1] + in1[1]) };
      const Point2 secondOut{ 6.0 * (out2[0] - 2.0 * out1[0] + pv[0]), 6.0 * (out2[1] - 2.0 * out1[1] + pv[1]) };
      const double scale = std::max({ Norm(firstIn), Norm(firstOut), Norm(secondIn), Norm(secondOut) });
      ++result.Joints;
      const double smaller = std::min(pieceScale(a, v), pieceScale(v, b));
      if (smaller == 0.0)
      {
        ++result.StraightJoints;
        continue;
      }
      if (smaller < 1.0)
      {
        ++result.ShortenedJoints;
        result.FirstDerivativeMismatch =
          std::max(result.FirstDerivativeMismatch, Norm(Sub(Unit(firstIn), Unit(firstOut))));
        continue;
      }
      if (smoothness == Smoothness::C2)
      {
        result.FirstDerivativeMismatch =
          std::max(result.FirstDerivativeMismatch, RelativeMismatch(firstIn, firstOut, scale));
        result.SecondDerivativeMismatch =
          std::max(result.SecondDerivativeMismatch, RelativeMismatch(secondIn, secondOut, scale));
      }
      else
      {
        result.FirstDerivativeMismatch =
          std::max(result.FirstDerivativeMismatch, Norm(Sub(Unit(firstIn), Unit(firstOut))));
      }
    }
  }
  return result;
}

} // namespace testing
} // namespace labelmesher
