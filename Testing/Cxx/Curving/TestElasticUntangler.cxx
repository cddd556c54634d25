// SPDX-License-Identifier: GPL-2.0-or-later
// MakeStraightCurvedMesh and UntangleControlNets (dissertation section 4.3,
// Figures 20-21): the straight control-point layout; equilibrium of the
// elastic control nets checked against a stiffness assembled here (also on a
// badly conditioned body); the affine patch test; a one-element case the
// one-step method leaves tangled and the iterative method untangles; an
// annulus with both circles curved; bends no load schedule can untangle;
// progress, abort, degenerate control triangles and bad input.
#include "Curving/CurvedMesh.h"
#include "Curving/ElasticUntangler.h"
#include "Curving/JacobianBound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace labelmesher;

namespace
{
const double Pi = 3.14159265358979323846;

using Prescribed = std::vector<std::pair<std::int64_t, Point2>>;

SimplexMesh Triangles(const std::vector<Point3>& points, const std::vector<std::int64_t>& conn)
{
  SimplexMesh m;
  m.Dimension = 2;
  m.Points = points;
  m.Connectivity = conn;
  m.Materials.assign(conn.size() / 3, 1);
  return m;
}

/// nx × ny unit squares, each split along its (i, j)-(i+1, j+1) diagonal, counter-clockwise.
SimplexMesh Grid(int nx, int ny)
{
  std::vector<Point3> points;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      points.push_back({ double(i), double(j), 0.0 });
  std::vector<std::int64_t> conn;
  auto id = [nx](int i, int j) { return std::int64_t(j) * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      conn.insert(conn.end(),
        { id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i, j + 1) });
  return Triangles(points, conn);
}

/// An annulus centred at the origin: `n` vertices on every circle of `radii`
/// (innermost first), quads between circles split into two triangles.
SimplexMesh Annulus(int n, const std::vector<double>& radii)
{
  std::vector<Point3> points;
  for (double r : radii)
    for (int i = 0; i < n; ++i)
      points.push_back({ r * std::cos(2 * Pi * i / n), r * std::sin(2 * Pi * i / n), 0.0 });
  std::vector<std::int64_t> conn;
  for (std::int64_t k = 0; k + 1 < std::int64_t(radii.size()); ++k)
    for (std::int64_t i = 0; i < n; ++i)
    {
      const std::int64_t a = k * n + i, b = k * n + (i + 1) % n, c = (k + 1) * n + (i + 1) % n,
                         d = (k + 1) * n + i;
      conn.insert(conn.end(), { a, d, c, a, c, b });
    }
  return Triangles(points, conn);
}

/// Targets that turn the edges of circle `ring` of an Annulus into cubic arcs:
/// inner control points along the circle's tangents at the ends, at distance
/// (4/3) tan(θ/4) r for an arc of angle θ (the standard circle approximation).
void AddCircleTargets(const CurvedMesh& curved, int n, int ring, double r, Prescribed& prescribed)
{
  const double handle = 4.0 / 3.0 * std::tan(2 * Pi / n / 4) * r;
  for (int i = 0; i < n; ++i)
  {
    const double a = 2 * Pi * i / n, b = 2 * Pi * (i + 1) / n;
    const auto ids = curved.EdgePoints(ring * n + i, ring * n + (i + 1) % n);
    prescribed.emplace_back(ids[0], Point2{ r * std::cos(a) - handle * std::sin(a), r * std::sin(a) + handle * std::cos(a) });
    prescribed.emplace_back(ids[1], Point2{ r * std::cos(b) + handle * std::sin(b), r * std::sin(b) - handle * std::cos(b) });
  }
}

/// Mesh edges (a < b) and how many cells use them.
std::map<std::pair<std::int64_t, std::int64_t>, int> EdgeUses(const SimplexMesh& mesh)
{
  std::map<std::pair<std::int64_t, std::int64_t>, int> uses;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    for (int e = 0; e < 3; ++e)
    {
      const std::int64_t a = mesh.Cell(c)[e], b = mesh.Cell(c)[(e + 1) % 3];
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  return uses;
}

std::vector<std::size_t> CellsNotProvenValid(const CurvedMesh& mesh)
{
  std::vector<std::size_t> cells;
  for (std::size_t c = 0; c < mesh.Cells.size(); ++c)
    if (ClassifyValidity(mesh.Cell(c)) != Validity::Valid)
      cells.push_back(c);
  return cells;
}

/// Smallest det J on a barycentric grid, relative to the largest: an
/// independent (sampled) witness of validity or invalidity.
double SampledRelativeMinimumJacobian(const CubicTriangle& triangle)
{
  const int n = 30;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j)
    {
      const double d = EvaluateJacobian(triangle, double(i) / n, double(j) / n, double(n - i - j) / n);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  return lo / std::abs(hi);
}

/// The control points the untangler may move: not vertices, not on a
/// mesh-boundary edge, not prescribed.
std::vector<char> FreePoints(const SimplexMesh& linear, const CurvedMesh& curved, const Prescribed& prescribed)
{
  std::vector<char> free(curved.ControlPoints.size(), 1);
  for (std::int64_t v = 0; v < curved.NumberOfVertices; ++v)
    free[v] = 0;
  for (const auto& [edge, uses] : EdgeUses(linear))
    if (uses == 1)
      for (std::int64_t id : curved.EdgeControlPoints.at(edge))
        free[id] = 0;
  for (const auto& [id, target] : prescribed)
    free[id] = 0;
  return free;
}

/// Residual forces at the free control points of the body in `before` deformed
/// to `after`, relative to the largest element force: P1 plane strain with
/// Young's modulus proportional to 1 / area (ElasticUntangler.cxx), assembled
/// here in the Lamé form K_ij = A E (λ ∇φ_i ⊗ ∇φ_j + μ ∇φ_j ⊗ ∇φ_i + μ ∇φ_i·∇φ_j I)
/// (λ, μ for E = 1), where A E is the same constant for every sub-triangle.
double RelativeResidual(const CurvedMesh& before, const CurvedMesh& after, const std::vector<char>& free, double nu)
{
  // Control triangles of a cubic net in VTK slots: six upward, three downward.
  const int net[9][3] = { { 0, 3, 8 }, { 3, 4, 9 }, { 4, 1, 5 }, { 8, 9, 7 }, { 9, 5, 6 }, { 7, 6, 2 },
    { 9, 8, 3 }, { 5, 9, 4 }, { 6, 7, 9 } };
  const double lambda = nu / ((1 + nu) * (1 - 2 * nu)), mu = 1 / (2 * (1 + nu));
  std::vector<Point2> force(before.ControlPoints.size(), Point2{ 0.0, 0.0 });
  double largest = 0.0;
  for (const auto& cell : before.Cells)
    for (const auto& t : net)
    {
      const Point2* p[3];
      Point2 u[3];
      for (int i = 0; i < 3; ++i)
      {
        p[i] = &before.ControlPoints[cell[t[i]]];
        u[i] = { after.ControlPoints[cell[t[i]]][0] - (*p[i])[0], after.ControlPoints[cell[t[i]]][1] - (*p[i])[1] };
      }
      const double area2 = ((*p[1])[0] - (*p[0])[0]) * ((*p[2])[1] - (*p[0])[1]) -
        ((*p[1])[1] - (*p[0])[1]) * ((*p[2])[0] - (*p[0])[0]);
      Point2 g[3]; // ∇φ_i
      for (int i = 0; i < 3; ++i)
      {
        const Point2 &q = *p[(i + 1) % 3], &r = *p[(i + 2) % 3];
        g[i] = { (q[1] - r[1]) / area2, (r[0] - q[0]) / area2 };
      }
      for (int i = 0; i < 3; ++i)
      {
        Point2 f{ 0.0, 0.0 };
        for (int j = 0; j < 3; ++j)
          for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b)
              f[a] += (lambda * g[i][a] * g[j][b] + mu * g[i][b] * g[j][a] + (a == b ? mu * (g[i][0] * g[j][0] + g[i][1] * g[j][1]) : 0.0)) * u[j][b];
        force[cell[t[i]]][0] += f[0];
        force[cell[t[i]]][1] += f[1];
        largest = std::max({ largest, std::abs(f[0]), std::abs(f[1]) });
      }
    }
  double residual = 0.0;
  for (std::size_t p = 0; p < force.size(); ++p)
    if (free[p])
      residual = std::max({ residual, std::abs(force[p][0]), std::abs(force[p][1]) });
  return residual / largest;
}

void ExpectAt(const CurvedMesh& mesh, const Prescribed& prescribed)
{
  for (const auto& [id, target] : prescribed)
  {
    EXPECT_EQ(mesh.ControlPoints[id][0], target[0]) << "control point " << id;
    EXPECT_EQ(mesh.ControlPoints[id][1], target[1]) << "control point " << id;
  }
}
} // namespace

