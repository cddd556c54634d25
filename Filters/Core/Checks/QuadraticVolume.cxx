// SPDX-License-Identifier: GPL-2.0-or-later
// Quadratic cells refined into linear ones, det J sampled, and voxels classified.
#include "Checks/QuadraticVolume.h"

#include "Support/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace labelmesher
{
using namespace geometry;
namespace
{

/// VTK_QUADRATIC_TETRA's edges, in its node order (kept here, not taken from the curver's
/// headers: the checks share no code with what they check).
constexpr int kEdge[6][2] = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 1, 3 }, { 2, 3 } };

/// Lagrange quadratic tetrahedron at barycentric l, nodes in VTK's order.
Point3 Map(const std::array<Point3, 10>& x, const double l[4])
{
  Point3 p{ 0.0, 0.0, 0.0 };
  for (int k = 0; k < 4; ++k)
    p = Add(p, Scale(x[k], l[k] * (2.0 * l[k] - 1.0)));
  for (int e = 0; e < 6; ++e)
    p = Add(p, Scale(x[4 + e], 4.0 * l[kEdge[e][0]] * l[kEdge[e][1]]));
  return p;
}

double Volume6(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  return Dot(Sub(b, a), Cross(Sub(c, a), Sub(d, a)));
}

} // namespace

double SampledScaledJacobian(const std::array<Point3, 10>& x, int n, double& smallest)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
      for (int k = 0; i + j + k <= n; ++k)
      {
        const double l[4] = { double(n - i - j - k) / n, double(i) / n, double(j) / n, double(k) / n };
        // dN/dl for every node, then dx/dxi_a = dx/dl_a − dx/dl_0.
        Point3 dl[4] = {};
        for (int c = 0; c < 4; ++c)
          dl[c] = Scale(x[c], 4.0 * l[c] - 1.0);
        for (int e = 0; e < 6; ++e)
        {
          const int a = kEdge[e][0], b = kEdge[e][1];
          dl[a] = Add(dl[a], Scale(x[4 + e], 4.0 * l[b]));
          dl[b] = Add(dl[b], Scale(x[4 + e], 4.0 * l[a]));
        }
        const double det = Dot(Sub(dl[1], dl[0]), Cross(Sub(dl[2], dl[0]), Sub(dl[3], dl[0])));
        lo = std::min(lo, det);
        hi = std::max(hi, det);
      }
  smallest = lo;
  return hi > 0.0 ? lo / hi : -1.0;
}

double MeasuredCornerAngle(const std::array<Point3, 10>& x)
{
  constexpr double t = 0.25;
  double smallest = 180.0;
  for (int k = 0; k < 4; ++k)
  {
    std::array<double, 4> corner{ 0.0, 0.0, 0.0, 0.0 };
    corner[static_cast<std::size_t>(k)] = 1.0;
    const Point3 origin = EvaluateQuadraticTetra(x, corner);
    Point3 tangent[3];
    for (int other = 0, n = 0; other < 4; ++other)
    {
      if (other == k)
        continue;
      auto along = [&](double s) {
        std::array<double, 4> l = corner;
        l[static_cast<std::size_t>(k)] = 1.0 - s;
        l[static_cast<std::size_t>(other)] = s;
        return Scale(Sub(EvaluateQuadraticTetra(x, l), origin), 1.0 / s);
      };
      tangent[n++] = Sub(Scale(along(t), 2.0), along(2.0 * t));
    }
    for (int i = 0; i < 3; ++i)
    {
      // The faces through tangent i are spanned by it and each of the other two.
      const Point3 a = Cross(tangent[i], tangent[(i + 1) % 3]);
      const Point3 b = Cross(tangent[i], tangent[(i + 2) % 3]);
      const double norms = Norm(a) * Norm(b);
      const double angle =
        norms > 0.0 ? std::acos(std::clamp(Dot(a, b) / norms, -1.0, 1.0)) * 180.0 / 3.14159265358979323846 : 0.0;
      smallest = std::min(smallest, angle);
    }
  }
  return smallest;
}

