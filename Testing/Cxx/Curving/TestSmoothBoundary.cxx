// SPDX-License-Identifier: GPL-2.0-or-later
// SmoothChain (section 4.1, Figure 17): continuity measured at every joint of
// C1 and C2 paths through random and sampled curves, the construction itself,
// end conditions and closeness to a circle. ExtractInterfaceChains on meshes of
// small label grids (two triangles per pixel), checked against a brute-force
// classification of every mesh edge.
#include "Curving/InterfaceChains.h"
#include "Curving/SmoothBoundary.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>

using namespace labelmesher;

namespace
{
constexpr double kPi = 3.14159265358979323846;

using Controls = std::vector<std::array<Point2, 2>>;

Point2 Add(const Point2& a, const Point2& b) { return { a[0] + b[0], a[1] + b[1] }; }
Point2 Sub(const Point2& a, const Point2& b) { return { a[0] - b[0], a[1] - b[1] }; }
Point2 Scale(const Point2& a, double s) { return { a[0] * s, a[1] * s }; }
double Norm(const Point2& a) { return std::hypot(a[0], a[1]); }
double Distance(const Point2& a, const Point2& b) { return Norm(Sub(a, b)); }

// ---------------------------------------------------------------------------
// Cubic Bézier paths

struct Cubic
{
  std::array<Point2, 4> P;