TEST(CurvedMesh, StraightLayout)
{
  const SimplexMesh linear = Grid(3, 2);
  const CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const auto uses = EdgeUses(linear);
  const std::size_t V = linear.Points.size(), E = uses.size(), C = linear.NumberOfCells();
  ASSERT_EQ(E, V + C - 1); // Euler: a disc
  ASSERT_EQ(curved.ControlPoints.size(), V + 2 * E + C);
  ASSERT_EQ(curved.NumberOfVertices, std::int64_t(V));
  ASSERT_EQ(curved.Cells.size(), C);
  EXPECT_EQ(curved.Materials, linear.Materials);
  EXPECT_EQ(curved.EdgeControlPoints.size(), E);

  for (std::size_t v = 0; v < V; ++v)
  {
    EXPECT_EQ(curved.ControlPoints[v][0], linear.Points[v][0]);
    EXPECT_EQ(curved.ControlPoints[v][1], linear.Points[v][1]);
  }
  // Edge points at 1/3 and 2/3 from the smaller id, ids in [V, V + 2E).
  std::set<std::int64_t> edgeIds;
  for (const auto& [edge, ids] : curved.EdgeControlPoints)
  {
    const Point2 a = curved.ControlPoints[edge.first], b = curved.ControlPoints[edge.second];
    for (int k = 0; k < 2; ++k)
    {
      EXPECT_GE(ids[k], std::int64_t(V));
      EXPECT_LT(ids[k], std::int64_t(V + 2 * E));
      edgeIds.insert(ids[k]);
      const double t = (k + 1) / 3.0;
      EXPECT_NEAR(curved.ControlPoints[ids[k]][0], a[0] + t * (b[0] - a[0]), 1e-15);
      EXPECT_NEAR(curved.ControlPoints[ids[k]][1], a[1] + t * (b[1] - a[1]), 1e-15);
    }
    const auto forward = curved.EdgePoints(edge.first, edge.second);
    const auto backward = curved.EdgePoints(edge.second, edge.first);
    EXPECT_EQ(forward, ids);
    EXPECT_EQ(backward[0], ids[1]);
    EXPECT_EQ(backward[1], ids[0]);
  }
  EXPECT_EQ(edgeIds.size(), 2 * E); // no edge point shared by two edges
  EXPECT_THROW(curved.EdgePoints(0, 2), std::out_of_range); // (0,0)-(2,0) is no edge
  // Cells: corners, then edge 0→1, 1→2, 2→0 each from its first corner, then the centroid.
  std::set<std::int64_t> interiorIds;
  std::map<std::int64_t, int> edgePointUses;
  for (std::size_t c = 0; c < C; ++c)
  {
    const std::int64_t* v = linear.Cell(c);
    const auto& ids = curved.Cells[c];
    for (int e = 0; e < 3; ++e)
    {
      EXPECT_EQ(ids[e], v[e]);
      const auto edge = curved.EdgePoints(v[e], v[(e + 1) % 3]);
      EXPECT_EQ(ids[3 + 2 * e], edge[0]);
      EXPECT_EQ(ids[4 + 2 * e], edge[1]);
      ++edgePointUses[edge[0]];
      ++edgePointUses[edge[1]];
    }
    EXPECT_GE(ids[9], std::int64_t(V + 2 * E));
    interiorIds.insert(ids[9]);
    const CubicTriangle cell = curved.Cell(c);
    const Point2 &a = cell.ControlPoints[0], &b = cell.ControlPoints[1], &d = cell.ControlPoints[2];
    EXPECT_NEAR(cell.ControlPoints[9][0], (a[0] + b[0] + d[0]) / 3, 1e-15);
    EXPECT_NEAR(cell.ControlPoints[9][1], (a[1] + b[1] + d[1]) / 3, 1e-15);
    const CubicTriangle straight = StraightCubicTriangle(a, b, d);
    for (int k = 0; k < 10; ++k)
    {
      EXPECT_NEAR(cell.ControlPoints[k][0], straight.ControlPoints[k][0], 1e-15) << "cell " << c << " slot " << k;
      EXPECT_NEAR(cell.ControlPoints[k][1], straight.ControlPoints[k][1], 1e-15) << "cell " << c << " slot " << k;
    }
    EXPECT_EQ(ClassifyValidity(cell), Validity::Valid);
    EXPECT_NEAR(BoundJacobian(cell).ScaledJacobian(), 1.0, 1e-12);
  }
  EXPECT_EQ(interiorIds.size(), C);
  // Interior edges share their points between both cells, boundary edges do not.
  for (const auto& [edge, count] : uses)
    for (std::int64_t id : curved.EdgeControlPoints.at(edge))
      EXPECT_EQ(edgePointUses[id], count);
}

