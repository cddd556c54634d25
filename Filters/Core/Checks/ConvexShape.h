// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ConvexShape_h
#define labelmesher_ConvexShape_h

/**
 * @file ConvexShape.h
 * Internal to the checks (not installed, not part of the public API): the
 * convex pieces that both boundaries are made of in the Hausdorff distance
 * check (HausdorffDistance.cxx): voxel faces and pixel edges (flat
 * axis-aligned boxes), mesh boundary triangles and segments. What the branch
 * and bound needs of a piece: its corners, bounding box, distance from a
 * point, the axis-aligned plane holding it and its subdivision.
 *
 * The small functions are inline: the branch and bound calls them once per
 * candidate and corner.
 */

#include "Support/Geometry.h"

#include <algorithm>
#include <cstdint>

namespace labelmesher
{
namespace checks_detail
{

/// Absolute round-off allowance of the distance check, in index space (MeshChecks.h).
constexpr double RoundOff = 1e-9;

enum class ShapeKind : std::uint8_t
{
  Segment,  ///< P[0], P[1]
  Triangle, ///< P[0], P[1], P[2]
  Box       ///< axis-aligned box P[0] (lo) .. P[1] (hi), flat along at least one axis
};

struct Shape
{
  Point3 P[3];
  ShapeKind K = ShapeKind::Triangle;
  std::int8_t Axis = -1; ///< normal axis of the axis-aligned hyperplane holding it, or -1
  double Plane = 0.0;    ///< coordinate of that hyperplane
};

/// Axes along which a box has extent; returns how many.
inline int FreeAxes(const Shape& s, int* axes)
{
  int n = 0;
  for (int a = 0; a < 3; ++a)
    if (s.P[1][a] > s.P[0][a])
      axes[n++] = a;
  return n;
}

/// Corners of the shape (at most 4), in cyclic order for polygons; returns how many.
inline int Corners(const Shape& s, Point3* out)
{
  switch (s.K)
  {
    case ShapeKind::Segment:
      out[0] = s.P[0];
      out[1] = s.P[1];
      return 2;
    case ShapeKind::Triangle:
      out[0] = s.P[0];
      out[1] = s.P[1];
      out[2] = s.P[2];
      return 3;
    case ShapeKind::Box:
    default:
    {
      int f[3];
      const int nf = FreeAxes(s, f);
      out[0] = s.P[0];
      if (nf == 0)
        return 1;
      out[1] = s.P[0];
      out[1][f[0]] = s.P[1][f[0]];
      if (nf == 1)
        return 2;
      out[2] = out[1];
      out[2][f[1]] = s.P[1][f[1]];
      out[3] = s.P[0];
      out[3][f[1]] = s.P[1][f[1]];
      return 4;
    }
  }
}

inline void BoundingBox(const Shape& s, Point3& lo, Point3& hi)
{
  if (s.K == ShapeKind::Box)
  {
    lo = s.P[0];
    hi = s.P[1];
    return;
  }
  const int n = s.K == ShapeKind::Segment ? 2 : 3;
  lo = hi = s.P[0];
  for (int t = 1; t < n; ++t)
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], s.P[t][a]);
      hi[a] = std::max(hi[a], s.P[t][a]);
    }
}

inline double SquaredDistance(const Point3& p, const Shape& s)
{
  using namespace geometry;
  switch (s.K)
  {
    case ShapeKind::Segment:
      return SquaredDistanceToSegment(p, s.P[0], s.P[1]);
    case ShapeKind::Triangle:
      return SquaredDistanceToTriangle(p, s.P[0], s.P[1], s.P[2]);
    case ShapeKind::Box:
    default:
      return SquaredDistanceToBox(p, s.P[0], s.P[1]);
  }
}

/// Centroid of the corners and the largest distance from it to a corner.
inline void CentreAndRadius(const Shape& s, Point3& centre, double& radius)
{
  using namespace geometry;
  Point3 c[4];
  const int n = Corners(s, c);
  centre = { 0, 0, 0 };
  for (int t = 0; t < n; ++t)
    centre = Add(centre, c[t]);
  centre = Scale(centre, 1.0 / n);
  radius = 0;
  for (int t = 0; t < n; ++t)
    radius = std::max(radius, Distance(centre, c[t]));
}

/// Records the axis-aligned hyperplane (line in 2D) holding the shape, if any,
/// to RoundOff: coplanar coverage (CoplanarCoverage.h) compares these.
void SetPlane(Shape& s, int dimension);

/// Splits the shape at the midpoints of its edges: a segment into 2, a
/// triangle into 4, a box into 2 per axis of extent (a square into 4). `out`
/// must hold 4 shapes. Returns the number of parts.
int Subdivide(const Shape& s, Shape* out);

} // namespace checks_detail
} // namespace labelmesher

#endif