  Point2 At(double t) const
  {
    const double s = 1.0 - t;
    Point2 r = Scale(P[0], s * s * s);
    r = Add(r, Scale(P[1], 3 * s * s * t));
    r = Add(r, Scale(P[2], 3 * s * t * t));
    return Add(r, Scale(P[3], t * t * t));
  }
  Point2 FirstDerivative(double t) const
  {
    const double s = 1.0 - t;
    Point2 r = Scale(Sub(P[1], P[0]), 3 * s * s);
    r = Add(r, Scale(Sub(P[2], P[1]), 6 * s * t));
    return Add(r, Scale(Sub(P[3], P[2]), 3 * t * t));
  }
  Point2 SecondDerivative(double t) const
  {
    const Point2 a = Add(Sub(P[2], Scale(P[1], 2)), P[0]);
    const Point2 b = Add(Sub(P[3], Scale(P[2], 2)), P[1]);
    return Add(Scale(a, 6 * (1 - t)), Scale(b, 6 * t));
  }
};

/// The cubic segments of a path: the vertices with SmoothChain's inner control points.
std::vector<Cubic> Path(const std::vector<Point2>& vertices, bool closed, const Controls& controls)
{
  const std::size_t n = vertices.size();
  std::vector<Cubic> path;
  for (std::size_t s = 0; s < controls.size(); ++s)
    path.push_back({ { vertices[s], controls[s][0], controls[s][1], vertices[(s + 1) % n] } });
  EXPECT_EQ(controls.size(), closed ? n : n - 1);
  return path;
}

/// Largest mismatches between the two sides of the path's joints. Derivatives
/// are taken in the uniform parameter (one unit per segment, as the B-spline
/// system assumes) and compared relative to max(|left|, |right|, longest chord).
struct JointMismatch
{
  double Position = 0.0;
  double UnitTangent = 0.0;
  double FirstDerivative = 0.0;
  double SecondDerivative = 0.0;
};

double LongestChord(const std::vector<Cubic>& path)
{
  double chord = 0.0;
  for (const Cubic& c : path)
    chord = std::max(chord, Distance(c.P[0], c.P[3]));
  return chord;
}

double Relative(const Point2& a, const Point2& b, double scale)
{
  return Distance(a, b) / std::max({ Norm(a), Norm(b), scale });
}

JointMismatch MeasureJoints(const std::vector<Cubic>& path, bool closed)
{
  JointMismatch m;
  const double scale = LongestChord(path);
  for (std::size_t s = closed ? 0 : 1; s < path.size(); ++s)
  {
    const Cubic& left = path[(s + path.size() - 1) % path.size()];
    const Cubic& right = path[s];
    const Point2 d1 = left.FirstDerivative(1.0), e1 = right.FirstDerivative(0.0);
    const Point2 d2 = left.SecondDerivative(1.0), e2 = right.SecondDerivative(0.0);
    m.Position = std::max(m.Position, Distance(left.At(1.0), right.At(0.0)) / scale);
    m.UnitTangent = std::max(m.UnitTangent, Distance(Scale(d1, 1.0 / Norm(d1)), Scale(e1, 1.0 / Norm(e1))));
    m.FirstDerivative = std::max(m.FirstDerivative, Relative(d1, e1, scale));
    m.SecondDerivative = std::max(m.SecondDerivative, Relative(d2, e2, scale));
  }
  return m;
}

/// Largest | |p − centre| − radius | over densely sampled path points.
double CircleDeviation(const std::vector<Cubic>& path, const Point2& centre, double radius)
{
  double deviation = 0.0;
  for (const Cubic& c : path)
    for (int k = 0; k <= 200; ++k)
      deviation = std::max(deviation, std::abs(Distance(c.At(k / 200.0), centre) - radius));
  return deviation;
}

// ---------------------------------------------------------------------------
// Point sets

std::vector<Point2> RandomPoints(std::mt19937& rng, std::size_t n)
{
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::vector<Point2> points(n);
  for (Point2& p : points)
    p = { u(rng), u(rng) };
  return points;
}

std::vector<Point2> Ellipse(std::size_t n, double a, double b, const Point2& centre, double phase = 0.0)
{
  std::vector<Point2> points(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double angle = phase + 2 * kPi * static_cast<double>(i) / static_cast<double>(n);
    points[i] = { centre[0] + a * std::cos(angle), centre[1] + b * std::sin(angle) };
  }
  return points;
}

/// A circle sampled at sorted random angles: unevenly spaced vertices.
std::vector<Point2> UnevenCircle(std::mt19937& rng, std::size_t n, double radius)
{
  std::uniform_real_distribution<double> u(0.0, 2 * kPi);
  std::vector<double> angles(n);
  for (double& a : angles)
    a = u(rng);
  std::sort(angles.begin(), angles.end());
  std::vector<Point2> points;
  for (double a : angles)
    points.push_back({ radius * std::cos(a), radius * std::sin(a) });
  return points;
}

/// Random point sets, circles and ellipses (evenly and unevenly sampled), of 3 to 70 vertices.
std::vector<std::vector<Point2>> TestChains()
{
  std::mt19937 rng(20240611);
  std::vector<std::vector<Point2>> chains;
  for (std::size_t n : { 3, 4, 5, 7, 10, 16, 31, 70 })
    for (int repeat = 0; repeat < 3; ++repeat)
      chains.push_back(RandomPoints(rng, n));
  chains.push_back(Ellipse(64, 10.0, 10.0, { 3.0, -2.0 }));
  chains.push_back(Ellipse(50, 7.0, 2.0, { -1.0, 4.0 }, 0.3));
  chains.push_back(Ellipse(5, 1.0, 3.0, { 0.0, 0.0 }));
  chains.push_back(UnevenCircle(rng, 40, 4.0));
  return chains;
}

Controls Smooth(const std::vector<Point2>& vertices, bool closed, Smoothness continuity, double tension = 1.0 / 3.0)
{
  SmoothingOptions options;
  options.Continuity = continuity;
  options.Tension = tension;
  return SmoothChain(vertices, closed, options);
}

void ExpectNear2(const Point2& actual, const Point2& expected, double tolerance)
{
  EXPECT_NEAR(actual[0], expected[0], tolerance);
  EXPECT_NEAR(actual[1], expected[1], tolerance);
}

// ---------------------------------------------------------------------------
// Label-grid meshes

/// Two counter-clockwise triangles per pixel (i, j) of [0, nx] × [0, ny]: the
/// lower-right one (i,j) (i+1,j) (i+1,j+1) has material(i, j, false), the
/// upper-left one (i,j) (i+1,j+1) (i,j+1) material(i, j, true). Cells of
/// material 0 are left out unless withBackground.
SimplexMesh GridMesh(
  int nx, int ny, const std::function<std::int32_t(int, int, bool)>& material, bool withBackground)
{
  SimplexMesh mesh;
  mesh.Dimension = 2;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.Points.push_back({ static_cast<double>(i), static_cast<double>(j), 0.0 });
  auto id = [&](int i, int j) { return static_cast<std::int64_t>(j) * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      for (bool upper : { false, true })
      {
        const std::int32_t m = material(i, j, upper);
        if (m == 0 && !withBackground)
          continue;
        if (upper)
          mesh.Connectivity.insert(mesh.Connectivity.end(), { id(i, j), id(i + 1, j + 1), id(i, j + 1) });
        else
          mesh.Connectivity.insert(mesh.Connectivity.end(), { id(i, j), id(i + 1, j), id(i + 1, j + 1) });
        mesh.Materials.push_back(m);
      }
  return mesh;
}

/// Rows of digits, the first row at the top (largest y): one label per pixel.
struct LabelGrid
{
  std::vector<std::string> Rows;

  int Width() const { return static_cast<int>(Rows.front().size()); }
  int Height() const { return static_cast<int>(Rows.size()); }
  std::int32_t operator()(int i, int j) const { return Rows[Height() - 1 - j][i] - '0'; }
  SimplexMesh Mesh(bool withBackground) const
  {
    return GridMesh(Width(), Height(), [&](int i, int j, bool) { return (*this)(i, j); }, withBackground);
  }
  Box2 Box() const { return { 0.0, static_cast<double>(Width()), 0.0, static_cast<double>(Height()) }; }
  /// Unit pixel sides between a label and another one (or the image outside, as 0).
  std::size_t InterfaceLength(std::int32_t label) const
  {
    auto at = [&](int i, int j) { return i < 0 || j < 0 || i >= Width() || j >= Height() ? 0 : (*this)(i, j); };
    std::size_t length = 0;
    for (int j = 0; j < Height(); ++j)
      for (int i = 0; i < Width(); ++i)
        if (at(i, j) == label)
          length += (at(i - 1, j) != label) + (at(i + 1, j) != label) + (at(i, j - 1) != label) + (at(i, j + 1) != label);
    return length;
  }
};

using Edge = std::pair<std::int64_t, std::int64_t>;

/// Brute force: the material on the left of every directed edge of a cell.
std::map<Edge, std::int32_t> LeftMaterials(const SimplexMesh& mesh)
{
  std::map<Edge, std::int32_t> left;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
    for (int i = 0; i < 3; ++i)
      left[{ mesh.Cell(c)[i], mesh.Cell(c)[(i + 1) % 3] }] = mesh.Materials[c];
  return left;
}

std::int32_t LeftOf(const std::map<Edge, std::int32_t>& left, std::int64_t a, std::int64_t b)
{
  const auto it = left.find({ a, b });
  return it == left.end() ? 0 : it->second; // outside the mesh: background
}

bool OnBorder(const Point3& p, const Box2& box, int side)
{
  const double tolerance = 1e-9 * std::max(box[1] - box[0], box[3] - box[2]);
  return std::abs(p[side / 2] - box[side]) <= tolerance;
}

bool OnBorder(const Point3& p, const Box2& box)
{
  return OnBorder(p, box, 0) || OnBorder(p, box, 1) || OnBorder(p, box, 2) || OnBorder(p, box, 3);
}

std::vector<Edge> ChainEdges(const InterfaceChain& chain)
{
  std::vector<Edge> edges;
  const std::size_t n = chain.Vertices.size();
  for (std::size_t k = 0; k + 1 < n; ++k)
    edges.emplace_back(chain.Vertices[k], chain.Vertices[k + 1]);
  if (chain.Closed && n > 0)
    edges.emplace_back(chain.Vertices[n - 1], chain.Vertices[0]);
  return edges;
}

/// Every interface edge (found by brute force) lies in exactly one chain, with
/// FirstMaterial on its left; chains pass through interface vertices of degree
/// 2 off the border only and end everywhere else.
void ExpectValidChains(const SimplexMesh& mesh, const Box2& border, const std::vector<InterfaceChain>& chains)
{
  const auto left = LeftMaterials(mesh);
  std::set<Edge> interfaces;
  std::map<std::int64_t, int> degree;
  for (const auto& [edge, material] : left)
  {
    const auto [a, b] = edge;
    if (material == LeftOf(left, b, a))
      continue;
    bool alongBorder = false;
    for (int side = 0; side < 4; ++side)
      alongBorder = alongBorder || (OnBorder(mesh.Points[a], border, side) && OnBorder(mesh.Points[b], border, side));
    if (alongBorder || !interfaces.insert({ std::min(a, b), std::max(a, b) }).second)
      continue;
    ++degree[a];
    ++degree[b];
  }

  std::map<Edge, int> covered;
  for (const InterfaceChain& chain : chains)
  {
    ASSERT_GE(chain.Vertices.size(), chain.Closed ? 3u : 2u);
    EXPECT_NE(chain.FirstMaterial, chain.SecondMaterial);
    for (const auto& [a, b] : ChainEdges(chain))
    {
      EXPECT_EQ(LeftOf(left, a, b), chain.FirstMaterial) << "edge " << a << "→" << b;
      EXPECT_EQ(LeftOf(left, b, a), chain.SecondMaterial) << "edge " << a << "→" << b;
      ++covered[{ std::min(a, b), std::max(a, b) }];
    }
    const std::size_t n = chain.Vertices.size();
    for (std::size_t k = 0; k < n; ++k)
    {
      const std::int64_t v = chain.Vertices[k];
      const bool end = !chain.Closed && (k == 0 || k + 1 == n);
      const bool passes = degree[v] == 2 && !OnBorder(mesh.Points[v], border);
      EXPECT_EQ(passes, !end) << "vertex " << v << " at position " << k;
    }
  }
  for (const Edge& e : interfaces)
    EXPECT_EQ(covered[e], 1) << "interface edge " << e.first << "-" << e.second;
  EXPECT_EQ(covered.size(), interfaces.size());
}

/// Twice the signed area enclosed by a closed chain (positive: counter-clockwise).
double SignedArea2(const SimplexMesh& mesh, const InterfaceChain& chain)
{
  double area = 0.0;
  for (const auto& [a, b] : ChainEdges(chain))
    area += mesh.Points[a][0] * mesh.Points[b][1] - mesh.Points[b][0] * mesh.Points[a][1];
  return area;
}

bool SameChains(const std::vector<InterfaceChain>& x, const std::vector<InterfaceChain>& y)
{
  if (x.size() != y.size())
    return false;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (x[k].Vertices != y[k].Vertices || x[k].Closed != y[k].Closed || x[k].FirstMaterial != y[k].FirstMaterial ||
      x[k].SecondMaterial != y[k].SecondMaterial)
      return false;
  return true;
}

LabelGrid Disc(int size, double radius)
{
  LabelGrid grid;
  for (int r = 0; r < size; ++r)
  {
    std::string row;
    for (int i = 0; i < size; ++i)
    {
      const double x = i + 0.5 - size / 2.0, y = (size - 1 - r) + 0.5 - size / 2.0;
      row += std::hypot(x, y) < radius ? '1' : '0';
    }
    grid.Rows.push_back(row);
  }
  return grid;
}

} // namespace

// ---------------------------------------------------------------------------
// SmoothChain

TEST(SmoothBoundary, C2PathsAreTwiceDifferentiableAtEveryJoint)
{
  for (bool closed : { true, false })
    for (const auto& vertices : TestChains())
    {
      const auto path = Path(vertices, closed, Smooth(vertices, closed, Smoothness::C2));
      const JointMismatch m = MeasureJoints(path, closed);
      EXPECT_LT(m.Position, 1e-12);
      EXPECT_LT(m.UnitTangent, 1e-9);
      EXPECT_LT(m.FirstDerivative, 1e-9) << vertices.size() << " vertices, closed " << closed;
      EXPECT_LT(m.SecondDerivative, 1e-9) << vertices.size() << " vertices, closed " << closed;
      if (!closed)
      {
        // Natural end conditions: no curvature at the two end vertices.
        const double scale = LongestChord(path);
        EXPECT_LT(Norm(path.front().SecondDerivative(0.0)), 1e-9 * scale);
        EXPECT_LT(Norm(path.back().SecondDerivative(1.0)), 1e-9 * scale);
      }
    }
}

TEST(SmoothBoundary, C2SolvesTheBSplineSystemOfFigure17c)
{
  for (bool closed : { true, false })
    for (const auto& s : TestChains())
    {
      const Controls c = Smooth(s, closed, Smoothness::C2);
      const std::size_t n = s.size(), segments = c.size();
      // The A-frame of Figure 17b: each segment's inner points are at 1/3 and
      // 2/3 of B_i B_{i+1}; both segments at a joint agree on the apex B_i.
      std::vector<Point2> b(n);
      for (std::size_t k = 0; k < segments; ++k)
        b[k] = Sub(Scale(c[k][0], 2.0), c[k][1]);
      if (!closed)
        b[n - 1] = Sub(Scale(c[n - 2][1], 2.0), c[n - 2][0]);
      for (std::size_t k = 0; k < segments; ++k)
        ExpectNear2(Sub(Scale(c[k][1], 2.0), c[k][0]), b[(k + 1) % n], 1e-10);
      // 6 S_i = B_{i-1} + 4 B_i + B_{i+1} wherever the system applies.
      for (std::size_t i = closed ? 0 : 1; i < (closed ? n : n - 1); ++i)
        ExpectNear2(Scale(s[i], 6.0), Add(Add(b[(i + n - 1) % n], Scale(b[i], 4.0)), b[(i + 1) % n]), 1e-10);
      if (!closed)
      {
        ExpectNear2(b[0], s[0], 1e-10);
        ExpectNear2(b[n - 1], s[n - 1], 1e-10);
      }
    }
}

TEST(SmoothBoundary, C1PathsShareTangentDirectionsAtEveryJoint)
{
  JointMismatch random; // largest C2 defects of C1 paths through random points
  for (double tension : { 1.0 / 3.0, 0.2, 0.5 })
    for (bool closed : { true, false })
      for (const auto& vertices : TestChains())
      {
        const auto path = Path(vertices, closed, Smooth(vertices, closed, Smoothness::C1, tension));
        const JointMismatch m = MeasureJoints(path, closed);
        EXPECT_LT(m.Position, 1e-12);
        EXPECT_LT(m.UnitTangent, 1e-9) << vertices.size() << " vertices, closed " << closed;
        random.FirstDerivative = std::max(random.FirstDerivative, m.FirstDerivative);
        random.SecondDerivative = std::max(random.SecondDerivative, m.SecondDerivative);
      }
  // The measurement can fail: Figure 17a scales the handles by the chords, so
  // on uneven points neither the derivative lengths nor the curvature match.
  EXPECT_GT(random.FirstDerivative, 1e-2);
  EXPECT_GT(random.SecondDerivative, 1e-2);
}

TEST(SmoothBoundary, C1HandlesFollowTheConstructionOfFigure17a)
{
  const std::vector<Point2> p{ { 0, 0 }, { 1, 0 }, { 3, 1 }, { 4, 4 }, { 2, 6 } };
  const double t = 0.4;
  const Controls c = Smooth(p, false, Smoothness::C1, t);
  ASSERT_EQ(c.size(), 4u);
  // Segment P1P2: Q1 on P0P2 with |P0Q1| / |Q1P2| = |P0P1| / |P1P2|; the
  // segment P0P2 translated to put Q1 on P1, scaled by t, has P2 at C2.
  const double d01 = Distance(p[0], p[1]), d12 = Distance(p[1], p[2]), d23 = Distance(p[2], p[3]);
  const Point2 q1 = Add(p[0], Scale(Sub(p[2], p[0]), d01 / (d01 + d12)));
  ExpectNear2(c[1][0], Add(p[1], Scale(Sub(p[2], q1), t)), 1e-14);
  // C3 likewise from P1P3 translated to put Q2 on P2 (P1's image).
  const Point2 q2 = Add(p[1], Scale(Sub(p[3], p[1]), d12 / (d12 + d23)));
  ExpectNear2(c[1][1], Add(p[2], Scale(Sub(p[1], q2), t)), 1e-14);
  // Open ends: the handle lies on the end chord.
  ExpectNear2(c[0][0], Add(p[0], Scale(Sub(p[1], p[0]), t)), 1e-14);
  ExpectNear2(c[3][1], Add(p[4], Scale(Sub(p[3], p[4]), t)), 1e-14);
}

TEST(SmoothBoundary, C1TensionOneThirdOnEvenPointsIsCatmullRom)
{
  const auto p = Ellipse(12, 3.0, 3.0, { 1.0, 1.0 });
  const Controls c = Smooth(p, true, Smoothness::C1);
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    const Point2& previous = p[(i + p.size() - 1) % p.size()];
    const Point2& next = p[(i + 1) % p.size()];
    ExpectNear2(c[i][0], Add(p[i], Scale(Sub(next, previous), 1.0 / 6.0)), 1e-12);
  }
  // Tension 0: the handles collapse onto the vertices, every segment is straight.
  const Controls straight = Smooth(p, true, Smoothness::C1, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    ExpectNear2(straight[i][0], p[i], 0.0);
    ExpectNear2(straight[i][1], p[(i + 1) % p.size()], 0.0);
  }
}

