// SPDX-License-Identifier: GPL-2.0-or-later
// det J of a quadratic tetrahedron in the cubic Bernstein basis.
#include "Quadratic/TetraJacobian.h"

#include "Quadratic/BernsteinCertificate.h"
#include "Quadratic/QuadraticMesh.h"
#include "Support/Geometry.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace labelmesher
{
using namespace geometry;
namespace
{

double Determinant(const Point3& a, const Point3& b, const Point3& c)
{
  return Dot(a, Cross(b, c));
}

/// Index 0..19 of the cubic multi-index with counts (n0, n1, n2, n3), and
/// α!/3! for it, as tables over the base-4 code n0 + 4 n1 + 16 n2 + 64 n3.
struct CubicIndex
{
  std::array<int, 256> Index{};
  std::array<double, 20> Weight{};
  CubicIndex()
  {
    Index.fill(-1);
    int next = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 4; ++c)
        {
          int n[4] = { 0, 0, 0, 0 };
          ++n[a], ++n[b], ++n[c];
          const int code = n[0] + 4 * n[1] + 16 * n[2] + 64 * n[3];
          if (Index[code] >= 0)
            continue;
          double factorials = 1.0;
          for (int k : n)
            factorials *= k == 3 ? 6.0 : (k == 2 ? 2.0 : 1.0);
          Index[code] = next;
          Weight[next++] = factorials / 6.0;
        }
  }
};

} // namespace

std::array<double, 20> JacobianCoefficients(const std::array<Point3, 10>& nodes)
{
  static const CubicIndex cubic;
  // Bézier control points Q[i][j]: corners on the diagonal, 2 m − (a + b)/2 for edge (i, j).
  Point3 q[4][4];
  for (int k = 0; k < 4; ++k)
    q[k][k] = nodes[k];
  for (int e = 0; e < 6; ++e)
  {
    const int i = kTetraEdges[e][0], j = kTetraEdges[e][1];
    q[i][j] = q[j][i] = Sub(Scale(nodes[4 + e], 2.0), Scale(Add(nodes[i], nodes[j]), 0.5));
  }
  // dx/dl_k − dx/dl_0 = 2 Σ_j (Q[k][j] − Q[0][j]) l_j: column k of J, linear in l.
  Point3 d[3][4];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 4; ++j)
      d[k][j] = Scale(Sub(q[k + 1][j], q[0][j]), 2.0);
  // det J = Σ l_a l_b l_c det[d0a, d1b, d2c], and l_a l_b l_c = (α!/3!) B_α for α = e_a + e_b + e_c.
  std::array<double, 20> coefficients{};
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
      {
        int n[4] = { 0, 0, 0, 0 };
        ++n[a], ++n[b], ++n[c];
        coefficients[cubic.Index[n[0] + 4 * n[1] + 16 * n[2] + 64 * n[3]]] +=
          Determinant(d[0][a], d[1][b], d[2][c]);
      }
  for (int k = 0; k < 20; ++k)
    coefficients[k] *= cubic.Weight[k];
  return coefficients;
}

namespace
{

/// The nodes of the eight pieces of the red refinement of the cell with `parent` nodes (in its
/// reference coordinates: corners, then the midpoints of its edges in kTetraEdges' order), each
/// positively oriented.
void Refine(const std::array<Point3, 10>& parent, std::vector<std::array<Point3, 10>>& out)
{
  static const int kChildren[8][4] = { { 0, 4, 6, 7 }, { 4, 1, 5, 8 }, { 6, 5, 2, 9 }, { 7, 8, 9, 3 },
    { 6, 8, 4, 5 }, { 6, 8, 5, 9 }, { 6, 8, 9, 7 }, { 6, 8, 7, 4 } };
  // Barycentric coordinates of the parent's corners and edge midpoints.
  std::array<std::array<double, 4>, 10> at{};
  for (int k = 0; k < 4; ++k)
    at[k][k] = 1.0;
  for (int e = 0; e < 6; ++e)
    at[4 + e][kTetraEdges[e][0]] = at[4 + e][kTetraEdges[e][1]] = 0.5;
  auto point = [](const std::array<double, 4>& l) { return Point3{ l[1], l[2], l[3] }; };
  for (const auto& child : kChildren)
  {
    int corner[4] = { child[0], child[1], child[2], child[3] };
    const Point3 a = point(at[corner[0]]);
    if (Determinant(Sub(point(at[corner[1]]), a), Sub(point(at[corner[2]]), a), Sub(point(at[corner[3]]), a)) < 0.0)
      std::swap(corner[1], corner[2]);
    std::array<Point3, 10> nodes;
    for (int k = 0; k < 4; ++k)
      nodes[k] = EvaluateQuadraticTetra(parent, at[corner[k]]);
    for (int e = 0; e < 6; ++e)
    {
      std::array<double, 4> mid{};
      for (int q = 0; q < 4; ++q)
        mid[q] = 0.5 * (at[corner[kTetraEdges[e][0]]][q] + at[corner[kTetraEdges[e][1]]][q]);
      nodes[4 + e] = EvaluateQuadraticTetra(parent, mid);
    }
    out.push_back(nodes);
  }
}

} // namespace

double CertifiedScaledJacobian(const std::array<Point3, 10>& nodes, double target, int depth)
{
  return CertifiedBernsteinRatio(nodes, target, depth, 1.0 / 8.0,
    [](const std::array<Point3, 10>& n) {
      const std::array<double, 20> c = JacobianCoefficients(n);
      const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
      return std::make_pair(*lo, *hi);
    },
    Refine);
}

} // namespace labelmesher