double RefinementTolerance(const QuadraticMesh& mesh, int n)
{
  double bend = 0.0;
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
  {
    const Point3& a = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[e][0])];
    const Point3& b = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[e][1])];
    bend = std::max(bend, Norm(Sub(Add(a, b), Scale(mesh.MidNode(e), 2.0))));
  }
  return 2.0 / 3.0 * bend / (double(n) * n);
}

namespace
{
/// Calls f(p, sorted) for each of the n³ Kuhn (Freudenthal) tetrahedra of cell c at step 1/n:
/// p[s] = (p1 >= p2 >= p3), a point of the ordered simplex n >= p1 >= p2 >= p3 >= 0, with
/// weights (n − p1, p1 − p2, p2 − p3, p3) on the cell's corners in the order `sorted` (by
/// global id, so that neighbours subdivide their common face alike).
template <typename F>
void ForEachKuhnTetrahedron(const QuadraticMesh& mesh, std::size_t c, int n, F&& f)
{
  // Kuhn's tetrahedra of the cube at the origin: from (0,0,0) to (1,1,1) one axis at a time.
  static const int order[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  const std::int64_t* v = mesh.Linear.Cell(c);
  int sorted[4] = { 0, 1, 2, 3 };
  std::sort(sorted, sorted + 4, [&](int a, int b) { return v[a] < v[b]; });
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& axes : order)
        {
          int p[4][3];
          p[0][0] = i, p[0][1] = j, p[0][2] = k;
          for (int s = 1; s < 4; ++s)
          {
            std::copy(p[s - 1], p[s - 1] + 3, p[s]);
            ++p[s][axes[s - 1]];
          }
          bool inside = true;
          for (const auto& q : p)
            inside = inside && n >= q[0] && q[0] >= q[1] && q[1] >= q[2] && q[2] >= 0;
          if (inside)
            f(p, sorted);
        }
}

/// The point of the quadratic cell at lattice point q (weights on the sorted corners).
Point3 LatticePoint(const std::array<Point3, 10>& nodes, const int sorted[4], const int q[3], int n)
{
  const int w[4] = { n - q[0], q[0] - q[1], q[1] - q[2], q[2] };
  double l[4] = { 0, 0, 0, 0 };
  for (int k = 0; k < 4; ++k)
    l[sorted[k]] = double(w[k]) / n;
  return Map(nodes, l);
}
} // namespace

SimplexMesh RefineQuadraticMesh(const QuadraticMesh& mesh, int n)
{
  SimplexMesh out;
  out.Dimension = 3;
  // A lattice point is named by the corners (global ids, ascending) it is a combination of and
  // their integer weights: the same name from every cell around it.
  std::map<std::array<std::int64_t, 8>, std::int64_t> named;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::array<Point3, 10> nodes = mesh.Nodes(c);
    const std::int64_t* v = mesh.Linear.Cell(c);
    ForEachKuhnTetrahedron(mesh, c, n, [&](const int p[4][3], const int sorted[4]) {
      const double orientation = Volume6(nodes[sorted[0]], nodes[sorted[1]], nodes[sorted[2]], nodes[sorted[3]]);
      auto pointId = [&](const int q[3]) {
        const std::int64_t w[4] = { n - q[0], q[0] - q[1], q[1] - q[2], q[2] };
        std::array<std::int64_t, 8> name;
        name.fill(-1);
        int used = 0;
        for (int k = 0; k < 4; ++k)
          if (w[k] > 0)
            name[2 * used] = v[sorted[k]], name[2 * used + 1] = w[k], ++used;
        const auto [it, added] = named.emplace(name, static_cast<std::int64_t>(out.Points.size()));
        if (added)
          out.Points.push_back(LatticePoint(nodes, sorted, q, n));
        return it->second;
      };
      std::int64_t ids[4];
      for (int s = 0; s < 4; ++s)
        ids[s] = pointId(p[s]);
      // Orientation in lattice coordinates times the cell's: the map from the lattice to the
      // straight cell has the sign of `orientation` (its columns are differences of consecutive
      // sorted corners).
      auto lattice = [&](int s) { return Point3{ double(p[s][0]), double(p[s][1]), double(p[s][2]) }; };
      const double sign = Volume6(lattice(0), lattice(1), lattice(2), lattice(3)) * orientation;
      if (sign < 0.0)
        std::swap(ids[1], ids[2]);
      out.Connectivity.insert(out.Connectivity.end(), ids, ids + 4);
      out.Materials.push_back(mesh.Linear.Materials[c]);
    });
  }
  return out;
}