TEST(SmoothBoundary, C2StaysCloseToASampledCircle)
{
  const Point2 centre{ 3.0, -2.0 };
  const double radius = 10.0;
  double deviation[2];
  for (int k = 0; k < 2; ++k)
  {
    const auto p = Ellipse(k == 0 ? 32 : 64, radius, radius, centre, 0.1);
    deviation[k] = CircleDeviation(Path(p, true, Smooth(p, true, Smoothness::C2)), centre, radius);
  }
  const auto p = Ellipse(64, radius, radius, centre, 0.1);
  const double c1 = CircleDeviation(Path(p, true, Smooth(p, true, Smoothness::C1)), centre, radius);
  const double polygon = radius * (1.0 - std::cos(kPi / 64));
  std::printf("circle r = %g, 64 points: C2 max deviation %.3e (%.3e r), C1 %.3e, polygon %.3e; 32 points C2 %.3e\n",
    radius, deviation[1], deviation[1] / radius, c1, polygon, deviation[0]);
  EXPECT_LT(deviation[1], 1e-5 * radius);
  EXPECT_LT(c1, 1e-3 * radius);
  EXPECT_LT(deviation[1], 1e-2 * polygon); // far closer than the straight segments
  // Fourth-order convergence of the interpolating cubic spline: halving the
  // spacing divides the error by about 16.
  EXPECT_GT(deviation[0] / deviation[1], 12.0);
}

