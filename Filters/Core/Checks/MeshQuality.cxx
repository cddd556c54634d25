// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file MeshQuality.cxx
 * MeasureQuality: the element quality guarantee of the ORD mesh (dissertation
 * section 3.2: dihedral angles of the tetrahedra, planar angles of the
 * triangles) and the validity check (no inverted or flat cell).
 *
 * Angles are computed with atan2(|sin|, cos) from unnormalised vectors, which is
 * accurate for angles near 0 and 180 degrees, and independent of the cell's
 * orientation. The dihedral angle at edge (a, b) of a tetrahedron is the angle
 * between the projections of c - a and d - a on the plane orthogonal to b - a.
 * A degenerate cell (zero-length edge or collinear points) gets the angle 0.
 */

#include "Checks/MeshChecks.h"

#include "Support/Geometry.h"
#include "Checks/MeshIncidence.h"

#include <cmath>
#include <limits>

namespace labelmesher
{

namespace
{
using namespace geometry;

constexpr double RadiansToDegrees = 180.0 / 3.14159265358979323846;

/// Angle in degrees between u and v (0 if either is zero).
double AngleBetween(const Point3& u, const Point3& v)
{
  const double s = Norm(Cross(u, v));
  const double c = Dot(u, v);
  if (s == 0.0 && c == 0.0)
    return 0.0;
  return std::atan2(s, c) * RadiansToDegrees;
}

/// Dihedral angle of tetrahedron at edge (a, b), opposite vertices c and d.
double DihedralAngle(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  const Point3 ab = Sub(b, a);
  const double l2 = Dot(ab, ab);
  // (x * |ab|^2 - (x . ab) ab) is |ab|^2 times the projection of x: same angle.
  const Point3 ac = Sub(c, a), ad = Sub(d, a);
  const Point3 pc = Sub(Scale(ac, l2), Scale(ab, Dot(ac, ab)));
  const Point3 pd = Sub(Scale(ad, l2), Scale(ab, Dot(ad, ab)));
  return AngleBetween(pc, pd);
}
} // namespace

QualityReport MeasureQuality(const SimplexMesh& mesh)
{
  QualityReport report;
  if (mesh.NumberOfCells() == 0)
    return report;
  struct Local
  {
    double Lo = std::numeric_limits<double>::infinity();
    double Hi = -std::numeric_limits<double>::infinity();
    std::size_t Inverted = 0;
  };
  std::vector<Local> locals(checks_detail::MaxThreads());
  const auto& P = mesh.Points;
  checks_detail::ParallelChunks(mesh.NumberOfCells(), 16384, [&](unsigned t, std::size_t b, std::size_t e) {
    Local& local = locals[t];
    for (std::size_t c = b; c < e; ++c)
    {
      const std::int64_t* v = mesh.Cell(c);
      if (mesh.Dimension == 3)
      {
        const Point3* p[4] = { &P[v[0]], &P[v[1]], &P[v[2]], &P[v[3]] };
        const double det = Dot(Sub(*p[1], *p[0]), Cross(Sub(*p[2], *p[0]), Sub(*p[3], *p[0])));
        if (!(det > 0.0))
          ++local.Inverted;
        // The six edges (i, j) with opposite vertices (k, l).
        static const int edges[6][4] = { { 0, 1, 2, 3 }, { 0, 2, 1, 3 }, { 0, 3, 1, 2 }, { 1, 2, 0, 3 },
          { 1, 3, 0, 2 }, { 2, 3, 0, 1 } };
        for (const auto& ed : edges)
        {
          const double angle = DihedralAngle(*p[ed[0]], *p[ed[1]], *p[ed[2]], *p[ed[3]]);
          local.Lo = std::min(local.Lo, angle);
          local.Hi = std::max(local.Hi, angle);
        }
      }
      else
      {
        const Point3* p[3] = { &P[v[0]], &P[v[1]], &P[v[2]] };
        const Point3 ab = Sub(*p[1], *p[0]), ac = Sub(*p[2], *p[0]);
        const double area2 = ab[0] * ac[1] - ab[1] * ac[0];
        if (!(area2 > 0.0))
          ++local.Inverted;
        for (int i = 0; i < 3; ++i)
        {
          const Point3& o = *p[i];
          const double angle = AngleBetween(Sub(*p[(i + 1) % 3], o), Sub(*p[(i + 2) % 3], o));
          local.Lo = std::min(local.Lo, angle);
          local.Hi = std::max(local.Hi, angle);
        }
      }
    }
  });
  report.MinimumAngle = std::numeric_limits<double>::infinity();
  report.MaximumAngle = -std::numeric_limits<double>::infinity();
  for (const Local& l : locals)
  {
    report.MinimumAngle = std::min(report.MinimumAngle, l.Lo);
    report.MaximumAngle = std::max(report.MaximumAngle, l.Hi);
    report.InvertedCells += l.Inverted;
  }
  return report;
}

} // namespace labelmesher
