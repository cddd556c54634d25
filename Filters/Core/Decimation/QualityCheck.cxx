// SPDX-License-Identifier: GPL-2.0-or-later
// Requirement 1 of section 3.1.3: exact orientation and the angle bound of the cells a merge moves.
#include "Decimation/QualityCheck.h"

#include <algorithm>
#include <cmath>

namespace labelmesher
{
namespace
{

using Vec = std::array<double, 3>;

Vec Sub(const Lattice& a, const Lattice& b)
{
  return { double(a[0] - b[0]), double(a[1] - b[1]), double(a[2] - b[2]) };
}
Vec Cross(const Vec& a, const Vec& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
double Dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

} // namespace

/// Dihedral angles from the outward face normals: cos(dihedral at an edge) =
/// -n_k . n_l over the two faces k, l at the edge.
double QualityCheck::LargestCosine(int dimension, const Lattice* p)
{
  double largest = -1.0;
  if (dimension == 2)
  {
    for (int i = 0; i < 3; ++i)
    {
      const Vec u = Sub(p[(i + 1) % 3], p[i]), v = Sub(p[(i + 2) % 3], p[i]);
      largest = std::max(largest, Dot(u, v) / std::sqrt(Dot(u, u) * Dot(v, v)));
    }
    return largest;
  }
  // For a positively oriented tetrahedron, the normal of face i computed as
  // (q1 - q0) x (q2 - q0) with the face's vertices in the order below points
  // outward.
  static const int faces[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
  Vec n[4];
  double length[4];
  for (int i = 0; i < 4; ++i)
  {
    n[i] = Cross(Sub(p[faces[i][1]], p[faces[i][0]]), Sub(p[faces[i][2]], p[faces[i][0]]));
    length[i] = std::sqrt(Dot(n[i], n[i]));
  }
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l)
      largest = std::max(largest, -Dot(n[k], n[l]) / (length[k] * length[l]));
  return largest;
}

QualityCheck::QualityCheck(int dimension, double minimumAngle)
  : Dimension(dimension)
  , CosineBound(std::cos(minimumAngle * 3.14159265358979323846 / 180.0))
{
}

void QualityCheck::Prepare(const EditableMesh& mesh, VertexId from)
{
  Faces.clear();
  const Lattice& a = mesh.Position[from];
  for (CellId c : mesh.CellsOf[from])
  {
    Lattice q[3] = {}; // q[2] unused in 2D
    int n = 0;
    for (int i = 0; i <= Dimension; ++i)
      if (mesh.Cells[c][i] != from)
        q[n++] = mesh.Position[mesh.Cells[c][i]];
    OppositeFace face{ c, q[0], { 0, 0, 0 } };
    if (Dimension == 2)
    {
      // The normal of the line through q0 q1 in the plane.
      face.Normal = { -(long long)(q[1][1] - q[0][1]), (long long)(q[1][0] - q[0][0]), 0 };
    }
    else
    {
      const long long ux = q[1][0] - q[0][0], uy = q[1][1] - q[0][1], uz = q[1][2] - q[0][2];
      const long long vx = q[2][0] - q[0][0], vy = q[2][1] - q[0][1], vz = q[2][2] - q[0][2];
      face.Normal = { uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx };
    }
    const __int128 side = __int128(face.Normal[0]) * (a[0] - q[0][0]) + __int128(face.Normal[1]) * (a[1] - q[0][1]) +
      __int128(face.Normal[2]) * (a[2] - q[0][2]);
    if (side < 0)
      for (auto& x : face.Normal)
        x = -x;
    Faces.push_back(face);
  }
}

bool QualityCheck::OrientationsHold(const EditableMesh& mesh, VertexId to) const
{
  // Products of coordinates below 2^24 fit 128 bits.
  const Lattice& b = mesh.Position[to];
  for (const OppositeFace& f : Faces)
  {
    if (mesh.Contains(f.Cell, to))
      continue; // vanishes
    const __int128 side = __int128(f.Normal[0]) * (b[0] - f.Point[0]) + __int128(f.Normal[1]) * (b[1] - f.Point[1]) +
      __int128(f.Normal[2]) * (b[2] - f.Point[2]);
    if (side <= 0)
      return false;
  }
  return true;
}

bool QualityCheck::AnglesHold(const EditableMesh& mesh, const EdgeCollapse& merge) const
{
  Lattice p[4];
  for (const auto& cell : merge.MovedCells)
  {
    for (int i = 0; i <= Dimension; ++i)
      p[i] = mesh.Position[cell[i]];
    if (LargestCosine(Dimension, p) > CosineBound)
      return false;
  }
  return true;
}

double QualityCheck::SmallestAngle(int dimension, const Lattice* points)
{
  return AngleOfCosine(LargestCosine(dimension, points));
}

double QualityCheck::AngleOfCosine(double cosine)
{
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

} // namespace labelmesher