TEST(SmoothBoundary, ShortChains)
{
  const Point2 a{ 1.0, 2.0 }, b{ 4.0, -1.0 }, c{ 0.0, -3.0 };
  for (Smoothness s : { Smoothness::C1, Smoothness::C2 })
  {
    // One open segment stays straight, whatever the tension.
    const Controls one = Smooth({ a, b }, false, s, 0.45);
    ASSERT_EQ(one.size(), 1u);
    ExpectNear2(one[0][0], { 2.0, 1.0 }, 1e-14);
    ExpectNear2(one[0][1], { 3.0, 0.0 }, 1e-14);
    EXPECT_TRUE(Smooth({ a }, false, s).empty());
    EXPECT_TRUE(Smooth({}, false, s).empty());
    EXPECT_TRUE(Smooth({}, true, s).empty());
    // A closed chain of two vertices: two straight segments, no crash.
    const Controls two = Smooth({ a, b }, true, s);
    ASSERT_EQ(two.size(), 2u);
    ExpectNear2(two[1][0], { 3.0, 0.0 }, 1e-14);
    ExpectNear2(two[1][1], { 2.0, 1.0 }, 1e-14);
    const Controls single = Smooth({ a }, true, s);
    ASSERT_EQ(single.size(), 1u);
    ExpectNear2(single[0][0], a, 0.0);
    // The smallest closed chain that bends: a triangle.
    const std::vector<Point2> triangle{ a, b, c };
    const auto path = Path(triangle, true, Smooth(triangle, true, s));
    const JointMismatch m = MeasureJoints(path, true);
    EXPECT_LT(m.UnitTangent, 1e-9);
    if (s == Smoothness::C2)
    {
      EXPECT_LT(m.SecondDerivative, 1e-9);
    }
    EXPECT_GT(Distance(path[0].At(0.5), Scale(Add(a, b), 0.5)), 0.1); // bent, not straight
  }
  // An open chain of three vertices: one unknown, 4 B_1 = 6 S_1 − S_0 − S_2.
  const Controls three = Smooth({ a, b, c }, false, Smoothness::C2);
  const Point2 b1 = Scale(Sub(Sub(Scale(b, 6.0), a), c), 0.25);
  ExpectNear2(three[0][0], Add(a, Scale(Sub(b1, a), 1.0 / 3.0)), 1e-13);
  ExpectNear2(three[1][1], Add(b1, Scale(Sub(c, b1), 2.0 / 3.0)), 1e-13);
}