std::vector<BoundaryFacet> CurvedBoundaryFacets(const QuadraticMesh& mesh, int n)
{
  // Every face once per cell, sorted by its corners: a face of two cells comes twice in a row
  // (a sorted list: about 160 bytes a cell against some 400 for a map of every face).
  struct Use
  {
    std::array<std::int64_t, 3> Key;
    std::size_t Cell;
    int Opposite;
  };
  std::vector<Use> uses;
  uses.reserve(mesh.NumberOfCells() * 4);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* v = mesh.Linear.Cell(c);
    for (int k = 0; k < 4; ++k)
    {
      std::array<std::int64_t, 3> key{ v[(k + 1) % 4], v[(k + 2) % 4], v[(k + 3) % 4] };
      std::sort(key.begin(), key.end());
      uses.push_back({ key, c, k });
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) {
    return a.Key != b.Key ? a.Key < b.Key : a.Cell < b.Cell;
  });
  // Each curved face at the coarsest step within the tolerance stated for step 1/n, which the
  // most bent edge sets: (2/3) bend / m² for a face of its own largest bend, at step 1/m.
  double largestBend = 0.0;
  auto bendOf = [&](std::size_t e) {
    const Point3& a = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[e][0])];
    const Point3& b = mesh.Linear.Points[static_cast<std::size_t>(mesh.Edges[e][1])];
    return Norm(Sub(Add(a, b), Scale(mesh.MidNode(e), 2.0)));
  };
  for (std::size_t e = 0; e < mesh.Edges.size(); ++e)
    largestBend = std::max(largestBend, bendOf(e));
  std::vector<BoundaryFacet> facets;
  for (std::size_t u = 0; u < uses.size();)
  {
    std::size_t next = u + 1;
    while (next < uses.size() && uses[next].Key == uses[u].Key)
      ++next;
    const Use& side = uses[u];
    const std::int32_t here = mesh.Linear.Materials[side.Cell];
    const std::int32_t there = next - u >= 2 ? mesh.Linear.Materials[uses[u + 1].Cell] : 0;
    u = next;
    if (here == there)
      continue;
    const std::array<Point3, 10> nodes = mesh.Nodes(side.Cell);
    // The face's own bend; a face whose three edges are straight is its flat triangle: one facet.
    double bend = 0.0;
    for (int e = 0; e < 6; ++e)
      if (kTetraEdges[e][0] != side.Opposite && kTetraEdges[e][1] != side.Opposite)
        bend = std::max(bend, bendOf(static_cast<std::size_t>(mesh.CellEdges[side.Cell * 6 + static_cast<std::size_t>(e)])));
    // (The 1e-9 keeps an exact ratio from taking one step more; the excess it may allow, a relative
    // 2e-9 of the tolerance, is far inside the measure's stated 1/1024.)
    const int m = bend > 0.0 ? std::clamp(static_cast<int>(std::ceil(n * std::sqrt(bend / largestBend) - 1e-9)), 1, n) : 1;
    // The face's lattice: weights on its three corners (the cell's others), 0 on the opposite one.
    int corner[3], used = 0;
    for (int k = 0; k < 4; ++k)
      if (k != side.Opposite)
        corner[used++] = k;
    auto at = [&](int i, int j) {
      double l[4] = { 0, 0, 0, 0 };
      l[corner[0]] = double(m - i - j) / m, l[corner[1]] = double(i) / m, l[corner[2]] = double(j) / m;
      return Map(nodes, l);
    };
    for (int j = 0; j < m; ++j)
      for (int i = 0; i + j < m; ++i)
      {
        facets.push_back({ { at(i, j), at(i + 1, j), at(i, j + 1) }, here, there });
        if (i + j + 1 < m)
          facets.push_back({ { at(i + 1, j), at(i + 1, j + 1), at(i, j + 1) }, here, there });
      }
  }
  return facets;
}