TEST(CurvedMesh, RejectsTetrahedra)
{
  SimplexMesh tets;
  tets.Dimension = 3;
  EXPECT_THROW(MakeStraightCurvedMesh(tets), std::invalid_argument);
}

TEST(ElasticUntangler, ZeroDisplacementLeavesPointsUnchanged)
{
  const SimplexMesh linear = Grid(3, 3);
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const std::vector<Point2> original = curved.ControlPoints;
  Prescribed prescribed;
  for (const auto& [edge, uses] : EdgeUses(linear))
    if (uses == 1)
      for (std::int64_t id : curved.EdgeControlPoints.at(edge))
        prescribed.emplace_back(id, curved.ControlPoints[id]);
  for (const Prescribed& p : { prescribed, Prescribed{} })
  {
    const UntanglingResult result = UntangleControlNets(curved, p, {});
    EXPECT_TRUE(result.Valid);
    EXPECT_EQ(result.Steps, 0);
    EXPECT_TRUE(result.InvalidCells.empty());
    EXPECT_NEAR(result.MinimumScaledJacobian, 1.0, 1e-12);
    EXPECT_EQ(curved.ControlPoints, original);
  }
}

TEST(ElasticUntangler, FreePointsAreInEquilibrium)
{
  // A jittered grid (sub-triangles of many areas) whose bottom edges bulge
  // smoothly inward; solved in one step, the free points must carry no net force.
  SimplexMesh linear = Grid(4, 4);
  for (Point3& p : linear.Points)
    if (p[0] > 0 && p[0] < 4 && p[1] > 0 && p[1] < 4)
    {
      p[0] += 0.2 * std::sin(1.7 * p[0] + 2.3 * p[1]);
      p[1] += 0.2 * std::cos(2.9 * p[0] - 1.1 * p[1]);
    }
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const CurvedMesh before = curved;
  Prescribed prescribed;
  for (std::int64_t i = 0; i < 4; ++i)
  {
    const auto ids = curved.EdgePoints(i, i + 1);
    for (std::int64_t id : ids)
    {
      const Point2 p = curved.ControlPoints[id];
      prescribed.emplace_back(id, Point2{ p[0], 0.25 * std::sin(Pi * p[0] / 4) });
    }
  }
  for (double nu : { 0.0, 0.3, 0.45 })
  {
    SCOPED_TRACE("Poisson ratio " + std::to_string(nu));
    curved = before;
    UntanglingOptions options;
    options.PoissonRatio = nu;
    const UntanglingResult result = UntangleControlNets(curved, prescribed, options);
    ASSERT_TRUE(result.Valid);
    ASSERT_EQ(result.Steps, 1);
    ExpectAt(curved, prescribed);
    const std::vector<char> free = FreePoints(linear, before, prescribed);
    std::size_t moved = 0;
    for (std::size_t p = 0; p < free.size(); ++p)
    {
      if (free[p])
      {
        moved += curved.ControlPoints[p] != before.ControlPoints[p];
        continue;
      }
      const bool isPrescribed = std::any_of(
        prescribed.begin(), prescribed.end(), [p](const auto& q) { return q.first == std::int64_t(p); });
      EXPECT_TRUE(isPrescribed || curved.ControlPoints[p] == before.ControlPoints[p]) << "control point " << p;
    }
    EXPECT_GT(moved, 0u);
    EXPECT_LT(RelativeResidual(before, curved, free, nu), 1e-8);
    // A displaced free point is no equilibrium: the check can fail.
    CurvedMesh disturbed = curved;
    const std::int64_t someFree = std::find(free.begin(), free.end(), 1) - free.begin();
    disturbed.ControlPoints[someFree][0] += 1e-3;
    EXPECT_GT(RelativeResidual(before, disturbed, free, nu), 1e-5);
  }
}

