// SPDX-License-Identifier: GPL-2.0-or-later
//
// The curver's fidelity machinery, stage by stage: certified polylines
// (FlattenCubic), the fit to the image (FitChain), the crossing proof
// (MeetingCurves) and the shortening that keeps both distance bounds and
// separates crossing curves (KeepDistanceBounds). Each shortening test first
// shows that its case breaks the property when the shortening is left out,
// measured by the independent checks of Checks/CurvedBoundary.h.

#include "Checks/CurvedBoundary.h"
#include "Curving/BezierCurver.h"
#include "Curving/CurveCrossings.h"
#include "Decimation/MeshDecimator.h"
#include "CurvingChecks.h"
#include "RandomLabelImages.h"
#include "SyntheticShapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace labelmesher
{
namespace
{

Point2 Bezier(const std::array<Point2, 4>& p, double t)
{
  const double u = 1.0 - t;
  Point2 q{ 0.0, 0.0 };
  const double w[4] = { u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t };
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 2; ++d)
      q[d] += w[k] * p[k][d];
  return q;
}

double DistanceToPolyline(const Point2& q, const std::vector<Point2>& line)
{
  double best = HUGE_VAL;
  for (std::size_t k = 0; k + 1 < line.size(); ++k)
  {
    const Point2& a = line[k];
    const Point2& b = line[k + 1];
    const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((q[0] - a[0]) * dx + (q[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(a[0] + t * dx - q[0], a[1] + t * dy - q[1]));
  }
  return best;
}

TEST(FlattenCubic, PolylineAndCurveWithinTheToleranceBothWays)
{
  testing::SeededRandom draw(11);
  for (int trial = 0; trial < 200; ++trial)
  {
    std::array<Point2, 4> p;
    for (Point2& q : p)
      q = { draw.Real(-10, 10), draw.Real(-10, 10) };
    const double epsilon = draw.Chance(0.5) ? 1.0 / 256.0 : 0.1;
    const std::vector<Point2> line = FlattenCubic(p, epsilon);
    ASSERT_GE(line.size(), 2u);
    EXPECT_EQ(line.front(), p[0]);
    EXPECT_EQ(line.back(), p[3]);
    std::vector<Point2> curve;
    for (int k = 0; k <= 4000; ++k)
      curve.push_back(Bezier(p, k / 4000.0));
    double curveToLine = 0.0, lineToCurve = 0.0;
    for (const Point2& q : curve)
      curveToLine = std::max(curveToLine, DistanceToPolyline(q, line));
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
      for (int s = 0; s <= 8; ++s)
      {
        const Point2 q{ line[k][0] + s / 8.0 * (line[k + 1][0] - line[k][0]),
          line[k][1] + s / 8.0 * (line[k + 1][1] - line[k][1]) };
        lineToCurve = std::max(lineToCurve, DistanceToPolyline(q, curve));
      }
    // The curve samples are 1/4000 of a parameter apart: allow their spacing.
    EXPECT_LE(curveToLine, epsilon + 1e-9) << "trial " << trial;
    EXPECT_LE(lineToCurve, epsilon + 0.02) << "trial " << trial;
  }
}

TEST(FitChain, FollowsACircleBetweenFewVerticesBetterThanInterpolation)
{
  // Six vertices on a circle of radius 20 (a decimated disc) and samples of
  // the circle between them: the fitted path must stay much closer to it than
  // Figure 17a's interpolation and the chords.
  const double r = 20.0;
  std::vector<Point2> vertices;
  for (int k = 0; k < 6; ++k)
    vertices.push_back({ r * std::cos(k * M_PI / 3), r * std::sin(k * M_PI / 3) });
  std::vector<BoundarySample> samples;
  for (std::size_t s = 0; s < 6; ++s)
    for (int k = 1; k < 20; ++k)
    {
      const double angle = (s + k / 20.0) * M_PI / 3;
      samples.push_back({ s, { r * std::cos(angle), r * std::sin(angle) }, k / 20.0 });
    }
  auto worstRadialError = [&](const std::vector<std::array<Point2, 2>>& inner) {
    double worst = 0.0;
    for (std::size_t s = 0; s < 6; ++s)
      for (int k = 0; k <= 100; ++k)
      {
        const Point2 q = Bezier({ vertices[s], inner[s][0], inner[s][1], vertices[(s + 1) % 6] }, k / 100.0);
        worst = std::max(worst, std::abs(std::hypot(q[0], q[1]) - r));
      }
    return worst;
  };
  const double fitted = worstRadialError(FitChain(vertices, true, samples, {}));
  const double interpolated = worstRadialError(SmoothChain(vertices, true, { Smoothness::C1, 1.0 / 3.0 }));
  const double chords = r * (1.0 - std::cos(M_PI / 6));
  EXPECT_LT(fitted, 0.05) << "interpolated " << interpolated << ", chords " << chords;
  EXPECT_LT(fitted, 0.25 * interpolated);
  EXPECT_LT(fitted, 0.05 * chords);
  // Without samples the fit is Figure 17a's path.
  const auto plain = FitChain(vertices, true, {}, {});
  const auto reference = SmoothChain(vertices, true, { Smoothness::C1, 1.0 / 3.0 });
  for (std::size_t s = 0; s < 6; ++s)
    for (int k = 0; k < 2; ++k)
      for (int d = 0; d < 2; ++d)
        EXPECT_NEAR(plain[s][k][d], reference[s][k][d], 1e-12);
}

TEST(MeetingCurves, ProvesCurvesApartAndFindsCrossingsBelowAnyPolylineResolution)
{
  auto straight = [](Point2 a, Point2 b, std::int64_t from, std::int64_t to) {
    return BoundaryCurve{ { a, Point2{ (2 * a[0] + b[0]) / 3, (2 * a[1] + b[1]) / 3 },
                            Point2{ (a[0] + 2 * b[0]) / 3, (a[1] + 2 * b[1]) / 3 }, b },
      from, to };
  };
  // Three straight edges from one vertex, and one far away: nothing meets.
  std::vector<BoundaryCurve> fan{ straight({ 0, 0 }, { 5, 0 }, 0, 1), straight({ 0, 0 }, { 0, 5 }, 0, 2),
    straight({ 0, 0 }, { -3, -4 }, 0, 3), straight({ 10, 10 }, { 12, 10 }, 4, 5) };
  EXPECT_TRUE(MeetingCurves(fan, 1.0 / 256.0).empty());
  // Two crossing segments (an X) of four different vertices.
  std::vector<BoundaryCurve> cross{ straight({ 0, 0 }, { 4, 4 }, 0, 1), straight({ 0, 4 }, { 4, 0 }, 2, 3) };
  EXPECT_EQ(MeetingCurves(cross, 1.0 / 256.0).size(), 2u);
  // Two curves from one vertex, the lower tangent bending up and the upper
  // one down, so that they swap sides: with tangents 1e-4 radians apart they
  // cross about 1e-3 from the vertex, far below a 1/256 polyline; 0.3 radians
  // apart, farther out. Both must be found.
  for (double spread : { 1e-4, 0.3 })
  {
    const Point2 v{ 0, 0 };
    const BoundaryCurve lower{ { v, Point2{ 1.0, 0.0 }, Point2{ 2.0, 0.6 }, Point2{ 3.0, 1.0 } }, 0, 1 };
    const BoundaryCurve upper{
      { v, Point2{ std::cos(spread), std::sin(spread) }, Point2{ 2.0, -0.6 }, Point2{ 3.0, -1.0 } }, 0, 2
    };
    EXPECT_EQ(MeetingCurves({ lower, upper }, 1.0 / 256.0).size(), 2u) << "spread " << spread;
  }
  // The same pair with the bends following the tangents' order never meets.
  {
    const Point2 v{ 0, 0 };
    BoundaryCurve lower{ { v, Point2{ 1.0, 0.0 }, Point2{ 2.0, -0.6 }, Point2{ 3.0, -1.0 } }, 0, 1 };
    BoundaryCurve upper{ { v, Point2{ std::cos(1e-4), std::sin(1e-4) }, Point2{ 2.0, 0.6 }, Point2{ 3.0, 1.0 } }, 0, 2 };
    EXPECT_TRUE(MeetingCurves({ lower, upper }, 1.0 / 256.0).empty());
  }
}

/// The pieces of `linear`'s interfaces with their inner control points pushed
/// `bulge` voxels to the right of each chain (out of the material on its left).
std::vector<CurvePiece> BulgingPieces(const SimplexMesh& linear, const CurvedMesh& curved, const Box2& border, double bulge)
{
  std::vector<CurvePiece> pieces;
  for (const InterfaceChain& chain : ExtractInterfaceChains(linear, border))
  {
    const std::size_t n = chain.Vertices.size();
    const std::size_t count = chain.Closed ? n : n - 1;
    for (std::size_t s = 0; s < count; ++s)
    {
      CurvePiece piece;
      piece.From = chain.Vertices[s];
      piece.To = chain.Vertices[(s + 1) % n];
      piece.ControlIds = curved.EdgePoints(piece.From, piece.To);
      piece.Left = chain.FirstMaterial;
      piece.Right = chain.SecondMaterial;
      const Point3& a = linear.Points[piece.From];
      const Point3& b = linear.Points[piece.To];
      const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
      for (int k = 0; k < 2; ++k)
      {
        const double w = (k + 1) / 3.0;
        piece.Fitted[k] = { a[0] + w * dx + bulge * dy / length, a[1] + w * dy - bulge * dx / length };
      }
      pieces.push_back(piece);
    }
  }
  return pieces;
}

CurvedMesh WithPieces(CurvedMesh mesh, const SimplexMesh& linear, const std::vector<CurvePiece>& pieces)
{
  for (const CurvePiece& piece : pieces)
  {
    const auto p = piece.ControlPoints(linear);
    mesh.ControlPoints[static_cast<std::size_t>(piece.ControlIds[0])] = p[1];
    mesh.ControlPoints[static_cast<std::size_t>(piece.ControlIds[1])] = p[2];
  }
  return mesh;
}

struct Scene
{
  LabelImage Image;
  SimplexMesh Linear;
  CurvedMesh Straight;
  Box2 Border;
  ImageOnMesh OnMesh;
};

Scene MakeScene(LabelImage image)
{
  Scene scene;
  scene.Image = std::move(image);
  MesherParameters mesher;
  DecimationParameters decimation;
  scene.Linear = testing::ForegroundMesh(DecimateMesh(scene.Image, MeshLabelImage(scene.Image, mesher).Mesh, decimation).Mesh);
  scene.Straight = MakeStraightCurvedMesh(scene.Linear);
  scene.Border = { -0.5, scene.Image.Dimensions[0] - 0.5, -0.5, scene.Image.Dimensions[1] - 0.5 };
  scene.OnMesh = { &scene.Image, { 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 } };
  return scene;
}

TEST(KeepDistanceBounds, ShortensCurvesThatLeaveTheImageBoundary)
{
  const Scene scene = MakeScene(testing::MakeDisc(48, 19.3));
  // Both bounds 2 voxels, or one of them loose (50) so that the other's test
  // alone must do the shortening.
  for (const CurveBounds& bounds :
    { CurveBounds{ 2.0, 2.0, 1.0 / 256.0 }, CurveBounds{ 2.0, 50.0, 1.0 / 256.0 }, CurveBounds{ 50.0, 2.0, 1.0 / 256.0 } })
  {
    std::vector<CurvePiece> pieces = BulgingPieces(scene.Linear, scene.Straight, scene.Border, 4.0);
    const CurvedMeshReport before =
      MeasureCurvedMesh(scene.Image, WithPieces(scene.Straight, scene.Linear, pieces), scene.OnMesh);
    ASSERT_GT(before.Curves.ImageToMesh, 2.5);
    ASSERT_GT(before.Curves.MeshToImage, 2.5);
    const FidelityOutcome outcome = KeepDistanceBounds(scene.Linear, pieces, scene.OnMesh, bounds);
    EXPECT_GT(outcome.ShortenedPieces, 0u);
    EXPECT_EQ(outcome.Uncertified, 0u);
    const CurvedMeshReport after =
      MeasureCurvedMesh(scene.Image, WithPieces(scene.Straight, scene.Linear, pieces), scene.OnMesh);
    EXPECT_LE(after.Curves.ImageToMesh, bounds.ImageToMesh + after.Resolution) << "bounds " << bounds.ImageToMesh
                                                                              << "/" << bounds.MeshToImage;
    EXPECT_LE(after.Curves.MeshToImage, bounds.MeshToImage + after.Resolution) << "bounds " << bounds.ImageToMesh
                                                                              << "/" << bounds.MeshToImage;
  }
}

TEST(KeepDistanceBounds, SeparatesCurvesThatCrossAcrossAGap)
{
  // Two discs three pixels apart, curves pushed out of each by 4.5 voxels at
  // their middles: they cross in the gap. The bounds are loose, so only the
  // crossing test acts.
  LabelImage image(60, 30, 1);
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 60; ++i)
    {
      if (std::hypot(i - 15.0, j - 14.5) <= 12.0)
        image(i, j, 0) = 1;
      if (std::hypot(i - 42.0, j - 14.5) <= 12.0)
        image(i, j, 0) = 2;
    }
  const Scene scene = MakeScene(image);
  std::vector<CurvePiece> pieces = BulgingPieces(scene.Linear, scene.Straight, scene.Border, 6.0);
  const SimplexMesh beforePolygons =
    CurvedBoundaryPolygons(WithPieces(scene.Straight, scene.Linear, pieces), scene.OnMesh, 1.0 / 1024.0);
  ASSERT_GT(CountBoundaryCrossings(beforePolygons), 0u);
  const FidelityOutcome outcome = KeepDistanceBounds(scene.Linear, pieces, scene.OnMesh, { 50.0, 50.0, 1.0 / 256.0 });
  EXPECT_GT(outcome.ShortenedPieces, 0u);
  EXPECT_LT(outcome.ShortenedPieces, pieces.size()) << "only the pieces facing each other need shortening";
  const SimplexMesh afterPolygons =
    CurvedBoundaryPolygons(WithPieces(scene.Straight, scene.Linear, pieces), scene.OnMesh, 1.0 / 1024.0);
  EXPECT_EQ(CountBoundaryCrossings(afterPolygons), 0u);
}

TEST(CurvedBoundary, StraightMeshMeasuresLikeTheLinearOne)
{
  const Scene scene = MakeScene(testing::MakeEllipse(50, 40, 17.2, 11.4, 30.0));
  const CurvedMeshReport curved = MeasureCurvedMesh(scene.Image, scene.Straight, scene.OnMesh);
  const HausdorffReport linear = MeasureHausdorff(scene.Image, scene.Linear);
  EXPECT_NEAR(curved.Curves.ImageToMesh, linear.Overall.ImageToMesh, curved.Resolution + 1e-9);
  EXPECT_NEAR(curved.Curves.MeshToImage, linear.Overall.MeshToImage, curved.Resolution + 1e-9);
  EXPECT_EQ(curved.Crossings, 0u);
  for (const auto& [material, comparison] : curved.Topology)
    EXPECT_TRUE(comparison.Matches()) << "material " << material;
}

TEST(CurvedBoundary, CountsCrossingAndOverlappingBoundaries)
{
  // Two triangles of different materials overlapping: their boundaries cross.
  SimplexMesh mesh;
  mesh.Dimension = 2;
  mesh.Points = { { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, { 1, 1, 0 }, { 5, 1, 0 }, { 1, 5, 0 } };
  mesh.Connectivity = { 0, 1, 2, 3, 4, 5 };
  mesh.Materials = { 1, 2 };
  EXPECT_GT(CountBoundaryCrossings(mesh), 0u);
  // Apart, and sharing one vertex only: no crossing.
  mesh.Points = { { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, { 4, 0, 0 }, { 8, 0, 0 }, { 6, 4, 0 } };
  mesh.Connectivity = { 0, 1, 2, 1, 4, 5 };
  EXPECT_EQ(CountBoundaryCrossings(mesh), 0u);
  // Sharing a vertex and overlapping along an edge direction: counted.
  mesh.Points = { { 0, 0, 0 }, { 4, 0, 0 }, { 0, 4, 0 }, { 0, 0, 0 }, { 2, 0, 0 }, { 2, -3, 0 } };
  mesh.Connectivity = { 0, 1, 2, 0, 4, 5 };
  mesh.Points[3] = { 9, 9, 0 }; // unused
  EXPECT_GT(CountBoundaryCrossings(mesh), 0u);
}

} // namespace
} // namespace labelmesher
