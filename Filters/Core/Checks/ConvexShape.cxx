// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file ConvexShape.cxx
 * The two operations on a convex piece that are not on the hot path of the
 * branch and bound: finding its axis-aligned plane (once per mesh facet) and
 * subdividing it (once per refinement step).
 */

#include "Checks/ConvexShape.h"

#include <cmath>

namespace labelmesher
{
namespace checks_detail
{

void SetPlane(Shape& s, int dimension)
{
  Point3 c[4];
  const int n = Corners(s, c);
  s.Axis = -1;
  for (int a = 0; a < dimension; ++a)
  {
    bool flat = true;
    for (int t = 1; t < n && flat; ++t)
      flat = std::abs(c[t][a] - c[0][a]) <= RoundOff;
    if (flat)
    {
      s.Axis = static_cast<std::int8_t>(a);
      s.Plane = c[0][a];
      return;
    }
  }
}

int Subdivide(const Shape& s, Shape* out)
{
  auto mid = [](const Point3& a, const Point3& b) {
    return Point3{ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
  };
  int n = 0;
  switch (s.K)
  {
    case ShapeKind::Segment:
    {
      const Point3 m = mid(s.P[0], s.P[1]);
      out[0] = s;
      out[0].P[1] = m;
      out[1] = s;
      out[1].P[0] = m;
      n = 2;
      break;
    }
    case ShapeKind::Triangle:
    {
      const Point3 &a = s.P[0], &b = s.P[1], &c = s.P[2];
      const Point3 ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      const Point3 tri[4][3] = { { a, ab, ca }, { ab, b, bc }, { ca, bc, c }, { ab, bc, ca } };
      for (int t = 0; t < 4; ++t)
      {
        out[t] = s;
        for (int q = 0; q < 3; ++q)
          out[t].P[q] = tri[t][q];
      }
      n = 4;
      break;
    }
    case ShapeKind::Box:
    default:
    {
      int f[3];
      const int nf = FreeAxes(s, f);
      const Point3 m = mid(s.P[0], s.P[1]);
      n = 1 << nf;
      for (int t = 0; t < n; ++t)
      {
        out[t] = s;
        for (int q = 0; q < nf; ++q)
        {
          const int a = f[q];
          if (t & (1 << q))
            out[t].P[0][a] = m[a];
          else
            out[t].P[1][a] = m[a];
        }
      }
      break;
    }
  }
  return n;
}

} // namespace checks_detail
} // namespace labelmesher