TEST(ElasticUntangler, AffineMotionIsReproduced)
{
  // Patch test: all vertices and mesh-boundary edge points follow an affine
  // map; linear elasticity reproduces it exactly at the free points. (Equal
  // cells, so the 1/area stiffening is the same in every sub-triangle.)
  const SimplexMesh linear = Grid(3, 3);
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const CurvedMesh before = curved;
  auto map = [](const Point2& p) {
    return Point2{ 1.1 * p[0] + 0.3 * p[1] + 0.5, -0.2 * p[0] + 0.9 * p[1] - 0.25 };
  };
  Prescribed prescribed;
  const std::vector<char> free = FreePoints(linear, curved, {});
  for (std::size_t p = 0; p < free.size(); ++p)
    if (!free[p])
      prescribed.emplace_back(std::int64_t(p), map(curved.ControlPoints[p]));
  ASSERT_LT(prescribed.size(), curved.ControlPoints.size());
  const UntanglingResult result = UntangleControlNets(curved, prescribed, {});
  EXPECT_TRUE(result.Valid);
  EXPECT_EQ(result.Steps, 1);
  for (std::size_t p = 0; p < curved.ControlPoints.size(); ++p)
  {
    const Point2 expected = map(before.ControlPoints[p]);
    EXPECT_NEAR(curved.ControlPoints[p][0], expected[0], 1e-9) << "control point " << p;
    EXPECT_NEAR(curved.ControlPoints[p][1], expected[1], 1e-9) << "control point " << p;
  }
  EXPECT_NEAR(result.MinimumScaledJacobian, 1.0, 1e-9); // affine images of straight cells
}