TEST(SmoothBoundary, RepeatedVerticesDoNotBreakTheC1Construction)
{
  const std::vector<Point2> p{ { 0, 0 }, { 0, 0 }, { 0, 0 }, { 1, 1 } };
  for (bool closed : { true, false })
    for (const auto& c : Smooth(p, closed, Smoothness::C1))
      for (const Point2& q : c)
        EXPECT_TRUE(std::isfinite(q[0]) && std::isfinite(q[1]));
}

TEST(SmoothBoundary, LongClosedChain)
{
  const auto p = Ellipse(100000, 300.0, 120.0, { 5.0, 5.0 });
  const auto path = Path(p, true, Smooth(p, true, Smoothness::C2));
  const JointMismatch m = MeasureJoints(path, true);
  EXPECT_LT(m.FirstDerivative, 1e-9);
  EXPECT_LT(m.SecondDerivative, 1e-9);
}

// ---------------------------------------------------------------------------
// ExtractInterfaceChains

TEST(InterfaceChains, SquareSplitByADiagonal)
{
  const int n = 6;
  // Material 2 above the diagonal y = x, 1 below it; the pixel diagonals lie on it.
  const SimplexMesh mesh =
    GridMesh(n, n, [](int i, int j, bool upper) { return i < j || (i == j && upper) ? 2 : 1; }, true);
  const Box2 box = BoundingBox2(mesh);
  EXPECT_EQ(box, (Box2{ 0.0, n, 0.0, n }));
  const auto chains = ExtractInterfaceChains(mesh, box);
  ExpectValidChains(mesh, box, chains);
  ASSERT_EQ(chains.size(), 1u);
  const InterfaceChain& chain = chains[0];
  EXPECT_FALSE(chain.Closed);
  EXPECT_EQ(chain.FirstMaterial, 2); // the upper-left half, on the left of the way up
  EXPECT_EQ(chain.SecondMaterial, 1);
  ASSERT_EQ(chain.Vertices.size(), static_cast<std::size_t>(n + 1));
  for (int k = 0; k <= n; ++k)
    EXPECT_EQ(mesh.Points[chain.Vertices[k]], (Point3{ double(k), double(k), 0.0 }));

  // Inside a larger border the mesh's own boundary is an interface with the
  // outside (material 0): two more chains from corner to corner.
  const Box2 larger{ -1.0, n + 1.0, -1.0, n + 1.0 };
  const auto all = ExtractInterfaceChains(mesh, larger);
  ExpectValidChains(mesh, larger, all);
  ASSERT_EQ(all.size(), 3u);
  std::multiset<std::pair<std::int32_t, std::int32_t>> pairs;
  for (const InterfaceChain& c : all)
  {
    EXPECT_FALSE(c.Closed);
    EXPECT_EQ(c.Vertices.size(), c.SecondMaterial == 0 ? 2u * n + 1 : n + 1u);
    pairs.insert({ c.FirstMaterial, c.SecondMaterial });
  }
  EXPECT_EQ(pairs, (std::multiset<std::pair<std::int32_t, std::int32_t>>{ { 1, 0 }, { 2, 0 }, { 2, 1 } }));
}

