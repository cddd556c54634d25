// SPDX-License-Identifier: GPL-2.0-or-later
// det J of a quadratic triangle in the quadratic Bernstein basis.
#include "Quadratic/TriangleJacobian.h"

#include "Quadratic/BernsteinCertificate.h"
#include "Support/Geometry.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace labelmesher
{
using namespace geometry;
namespace
{

double Cross2(const Point3& a, const Point3& b)
{
  return a[0] * b[1] - a[1] * b[0];
}

/// The nodes of the four pieces of the cell with `parent` nodes (corners, then its edges'
/// midpoints: reference points 0-5), each counter-clockwise like the parent.
void Refine(const std::array<Point3, 6>& parent, std::vector<std::array<Point3, 6>>& out)
{
  static const int kChildren[4][3] = { { 0, 3, 5 }, { 3, 1, 4 }, { 5, 4, 2 }, { 4, 5, 3 } };
  std::array<std::array<double, 3>, 6> at{};
  for (int k = 0; k < 3; ++k)
    at[static_cast<std::size_t>(k)][static_cast<std::size_t>(k)] = 1.0;
  for (int e = 0; e < 3; ++e)
    at[static_cast<std::size_t>(3 + e)][kTriangleEdges[e][0]] = at[static_cast<std::size_t>(3 + e)][kTriangleEdges[e][1]] = 0.5;
  for (const auto& child : kChildren)
  {
    std::array<Point3, 6> nodes;
    for (int k = 0; k < 3; ++k)
      nodes[static_cast<std::size_t>(k)] = EvaluateQuadraticTriangle(parent, at[static_cast<std::size_t>(child[k])]);
    for (int e = 0; e < 3; ++e)
    {
      std::array<double, 3> mid{};
      for (int q = 0; q < 3; ++q)
        mid[static_cast<std::size_t>(q)] = 0.5 *
          (at[static_cast<std::size_t>(child[kTriangleEdges[e][0]])][static_cast<std::size_t>(q)] +
            at[static_cast<std::size_t>(child[kTriangleEdges[e][1]])][static_cast<std::size_t>(q)]);
      nodes[static_cast<std::size_t>(3 + e)] = EvaluateQuadraticTriangle(parent, mid);
    }
    out.push_back(nodes);
  }
}

} // namespace

Point3 EvaluateQuadraticTriangle(const std::array<Point3, 6>& nodes, const std::array<double, 3>& l)
{
  // Lagrange basis of degree 2: corners l(2l − 1), edge (i, j) 4 l_i l_j.
  Point3 x{ 0.0, 0.0, 0.0 };
  for (int k = 0; k < 3; ++k)
    x = Add(x, Scale(nodes[static_cast<std::size_t>(k)], l[static_cast<std::size_t>(k)] * (2.0 * l[static_cast<std::size_t>(k)] - 1.0)));
  for (int e = 0; e < 3; ++e)
    x = Add(x, Scale(nodes[static_cast<std::size_t>(3 + e)], 4.0 * l[kTriangleEdges[e][0]] * l[kTriangleEdges[e][1]]));
  return x;
}

std::array<double, 6> TriangleJacobianCoefficients(const std::array<Point3, 6>& nodes)
{
  // Bézier control points: corners on the diagonal, 2 m − (a + b)/2 for edge (i, j).
  Point3 q[3][3];
  for (int k = 0; k < 3; ++k)
    q[k][k] = nodes[static_cast<std::size_t>(k)];
  for (int e = 0; e < 3; ++e)
  {
    const int i = kTriangleEdges[e][0], j = kTriangleEdges[e][1];
    q[i][j] = q[j][i] = Sub(Scale(nodes[static_cast<std::size_t>(3 + e)], 2.0), Scale(Add(q[i][i], q[j][j]), 0.5));
  }
  // dx/dl_k − dx/dl_0 = 2 Σ_a (Q[k][a] − Q[0][a]) l_a: column k of J, linear in l.
  Point3 d[2][3];
  for (int k = 0; k < 2; ++k)
    for (int a = 0; a < 3; ++a)
      d[k][a] = Scale(Sub(q[k + 1][a], q[0][a]), 2.0);
  // det J = Σ l_a l_b cross(d0a, d1b); l_a² = B_(2 e_a), l_a l_b = B_(e_a + e_b) / 2.
  std::array<double, 6> c{};
  for (int a = 0; a < 3; ++a)
    c[static_cast<std::size_t>(a)] = Cross2(d[0][a], d[1][a]);
  for (int e = 0; e < 3; ++e)
  {
    const int a = kTriangleEdges[e][0], b = kTriangleEdges[e][1];
    c[static_cast<std::size_t>(3 + e)] = 0.5 * (Cross2(d[0][a], d[1][b]) + Cross2(d[0][b], d[1][a]));
  }
  return c;
}

double CertifiedTriangleScaledJacobian(const std::array<Point3, 6>& nodes, double target, int depth)
{
  return CertifiedBernsteinRatio(nodes, target, depth, 1.0 / 4.0,
    [](const std::array<Point3, 6>& n) {
      const std::array<double, 6> c = TriangleJacobianCoefficients(n);
      const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
      return std::make_pair(*lo, *hi);
    },
    Refine);
}

} // namespace labelmesher