TEST(ElasticUntangler, IterativeMethodUntanglesWhatOneStepCannot)
{
  // Figure 21: one element; the first control point of its bottom edge is
  // pulled far inward (past the apex height), its vertices stay. Only the
  // interior control point is free. Applied at once, the equilibrium leaves
  // det J negative somewhere; applied in 4 fractions, each on the body the
  // previous one deformed, the element is valid.
  const SimplexMesh linear = Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 } }, { 0, 1, 2 });
  const CurvedMesh straight = MakeStraightCurvedMesh(linear);
  const Prescribed prescribed{ { straight.EdgePoints(0, 1)[0], Point2{ 0.75, 1.3 } } };

  CurvedMesh boundaryOnly = straight;
  boundaryOnly.ControlPoints[prescribed[0].first] = prescribed[0].second;
  EXPECT_NE(ClassifyValidity(boundaryOnly.Cell(0)), Validity::Valid);

  for (int maximum : { 1, 2 })
  {
    CurvedMesh few = straight;
    UntanglingOptions options;
    options.MaximumSteps = maximum;
    const UntanglingResult result = UntangleControlNets(few, prescribed, options);
    EXPECT_FALSE(result.Valid) << maximum << " fractions";
    EXPECT_EQ(result.InvalidCells, std::vector<std::size_t>{ 0 });
    EXPECT_EQ(ClassifyValidity(few.Cell(0)), Validity::Invalid);
    EXPECT_LT(SampledRelativeMinimumJacobian(few.Cell(0)), -0.1); // clearly tangled
    EXPECT_LE(result.MinimumScaledJacobian, 0.0);
    ExpectAt(few, prescribed);
  }

  CurvedMesh iterative = straight;
  const UntanglingResult result = UntangleControlNets(iterative, prescribed, {});
  EXPECT_TRUE(result.Valid);
  EXPECT_EQ(result.Steps, 4);
  EXPECT_TRUE(result.InvalidCells.empty());
  EXPECT_EQ(ClassifyValidity(iterative.Cell(0)), Validity::Valid);
  EXPECT_GT(SampledRelativeMinimumJacobian(iterative.Cell(0)), 0.1); // clearly valid
  EXPECT_EQ(result.MinimumScaledJacobian, BoundJacobian(iterative.Cell(0)).ScaledJacobian());
  EXPECT_GT(result.MinimumScaledJacobian, 0.0);
  ExpectAt(iterative, prescribed);
  // Vertices and boundary edges stay; the interior point moved.
  for (int k = 0; k < 9; ++k)
  {
    const std::int64_t id = straight.Cells[0][k];
    if (id != prescribed[0].first)
    {
      EXPECT_EQ(iterative.ControlPoints[id], straight.ControlPoints[id]);
    }
  }
  EXPECT_NE(iterative.ControlPoints[straight.Cells[0][9]], straight.ControlPoints[straight.Cells[0][9]]);
}