TEST(InterfaceChains, DiscIsOneCounterClockwiseLoop)
{
  const LabelGrid grid = Disc(16, 5.5);
  std::vector<std::int64_t> sorted[2];
  for (bool withBackground : { true, false })
  {
    const SimplexMesh mesh = grid.Mesh(withBackground);
    const auto chains = ExtractInterfaceChains(mesh, grid.Box());
    ExpectValidChains(mesh, grid.Box(), chains);
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_TRUE(chains[0].Closed);
    EXPECT_EQ(chains[0].FirstMaterial, 1);
    EXPECT_EQ(chains[0].SecondMaterial, 0);
    EXPECT_EQ(chains[0].Vertices.size(), grid.InterfaceLength(1));
    EXPECT_GT(SignedArea2(mesh, chains[0]), 0.0);
    sorted[withBackground] = chains[0].Vertices;
    std::sort(sorted[withBackground].begin(), sorted[withBackground].end());
    // The loop can be smoothed as it is.
    std::vector<Point2> points;
    for (std::int64_t v : chains[0].Vertices)
      points.push_back({ mesh.Points[v][0], mesh.Points[v][1] });
    const JointMismatch m = MeasureJoints(Path(points, true, Smooth(points, true, Smoothness::C2)), true);
    EXPECT_LT(m.SecondDerivative, 1e-9);
  }
  // Background cells or none: the same loop.
  EXPECT_EQ(sorted[0], sorted[1]);
}

