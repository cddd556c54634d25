// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_Geometry_h
#define labelmesher_Geometry_h

/**
 * @file Geometry.h
 * Small exact-as-floating-point geometric primitives used by the mesher's
 * fidelity test and by the checks: distances from a point to a segment, a
 * triangle and an axis-aligned square (a voxel face).
 */

#include "Mesh/SimplexMesh.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
namespace geometry
{

inline Point3 Sub(const Point3& a, const Point3& b) { return { a[0] - b[0], a[1] - b[1], a[2] - b[2] }; }
inline Point3 Add(const Point3& a, const Point3& b) { return { a[0] + b[0], a[1] + b[1], a[2] + b[2] }; }
inline Point3 Scale(const Point3& a, double s) { return { a[0] * s, a[1] * s, a[2] * s }; }
inline double Dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point3 Cross(const Point3& a, const Point3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline double Norm(const Point3& a) { return std::sqrt(Dot(a, a)); }
inline double Distance(const Point3& a, const Point3& b) { return Norm(Sub(a, b)); }

/// Squared distance from p to segment [a, b].
inline double SquaredDistanceToSegment(const Point3& p, const Point3& a, const Point3& b)
{
  const Point3 ab = Sub(b, a);
  const double len2 = Dot(ab, ab);
  double t = len2 > 0.0 ? Dot(Sub(p, a), ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const Point3 q = Add(a, Scale(ab, t));
  const Point3 d = Sub(p, q);
  return Dot(d, d);
}

/// Squared distance from p to the closed triangle (a, b, c) (Ericson, Real-Time
/// Collision Detection, 5.1.5). A degenerate triangle (two equal points, or
/// three on a line, to 1e-6 radians) is the segment it spans, never NaN:
/// Ericson's regions assume a proper triangle, and an edge region with a zero
/// denominator is reached only by a degenerate one.
inline double SquaredDistanceToTriangle(const Point3& p, const Point3& a, const Point3& b, const Point3& c)
{
  auto sq = [](const Point3& v) { return Dot(v, v); };
  auto degenerate = [&] {
    return std::min({ SquaredDistanceToSegment(p, a, b), SquaredDistanceToSegment(p, b, c),
      SquaredDistanceToSegment(p, a, c) });
  };
  const Point3 ab = Sub(b, a), ac = Sub(c, a), ap = Sub(p, a);
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
    return sq(ap);
  const Point3 bp = Sub(p, b);
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
    return sq(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
    return d1 - d3 > 0 ? sq(Sub(p, Add(a, Scale(ab, d1 / (d1 - d3))))) : degenerate(); // d1 - d3 = |ab|^2
  const Point3 cp = Sub(p, c);
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
    return sq(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
    return d2 - d6 > 0 ? sq(Sub(p, Add(a, Scale(ac, d2 / (d2 - d6))))) : degenerate(); // |ac|^2
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double along = (d4 - d3) + (d5 - d6); // |bc|^2
    return along > 0 ? sq(Sub(p, Add(b, Scale(Sub(c, b), (d4 - d3) / along)))) : degenerate();
  }
  // va + vb + vc = |ab x ac|^2: on a line (up to the rounding of the products above, which can
  // leave it a little positive and every edge region missed), the segments decide.
  if (!(va + vb + vc > 1e-12 * Dot(ab, ab) * Dot(ac, ac)))
    return degenerate();
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return sq(Sub(p, Add(a, Add(Scale(ab, v), Scale(ac, w)))));
}

/// Squared distance from p to the axis-aligned box [lo, hi] (a voxel face is a
/// box with lo == hi along its normal axis; a pixel edge along two axes).
inline double SquaredDistanceToBox(const Point3& p, const Point3& lo, const Point3& hi)
{
  double s = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    const double d = p[a] < lo[a] ? lo[a] - p[a] : (p[a] > hi[a] ? p[a] - hi[a] : 0.0);
    s += d * d;
  }
  return s;
}

/// Smallest of the six dihedral angles of tetrahedron (a, b, c, d), in degrees.
inline double MinimumDihedralAngle(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  const Point3 p[4] = { a, b, c, d };
  // Face normals (outward up to a common sign); the dihedral angle at edge
  // (i, j) is pi minus the angle between the normals of the faces opposite k, l.
  Point3 n[4];
  for (int i = 0; i < 4; ++i)
  {
    const Point3& q0 = p[(i + 1) % 4];
    const Point3& q1 = p[(i + 2) % 4];
    const Point3& q2 = p[(i + 3) % 4];
    n[i] = Cross(Sub(q1, q0), Sub(q2, q0));
    if (Dot(n[i], Sub(p[i], q0)) > 0)
      n[i] = Scale(n[i], -1.0); // point away from the opposite vertex
  }
  double smallest = 180.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
    {
      const double cosine = -Dot(n[i], n[j]) / (Norm(n[i]) * Norm(n[j]));
      const double angle = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
      smallest = std::min(smallest, angle);
    }
  return smallest;
}

} // namespace geometry
} // namespace labelmesher

#endif