TEST(ElasticUntangler, AnnulusWithCurvedCircles)
{
  // Eight edges per circle: the inner arcs bulge 0.076 into a first layer only
  // 0.03 thick, so straight interior edges leave those cells tangled.
  const int n = 8;
  const std::vector<double> radii{ 1.0, 1.03, 1.5, 2.2, 3.0 };
  const SimplexMesh linear = Annulus(n, radii);
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const CurvedMesh before = curved;
  Prescribed prescribed;
  AddCircleTargets(curved, n, 0, radii.front(), prescribed);
  AddCircleTargets(curved, n, int(radii.size()) - 1, radii.back(), prescribed);

  CurvedMesh boundaryOnly = curved;
  for (const auto& [id, target] : prescribed)
    boundaryOnly.ControlPoints[id] = target;
  EXPECT_GE(CellsNotProvenValid(boundaryOnly).size(), std::size_t(n));

  UntanglingOptions options;
  const UntanglingResult result = UntangleControlNets(curved, prescribed, options);
  ASSERT_TRUE(result.Valid);
  EXPECT_TRUE(result.InvalidCells.empty());
  EXPECT_GE(result.Steps, 1);
  EXPECT_TRUE(CellsNotProvenValid(curved).empty());
  double minimum = HUGE_VAL;
  for (std::size_t c = 0; c < curved.Cells.size(); ++c)
  {
    EXPECT_GT(SampledRelativeMinimumJacobian(curved.Cell(c)), 0.0) << "cell " << c;
    minimum = std::min(minimum, BoundJacobian(curved.Cell(c)).ScaledJacobian());
  }
  EXPECT_EQ(result.MinimumScaledJacobian, minimum);
  EXPECT_GT(result.MinimumScaledJacobian, 0.0);
  ExpectAt(curved, prescribed);
  for (std::int64_t v = 0; v < curved.NumberOfVertices; ++v)
    EXPECT_EQ(curved.ControlPoints[v], before.ControlPoints[v]);
  // Targets lie on the curved circles' tangents: the arcs stay within 0.1% of the radius.
  for (int ring : { 0, int(radii.size()) - 1 })
    for (int i = 0; i < n; ++i)
    {
      const auto ids = curved.EdgePoints(ring * n + i, ring * n + (i + 1) % n);
      const Point2 &a = curved.ControlPoints[ring * n + i], &b = curved.ControlPoints[ring * n + (i + 1) % n];
      const Point2 &p = curved.ControlPoints[ids[0]], &q = curved.ControlPoints[ids[1]];
      const double x = (a[0] + 3 * p[0] + 3 * q[0] + b[0]) / 8, y = (a[1] + 3 * p[1] + 3 * q[1] + b[1]) / 8;
      EXPECT_NEAR(std::hypot(x, y), radii[ring], 1e-3 * radii[ring]);
    }

  // Finer fractions are kept only when the worst cell improves.
  CurvedMesh refined = before;
  options.QualityIterations = 2;
  const UntanglingResult better = UntangleControlNets(refined, prescribed, options);
  // (Here every doubling improves the worst cell: 1, 2, 4 fractions give 0.648, 0.661, 0.667.)
  EXPECT_TRUE(better.Valid);
  EXPECT_GT(better.MinimumScaledJacobian, result.MinimumScaledJacobian);
  EXPECT_EQ(better.Steps, 4 * result.Steps);
  EXPECT_TRUE(CellsNotProvenValid(refined).empty());
}

