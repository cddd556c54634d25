// SPDX-License-Identifier: GPL-2.0-or-later
// Least-squares offsets of interface mid-nodes against the image's voxel faces.
#include "Quadratic/InterfaceFit.h"

#include "Support/BoxBins.h"
#include "Support/Geometry.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace labelmesher
{
using namespace geometry;
namespace
{

/// Barycentric coordinates of p's projection onto the triangle's plane,
/// clamped into the triangle (negative weights dropped, the rest renormalised).
std::array<double, 3> ClampedBarycentric(const Point3& p, const Point3& a, const Point3& b, const Point3& c)
{
  const Point3 ab = Sub(b, a), ac = Sub(c, a), ap = Sub(p, a);
  const double d00 = Dot(ab, ab), d01 = Dot(ab, ac), d11 = Dot(ac, ac);
  const double d20 = Dot(ap, ab), d21 = Dot(ap, ac);
  const double det = d00 * d11 - d01 * d01;
  if (det <= 0.0)
    return { 1.0 / 3, 1.0 / 3, 1.0 / 3 };
  const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
  std::array<double, 3> l{ std::max(0.0, 1.0 - v - w), std::max(0.0, v), std::max(0.0, w) };
  const double sum = l[0] + l[1] + l[2];
  for (double& x : l)
    x /= sum;
  return l;
}

} // namespace

std::size_t FitInterfaceMidNodes(QuadraticMesh& mesh, const std::vector<MaterialFace>& faces,
  const std::vector<char>& curvable, const LabelImage& image, const InterfaceFitOptions& options)
{
  const auto& P = mesh.Linear.Points;
  auto point = [&](std::int64_t id) -> const Point3& { return P[static_cast<std::size_t>(id)]; };
  // Each curvable edge's direction: the mean of its two faces' unit normals.
  std::vector<Point3> direction(mesh.Edges.size(), Point3{ 0.0, 0.0, 0.0 });
  std::vector<Point3> normals(faces.size());
  BoxBins3 bins(4.0);
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    if (faces[f].OnBox)
      continue;
    normals[f] = FaceNormal(mesh, faces[f]);
    for (std::int64_t e : faces[f].Edges)
      if (curvable[static_cast<std::size_t>(e)])
        direction[static_cast<std::size_t>(e)] = Add(direction[static_cast<std::size_t>(e)], normals[f]);
    // Every interface face is binned: a sample nearest to a straight one is not fitted at all
    // (rather than to a farther curved face).
    std::array<double, 3> lo, hi;
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min({ point(faces[f].Points[0])[a], point(faces[f].Points[1])[a], point(faces[f].Points[2])[a] }) - options.Reach;
      hi[a] = std::max({ point(faces[f].Points[0])[a], point(faces[f].Points[1])[a], point(faces[f].Points[2])[a] }) + options.Reach;
    }
    bins.Insert(f, lo, hi);
  }
  // Unknowns: the curvable edges, numbered.
  std::vector<int> unknown(mesh.Edges.size(), -1);
  int unknowns = 0;
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
  {
    const double length = Norm(direction[e]);
    if (curvable[e] && length > 1e-12)
    {
      direction[e] = Scale(direction[e], 1.0 / length);
      unknown[e] = unknowns++;
    }
  }
  if (unknowns == 0)
    return 0;

  std::vector<Eigen::Triplet<double>> normal;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  const double reach2 = options.Reach * options.Reach;
  auto addSample = [&](const Point3& s, std::int32_t p, std::int32_t q) {
    const std::int32_t below = std::min(p, q), above = std::max(p, q);
    double best = reach2;
    std::size_t nearest = faces.size();
    for (std::size_t f : bins.At({ s[0], s[1], s[2] }))
    {
      const MaterialFace& face = faces[f];
      if (face.Below != below || face.Above != above)
        continue;
      const double d2 = SquaredDistanceToTriangle(s, point(face.Points[0]), point(face.Points[1]), point(face.Points[2]));
      if (d2 < best)
        best = d2, nearest = f;
    }
    if (nearest == faces.size())
      return;
    const MaterialFace& face = faces[nearest];
    const Point3 &a = point(face.Points[0]), &b = point(face.Points[1]), &c = point(face.Points[2]);
    const std::array<double, 3> l = ClampedBarycentric(s, a, b, c);
    const Point3 flat = Add(Add(Scale(a, l[0]), Scale(b, l[1])), Scale(c, l[2]));
    const double residual = Dot(Sub(s, flat), normals[nearest]);
    // Edge j is opposite corner j: its quadratic weight is 4 l_{j+1} l_{j+2}.
    int ids[3];
    double row[3];
    int used = 0;
    for (int j = 0; j < 3; ++j)
    {
      const auto e = static_cast<std::size_t>(face.Edges[j]);
      if (unknown[e] < 0)
        continue;
      ids[used] = unknown[e];
      row[used++] = 4.0 * l[(j + 1) % 3] * l[(j + 2) % 3] * Dot(direction[e], normals[nearest]);
    }
    for (int i = 0; i < used; ++i)
    {
      rhs[ids[i]] += row[i] * residual;
      for (int k = 0; k < used; ++k)
        normal.emplace_back(ids[i], ids[k], row[i] * row[k]);
    }
  };
  // Voxel faces between two labels inside the image; voxel centres are at integer coordinates.
  const int nx = image.Dimensions[0], ny = image.Dimensions[1], nz = image.Dimensions[2];
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        const std::int32_t here = image.At(i, j, k);
        if (i + 1 < nx && image.At(i + 1, j, k) != here)
          addSample({ i + 0.5, double(j), double(k) }, here, image.At(i + 1, j, k));
        if (j + 1 < ny && image.At(i, j + 1, k) != here)
          addSample({ double(i), j + 0.5, double(k) }, here, image.At(i, j + 1, k));
        if (k + 1 < nz && image.At(i, j, k + 1) != here)
          addSample({ double(i), double(j), k + 0.5 }, here, image.At(i, j, k + 1));
      }
  for (int u = 0; u < unknowns; ++u)
    normal.emplace_back(u, u, options.Regularization);
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(normal.begin(), normal.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
  if (solver.info() != Eigen::Success)
    return 0;
  const Eigen::VectorXd d = solver.solve(rhs);
  std::size_t fitted = 0;
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
  {
    if (unknown[e] < 0 || !std::isfinite(d[unknown[e]]))
      continue;
    const double length = Distance(point(mesh.Edges[e][0]), point(mesh.Edges[e][1]));
    const double limit = options.MaximumOffset * length;
    const double offset = std::clamp(d[unknown[e]], -limit, limit);
    if (std::fabs(offset) < 1e-6)
      continue;
    mesh.Offset[e] = Scale(direction[e], offset);
    mesh.Scales[e] = 1.0;
    ++fitted;
  }
  return fitted;
}

} // namespace labelmesher