namespace
{
constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::min();

/// Every voxel centre in the tetrahedron p not claimed yet goes to `material`.
void Claim(const LabelImage& image, const Point3 p[4], std::int64_t material, std::vector<std::int64_t>& claimed)
{
  const double volume = Volume6(p[0], p[1], p[2], p[3]);
  if (!(std::fabs(volume) > 0.0))
    return;
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a)
  {
    const double mn = std::min({ p[0][a], p[1][a], p[2][a], p[3][a] });
    const double mx = std::max({ p[0][a], p[1][a], p[2][a], p[3][a] });
    lo[a] = std::max(0, static_cast<int>(std::ceil(mn - 1e-9)));
    hi[a] = std::min(image.Dimensions[a] - 1, static_cast<int>(std::floor(mx + 1e-9)));
  }
  const double tolerance = 1e-12 * std::fabs(volume);
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i)
      {
        const Point3 x{ double(i), double(j), double(k) };
        // Barycentric weights as signed sub-volumes, each of the cell's sign when inside.
        const double w[4] = { Volume6(x, p[1], p[2], p[3]), Volume6(p[0], x, p[2], p[3]),
          Volume6(p[0], p[1], x, p[3]), Volume6(p[0], p[1], p[2], x) };
        bool inside = true;
        for (double wk : w)
          inside = inside && wk * (volume > 0 ? 1.0 : -1.0) >= -tolerance;
        if (!inside)
          continue;
        std::int64_t& owner = claimed[image.Index(i, j, k)];
        if (owner == kNone)
          owner = material;
      }
}

VoxelAccuracy Count(const LabelImage& image, const std::vector<std::int64_t>& claimed)
{
  VoxelAccuracy accuracy;
  accuracy.Voxels = claimed.size();
  for (int k = 0; k < image.Dimensions[2]; ++k)
    for (int j = 0; j < image.Dimensions[1]; ++j)
      for (int i = 0; i < image.Dimensions[0]; ++i)
      {
        const std::int64_t owner = claimed[image.Index(i, j, k)];
        accuracy.Misclassified += (owner == kNone ? 0 : owner) != image.At(i, j, k) ? 1 : 0;
      }
  return accuracy;
}
} // namespace

VoxelAccuracy MeasureVoxelAccuracy(const LabelImage& image, const SimplexMesh& mesh)
{
  std::vector<std::int64_t> claimed(image.NumberOfVoxels(), kNone);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::int64_t* v = mesh.Cell(c);
    Point3 p[4];
    for (int k = 0; k < 4; ++k)
      p[k] = mesh.Points[static_cast<std::size_t>(v[k])];
    Claim(image, p, mesh.Materials[c], claimed);
  }
  return Count(image, claimed);
}

VoxelAccuracy MeasureVoxelAccuracy(const LabelImage& image, const QuadraticMesh& mesh, int n)
{
  // The cells of RefineQuadraticMesh(mesh, n), in its order, one at a time (nothing held but
  // the claims); a straight cell is its own union of sub-cells.
  std::vector<std::int64_t> claimed(image.NumberOfVoxels(), kNone);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::array<Point3, 10> nodes = mesh.Nodes(c);
    const std::int64_t material = mesh.Linear.Materials[c];
    if (!mesh.CellIsCurved(c))
    {
      const Point3 p[4] = { nodes[0], nodes[1], nodes[2], nodes[3] };
      Claim(image, p, material, claimed);
      continue;
    }
    ForEachKuhnTetrahedron(mesh, c, n, [&](const int q[4][3], const int sorted[4]) {
      Point3 p[4];
      for (int s = 0; s < 4; ++s)
        p[s] = LatticePoint(nodes, sorted, q[s], n);
      Claim(image, p, material, claimed);
    });
  }
  return Count(image, claimed);
}

} // namespace labelmesher