TEST(ElasticUntangler, ThinCellsAreInEquilibriumToo)
{
  // Sixty rings of cells ten to thirty times longer than thick: a stiffness
  // matrix far worse conditioned than those above, solved as accurately.
  const int n = 12;
  std::vector<double> radii{ 1.0, 1.01 };
  for (int k = 1; k <= 60; ++k)
    radii.push_back(1.01 + k * (3.0 - 1.01) / 60);
  const SimplexMesh linear = Annulus(n, radii);
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const CurvedMesh before = curved;
  Prescribed prescribed;
  AddCircleTargets(curved, n, 0, radii.front(), prescribed);
  const UntanglingResult result = UntangleControlNets(curved, prescribed, {});
  ASSERT_TRUE(result.Valid);
  ASSERT_EQ(result.Steps, 1);
  EXPECT_LT(RelativeResidual(before, curved, FreePoints(linear, before, prescribed), 0.3), 1e-8);
}

TEST(ElasticUntangler, EdgeBentAcrossTheOppositeVertexStaysInvalid)
{
  // Cell 0 of the grid is (0,0), (1,0), (1,1); its bottom edge is bent up
  // around the vertex (1,1). The boundary of its image winds the wrong way
  // around the points between the arch and that vertex: no valid placement exists.
  const SimplexMesh linear = Grid(3, 2);
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const CurvedMesh before = curved;
  const auto ids = curved.EdgePoints(0, 1);
  const Prescribed prescribed{ { ids[0], Point2{ 0.4, 2.2 } }, { ids[1], Point2{ 1.3, 2.2 } } };
  const UntanglingResult result = UntangleControlNets(curved, prescribed, {});
  EXPECT_FALSE(result.Valid);
  ASSERT_FALSE(result.InvalidCells.empty());
  EXPECT_TRUE(std::is_sorted(result.InvalidCells.begin(), result.InvalidCells.end()));
  EXPECT_NE(std::find(result.InvalidCells.begin(), result.InvalidCells.end(), 0u), result.InvalidCells.end());
  // The report matches the mesh left behind, and no attempt claims more than it proves.
  EXPECT_EQ(result.InvalidCells, CellsNotProvenValid(curved));
  EXPECT_LE(result.MinimumScaledJacobian, 0.0);
  EXPECT_GE(result.Steps, 1);
  EXPECT_LE(result.Steps, UntanglingOptions{}.MaximumSteps);
  ExpectAt(curved, prescribed);
  for (std::int64_t v = 0; v < curved.NumberOfVertices; ++v)
    EXPECT_EQ(curved.ControlPoints[v], before.ControlPoints[v]);
  for (const Point2& p : curved.ControlPoints)
    EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]));
}

TEST(ElasticUntangler, CornerOpenedTo180DegreesEndsTheSearch)
{
  // Both edges at vertex 0 are constrained and leave it in opposite directions:
  // det J is 0 there whatever the free interior point does, so the first
  // attempt is final (no 2, 4, ... 64 fractions tried).
  const SimplexMesh linear = Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { 0, 1, 2 });
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  const Prescribed prescribed{ { curved.EdgePoints(2, 0)[1], Point2{ -1.0 / 3, 0.0 } } };
  int reports = 0;
  ProgressObserver observer;
  observer.Callback = [&reports](const std::string&, double) { return ++reports, true; };
  const UntanglingResult result = UntangleControlNets(curved, prescribed, {}, observer);
  EXPECT_FALSE(result.Valid);
  EXPECT_EQ(result.InvalidCells, std::vector<std::size_t>{ 0 });
  EXPECT_EQ(result.Steps, 1);
  EXPECT_LE(reports, 3); // start, one step, end
}