TEST(InterfaceChains, HoleIsAClockwiseLoop)
{
  LabelGrid grid = Disc(16, 6.5);
  grid.Rows[7] = "0011111001111100";
  grid.Rows[8] = "0011111001111100";
  const SimplexMesh mesh = grid.Mesh(true);
  const auto chains = ExtractInterfaceChains(mesh, grid.Box());
  ExpectValidChains(mesh, grid.Box(), chains);
  ASSERT_EQ(chains.size(), 2u);
  int clockwise = 0;
  for (const InterfaceChain& c : chains)
  {
    EXPECT_TRUE(c.Closed);
    EXPECT_EQ(c.FirstMaterial, 1);
    clockwise += SignedArea2(mesh, c) < 0.0;
  }
  EXPECT_EQ(clockwise, 1);
  EXPECT_EQ(chains[0].Vertices.size() + chains[1].Vertices.size(), grid.InterfaceLength(1));
}

TEST(InterfaceChains, ThreeMaterialsMeetAtAJunction)
{
  const LabelGrid grid{ { "11113333", "11113333", "11113333", "11113333", //
    "11112222", "11112222", "11112222", "11112222" } };
  const SimplexMesh mesh = grid.Mesh(true);
  const auto chains = ExtractInterfaceChains(mesh, grid.Box());
  ExpectValidChains(mesh, grid.Box(), chains);
  ASSERT_EQ(chains.size(), 3u);
  const std::int64_t junction = 4 * 9 + 4; // the point (4, 4)
  std::set<std::pair<std::int32_t, std::int32_t>> pairs;
  for (const InterfaceChain& c : chains)
  {
    EXPECT_FALSE(c.Closed);
    EXPECT_EQ(c.Vertices.size(), 5u);
    const bool atJunction = c.Vertices.front() == junction || c.Vertices.back() == junction;
    EXPECT_TRUE(atJunction);
    const std::int64_t other = c.Vertices.front() == junction ? c.Vertices.back() : c.Vertices.front();
    EXPECT_TRUE(OnBorder(mesh.Points[other], grid.Box()));
    pairs.insert({ c.FirstMaterial, c.SecondMaterial });
  }
  EXPECT_EQ(pairs, (std::set<std::pair<std::int32_t, std::int32_t>>{ { 2, 1 }, { 3, 1 }, { 3, 2 } }));
}

TEST(InterfaceChains, JunctionsAwayFromTheBorder)
{
  // Three materials inside the background: one triple junction of 1, 2, 3 and
  // three where two of them meet the background; every chain ends at two of them.
  const LabelGrid grid{ { "000000000", "033333330", "033333330", "011112220", //
    "011112220", "011112220", "000000000" } };
  for (bool withBackground : { true, false })
  {
    const SimplexMesh mesh = grid.Mesh(withBackground);
    const auto chains = ExtractInterfaceChains(mesh, grid.Box());
    ExpectValidChains(mesh, grid.Box(), chains);
    ASSERT_EQ(chains.size(), 6u);
    const std::int64_t junction = 4 * 10 + 5; // the point (5, 4)
    int atJunction = 0;
    for (const InterfaceChain& c : chains)
    {
      EXPECT_FALSE(c.Closed);
      atJunction += c.Vertices.front() == junction || c.Vertices.back() == junction;
    }
    EXPECT_EQ(atJunction, 3);
  }
}

TEST(InterfaceChains, ChainsEndOnTheBorder)
{
  const LabelGrid grid{ { "0000000", "1100000", "1110000", "1100000", "0000000" } };
  for (bool withBackground : { true, false })
  {
    const SimplexMesh mesh = grid.Mesh(withBackground);
    const auto chains = ExtractInterfaceChains(mesh, grid.Box());
    ExpectValidChains(mesh, grid.Box(), chains);
    ASSERT_EQ(chains.size(), 1u);
    const InterfaceChain& c = chains[0];
    EXPECT_FALSE(c.Closed);
    EXPECT_EQ(c.FirstMaterial, 1);
    EXPECT_EQ(c.SecondMaterial, 0);
    // From (0, 1) around the blob to (0, 4), never along the border x = 0.
    EXPECT_EQ(mesh.Points[c.Vertices.front()], (Point3{ 0.0, 1.0, 0.0 }));
    EXPECT_EQ(mesh.Points[c.Vertices.back()], (Point3{ 0.0, 4.0, 0.0 }));
    EXPECT_EQ(c.Vertices.size(), grid.InterfaceLength(1) - 3 + 1);
    for (std::size_t k = 1; k + 1 < c.Vertices.size(); ++k)
      EXPECT_GT(mesh.Points[c.Vertices[k]][0], 0.0);

    // The border is matched to within 1e-9 of its size, no further.
    const Box2 near{ -1e-10, 7.0, 0.0, 5.0 + 1e-10 };
    EXPECT_TRUE(SameChains(ExtractInterfaceChains(mesh, near), chains));
    const Box2 away{ -1e-6, 7.0, 0.0, 5.0 };
    const auto loop = ExtractInterfaceChains(mesh, away);
    ExpectValidChains(mesh, away, loop);
    ASSERT_EQ(loop.size(), 1u);
    EXPECT_TRUE(loop[0].Closed);
    EXPECT_EQ(loop[0].Vertices.size(), grid.InterfaceLength(1));
  }
}