TEST(ElasticUntangler, ProgressAndAbort)
{
  const SimplexMesh linear = Triangles({ { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 } }, { 0, 1, 2 });
  const CurvedMesh straight = MakeStraightCurvedMesh(linear);
  const Prescribed prescribed{ { straight.EdgePoints(0, 1)[0], Point2{ 0.75, 1.3 } } };

  std::vector<double> fractions;
  ProgressObserver recorder;
  recorder.Callback = [&fractions](const std::string& stage, double fraction) {
    EXPECT_EQ(stage, "Untangling");
    fractions.push_back(fraction);
    return true;
  };
  CurvedMesh curved = straight;
  EXPECT_TRUE(UntangleControlNets(curved, prescribed, {}, recorder).Valid);
  ASSERT_GE(fractions.size(), 2u + 1 + 2 + 4); // start, the steps of 1, 2 and 4 fractions, end
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));

  // Stop during the second attempt: nothing is written to the mesh.
  int calls = 0;
  ProgressObserver stopper;
  stopper.Callback = [&calls](const std::string&, double) { return ++calls < 3; };
  curved = straight;
  EXPECT_THROW(UntangleControlNets(curved, prescribed, {}, stopper), AbortRequested);
  EXPECT_EQ(curved.ControlPoints, straight.ControlPoints);
}

TEST(ElasticUntangler, DegenerateControlTrianglesStayFinite)
{
  // A curved input whose control nets contain flat and collapsed
  // sub-triangles (the body of a later load step can look like this).
  const SimplexMesh linear = Grid(2, 2);
  CurvedMesh curved = MakeStraightCurvedMesh(linear);
  // Cell 2: interior point on the line through the points of edge 0→1, so (P210, P120, P111) is flat.
  const auto& cell = curved.Cells[2];
  const Point2 p = curved.ControlPoints[cell[3]], q = curved.ControlPoints[cell[4]];
  curved.ControlPoints[cell[9]] = { 2 * q[0] - p[0], 2 * q[1] - p[1] };
  // Cell 5: interior point on P120, so two of its control triangles have two coincident corners.
  curved.ControlPoints[curved.Cells[5][9]] = curved.ControlPoints[curved.Cells[5][4]];
  // Cell 7: P210, P120 and P111 all at one point.
  const Point2 m = curved.ControlPoints[curved.Cells[7][3]];
  for (int k : { 4, 9 })
    curved.ControlPoints[curved.Cells[7][k]] = m;
  // Cell 0: its bottom edge lies on y = 0; an interior point at y = 1e-200 makes
  // (P210, P120, P111) tiny but not flat (1 / area^2 would overflow).
  ASSERT_EQ(curved.ControlPoints[curved.Cells[0][3]][1], 0.0);
  ASSERT_EQ(curved.ControlPoints[curved.Cells[0][4]][1], 0.0);
  curved.ControlPoints[curved.Cells[0][9]] = { 1.0, 1e-200 };
  const auto ids = curved.EdgePoints(0, 1);
  const Prescribed prescribed{ { ids[0], Point2{ 1.0 / 3, 0.1 } }, { ids[1], Point2{ 2.0 / 3, 0.1 } } };
  const UntanglingResult result = UntangleControlNets(curved, prescribed, {});
  EXPECT_GE(result.Steps, 1); // a solve succeeded
  ExpectAt(curved, prescribed);
  for (const Point2& point : curved.ControlPoints)
    ASSERT_TRUE(std::isfinite(point[0]) && std::isfinite(point[1]));
  EXPECT_TRUE(std::isfinite(result.MinimumScaledJacobian));
  EXPECT_EQ(result.InvalidCells, CellsNotProvenValid(curved));
}

TEST(ElasticUntangler, RejectsBadInput)
{
  CurvedMesh curved = MakeStraightCurvedMesh(Grid(1, 1));
  const auto size = std::int64_t(curved.ControlPoints.size());
  EXPECT_THROW(UntangleControlNets(curved, { { size, Point2{ 0, 0 } } }, {}), std::invalid_argument);
  EXPECT_THROW(UntangleControlNets(curved, { { -1, Point2{ 0, 0 } } }, {}), std::invalid_argument);
  UntanglingOptions options;
  options.PoissonRatio = 0.5;
  EXPECT_THROW(UntangleControlNets(curved, {}, options), std::invalid_argument);
  options = {};
  options.MaximumSteps = 0;
  EXPECT_THROW(UntangleControlNets(curved, {}, options), std::invalid_argument);
}