TEST(InterfaceChains, LoopTouchingTheBorderAtAVertexEndsThere)
{
  // A blob of pixels whose lower tip, one triangle, touches the border y = 0
  // at the point (3, 0) only: an interface vertex of degree 2 on the border.
  const auto material = [](int i, int j, bool upper) {
    return (i == 3 && j == 0 && upper) || (j >= 1 && j <= 2 && i >= 2 && i <= 4) ? 1 : 0;
  };
  const Box2 box{ 0.0, 6.0, 0.0, 4.0 };
  for (bool withBackground : { true, false })
  {
    const SimplexMesh mesh = GridMesh(6, 4, material, withBackground);
    const auto chains = ExtractInterfaceChains(mesh, box);
    ExpectValidChains(mesh, box, chains);
    ASSERT_EQ(chains.size(), 1u);
    EXPECT_FALSE(chains[0].Closed);
    EXPECT_EQ(chains[0].Vertices.front(), 3);
    EXPECT_EQ(chains[0].Vertices.back(), 3);
    EXPECT_EQ(chains[0].Vertices.size(), 12u); // 11 edges: 9 pixel sides, the tip's diagonal and side
    // Away from the border the same blob is a closed loop.
    const auto loop = ExtractInterfaceChains(mesh, { -1.0, 6.0, -1.0, 4.0 });
    ASSERT_EQ(loop.size(), 1u);
    EXPECT_TRUE(loop[0].Closed);
    EXPECT_EQ(loop[0].Vertices.size(), 11u);
  }
}

TEST(InterfaceChains, BackgroundAloneHasNoInterfaces)
{
  const LabelGrid grid{ { "000", "000" } };
  const SimplexMesh mesh = grid.Mesh(true);
  EXPECT_TRUE(ExtractInterfaceChains(mesh, { -1.0, 4.0, -1.0, 3.0 }).empty());
  EXPECT_TRUE(ExtractInterfaceChains(SimplexMesh{ 2, {}, {}, {} }, { 0.0, 1.0, 0.0, 1.0 }).empty());
  SimplexMesh volume;
  EXPECT_THROW(ExtractInterfaceChains(volume, { 0.0, 1.0, 0.0, 1.0 }), std::invalid_argument);
}

TEST(InterfaceChains, RandomLabelGrids)
{
  // Noise of three labels: pinches, junctions, islands, loops pinned at a vertex.
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> label(0, 3);
  for (int repeat = 0; repeat < 12; ++repeat)
  {
    LabelGrid grid;
    for (int r = 0; r < 20; ++r)
    {
      std::string row;
      for (int i = 0; i < 24; ++i)
        row += static_cast<char>('0' + (label(rng) == 0 ? 0 : (repeat % 3 == 0 ? 1 : label(rng))));
      grid.Rows.push_back(row);
    }
    const bool withBackground = repeat % 2 == 0;
    const SimplexMesh mesh = grid.Mesh(withBackground);
    for (const Box2& box : { grid.Box(), Box2{ -2.0, 30.0, -1.0, 25.0 } })
    {
      const auto chains = ExtractInterfaceChains(mesh, box);
      ExpectValidChains(mesh, box, chains);
      EXPECT_FALSE(chains.empty());
      EXPECT_TRUE(SameChains(chains, ExtractInterfaceChains(mesh, box))); // deterministic
    }
  }
}

TEST(InterfaceChains, LargeDisc)
{
  const LabelGrid grid = Disc(400, 170.0);
  const SimplexMesh mesh = grid.Mesh(true);
  ASSERT_EQ(mesh.NumberOfCells(), 320000u);
  const auto chains = ExtractInterfaceChains(mesh, grid.Box());
  ASSERT_EQ(chains.size(), 1u);
  EXPECT_TRUE(chains[0].Closed);
  EXPECT_EQ(chains[0].Vertices.size(), grid.InterfaceLength(1));
  EXPECT_GT(SignedArea2(mesh, chains[0]), 0.0);
}
