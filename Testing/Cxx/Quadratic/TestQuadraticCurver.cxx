// SPDX-License-Identifier: GPL-2.0-or-later
//
// The 3D quadratic curver (Quadratic/QuadraticCurver.h):
//   - its certificates against sampling: the Bernstein coefficients of det J
//     bound det J sampled densely on random curved cells, and a face's
//     flattening is within the stated tolerance of the face;
//   - through mesher, decimator and curver on seeded random 3D images (both
//     generators, distance bounds 0-3, angles drawn): every guarantee measured
//     independently (QuadraticGuarantees.h), and each of the curver's two
//     certificates (and the corner bound), switched off, lets the checks find a
//     violation;
//   - corner angles: a straight cell's are its dihedral angles, and the
//     curver's exact tangents agree with tangents from points of the map;
//   - on smooth shapes (sphere, torus, Cassini volume): the same, and fewer
//     misclassified voxels than the linear mesh.
// A failure prints the seed and what its image contains.

#include "Checks/QuadraticVolume.h"
#include "DecimatorGuarantees.h"
#include "MesherGuarantees.h"
#include "Quadratic/QuadraticCorners.h"
#include "Quadratic/QuadraticFidelity.h"
#include "Quadratic/TetraJacobian.h"
#include "QuadraticGuarantees.h"
#include "RandomLabelImages.h"
#include "SyntheticShapes.h"
#include "Support/Geometry.h"
#include "Support/ParallelChunks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>

namespace labelmesher
{
using namespace geometry;
namespace
{

std::array<Point3, 10> StraightTetra(const Point3& a, const Point3& b, const Point3& c, const Point3& d)
{
  std::array<Point3, 10> n{ a, b, c, d };
  for (int e = 0; e < 6; ++e)
    n[4 + e] = Scale(Add(n[kTetraEdges[e][0]], n[kTetraEdges[e][1]]), 0.5);
  return n;
}

TEST(TetraJacobian, StraightCellHasSixTimesItsVolumeEverywhere)
{
  const auto nodes = StraightTetra({ 0, 0, 0 }, { 2, 0, 0 }, { 0, 3, 0 }, { 0, 0, 1 });
  for (double c : JacobianCoefficients(nodes))
    EXPECT_NEAR(c, 6.0, 1e-12);
  EXPECT_NEAR(CertifiedScaledJacobian(nodes), 1.0, 1e-12);
}

TEST(QuadraticCorners, StraightCellCornersAreItsDihedralAngles)
{
  const auto nodes = StraightTetra({ 0, 0, 0 }, { 2, 0.3, 0 }, { 0.4, 3, 0 }, { 0.2, 0.1, 1 });
  EXPECT_NEAR(SmallestCornerAngle(nodes), MinimumDihedralAngle(nodes[0], nodes[1], nodes[2], nodes[3]), 1e-9);
  // The right corner of the unit tetrahedron: three right angles.
  for (double angle : CornerDihedralAngles(StraightTetra({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }), 0))
    EXPECT_NEAR(angle, 90.0, 1e-12);
}

TEST(QuadraticCorners, ExactTangentsAgreeWithPointsOfTheMap)
{
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> offset(-0.15, 0.15);
  double lowest = 180.0;
  for (int trial = 0; trial < 500; ++trial)
  {
    auto nodes = StraightTetra({ 0, 0, 0 }, { 1, 0, 0 }, { 0.2, 0.9, 0 }, { 0.1, 0.2, 0.8 });
    for (int e = 4; e < 10; ++e)
      nodes[e] = Add(nodes[e], { offset(random), offset(random), offset(random) });
    const double exact = SmallestCornerAngle(nodes);
    EXPECT_NEAR(exact, MeasuredCornerAngle(nodes), 1e-7) << trial;
    lowest = std::min(lowest, exact);
  }
  // Curving bends corners below the straight cell's (whose smallest is about 35 degrees).
  EXPECT_LT(lowest, 20.0);
  // A curved edge leaving its corner along another edge folds the corner flat: angle 0.
  auto folded = StraightTetra({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 });
  folded[4] = { 0.25, 0.5, 0.0 }; // edge 0-1 leaves corner 0 along 4m - 3a - b = (0, 2, 0), edge 0-2's direction
  EXPECT_NEAR(CornerDihedralAngles(folded, 0)[0], 0.0, 1e-9);
}

TEST(TetraJacobian, CoefficientsBoundSampledDeterminants)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> offset(-0.08, 0.08);
  int invalid = 0, valid = 0, refinedValid = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    auto nodes = StraightTetra({ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 });
    for (int e = 4; e < 10; ++e)
      for (double& x : nodes[e])
        x += offset(random) * (trial % 5 + 1);
    const auto c = JacobianCoefficients(nodes);
    const double lo = *std::min_element(c.begin(), c.end()), hi = *std::max_element(c.begin(), c.end());
    double smallest = 0.0;
    const double ratio = SampledScaledJacobian(nodes, 10, smallest);
    // Sampled values lie between the extreme coefficients; corners are where B_{3e_k} = 1.
    EXPECT_GE(smallest, lo - 1e-9);
    EXPECT_LE(smallest * (ratio > 0 ? 1.0 / ratio : 1.0), hi + 1e-9);
    const double certified = CertifiedScaledJacobian(nodes);
    if (certified > 0.0)
    {
      ++valid;
      EXPECT_GT(smallest, 0.0);
      EXPECT_GE(ratio, certified - 1e-12);
    }
    // Subdivision tightens the bound and never passes the truth (sampled ratios are above it).
    const double refined = CertifiedScaledJacobian(nodes, 1.0, 2);
    if (certified > 0.0)
      EXPECT_GE(refined, certified - 1e-12);
    if (refined > 0.0)
    {
      ++refinedValid;
      EXPECT_GT(smallest, 0.0);
      EXPECT_GE(ratio, refined - 1e-12);
    }
    invalid += smallest <= 0.0 ? 1 : 0;
  }
  // The sample holds both kinds, so the assertions above were exercised.
  EXPECT_GT(valid, 100);
  EXPECT_GT(invalid, 100);
  EXPECT_GT(refinedValid, valid); // cells the coefficients alone could not prove valid
  std::cout << "[ jacobian ] proved valid: " << valid << " whole, " << refinedValid << " with 2 levels of subdivision; "
            << 2000 - invalid << " positive at every sample\n";
}

TEST(QuadraticFidelity, FlatteningIsWithinItsTolerance)
{
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> offset(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial)
  {
    std::array<Point3, 6> n{ Point3{ 0, 0, 0 }, Point3{ 6, 0, 0 }, Point3{ 0, 5, 0 } };
    for (int k = 0; k < 3; ++k)
    {
      n[3 + k] = Scale(Add(n[(k + 1) % 3], n[(k + 2) % 3]), 0.5);
      for (double& x : n[3 + k])
        x += offset(random);
    }
    const double tolerance = 1.0 / 64.0;
    const int level = FlatteningLevel(n, tolerance);
    ASSERT_GE(level, 0);
    const auto triangles = FlattenFace(n, level);
    ASSERT_EQ(triangles.size(), std::size_t(1) << (2 * level));
    // Points of the face (evaluated directly) are within the tolerance of the flattening.
    for (int i = 0; i <= 40; ++i)
      for (int j = 0; i + j <= 40; ++j)
      {
        const double l[3] = { (40.0 - i - j) / 40, i / 40.0, j / 40.0 };
        Point3 x{ 0, 0, 0 };
        for (int k = 0; k < 3; ++k)
        {
          x = Add(x, Scale(n[k], l[k] * (2 * l[k] - 1)));
          x = Add(x, Scale(n[3 + k], 4 * l[(k + 1) % 3] * l[(k + 2) % 3]));
        }
        double best = 1e300;
        for (const auto& t : triangles)
          best = std::min(best, SquaredDistanceToTriangle(x, t[0], t[1], t[2]));
        EXPECT_LE(std::sqrt(best), tolerance + 1e-12);
      }
  }
}

std::string Violations(const std::vector<std::string>& violated)
{
  std::ostringstream out;
  for (const std::string& line : violated)
    out << "  " << line << "\n";
  return out.str();
}

constexpr int kImagesPerShard = 12;
constexpr std::uint64_t kFirstSeed = 9100;

/// The shard's image for `seed`: the blob generator on even seeds, boxes on odd ones.
testing::RandomLabelImage ShardImage(std::uint64_t seed)
{
  return seed % 2 == 0 ? testing::GenerateRandomLabelImageWithDescription(seed, 3)
                       : testing::GenerateRandomBoxImage(seed, 3, 12);
}

class QuadraticProperties : public ::testing::TestWithParam<int>
{
};

TEST_P(QuadraticProperties, ValidWithinBoundsSameTopologyOnRandomImages)
{
  const std::uint64_t first = kFirstSeed + static_cast<std::uint64_t>(GetParam()) * kImagesPerShard;
  std::size_t curved = 0, fitted = 0, linear = 0, quadratic = 0, faces = 0, cells = 0;
  for (std::uint64_t seed = first; seed < first + kImagesPerShard; ++seed)
  {
    const testing::RandomLabelImage random = ShardImage(seed);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    const DecimationParameters decimation = testing::DrawDecimationParameters(seed, 3, mesher);
    testing::QuadraticRun run;
    const auto violated = testing::ViolatedQuadraticGuarantees(random.Image, mesher, decimation, &run);
    ASSERT_TRUE(violated.empty()) << "seed " << seed << ", h = " << mesher.ImageToMeshDistance << "/"
                                  << mesher.MeshToImageDistance << ", angle " << decimation.MinimumAngle << "\n"
                                  << Violations(violated) << random.Describe();
    curved += run.Result.CurvedEdges;
    fitted += run.Result.FittedEdges;
    linear += run.MisclassifiedLinear;
    quadratic += run.MisclassifiedCurved;
    faces += run.Result.FacesFailedDistance;
    cells += run.Result.CellsFailedQuality;
  }
  std::cout << "[ quadratic ] seeds " << first << "-" << first + kImagesPerShard - 1 << ": " << curved << " of "
            << fitted << " fitted edges curved; misclassified voxels " << linear << " linear, " << quadratic
            << " quadratic; pulled back: " << faces << " faces for a distance, " << cells << " cells for det J\n";
}

INSTANTIATE_TEST_SUITE_P(Shards, QuadraticProperties, ::testing::Range(0, 4));

TEST(QuadraticProperties, PinnedSeeds)
{
  // Seeds a scan once failed (smooth 3D family): 1140875 and 1141367 made the check count a
  // refined node lying on another cell's piecewise-linear sub-triangle as a hanging vertex (a
  // fault of the check, not the mesh: see QuadraticGuarantees.cxx).
  for (std::uint64_t seed : { 1140875u, 1141367u })
  {
    const testing::RandomLabelImage random = testing::GenerateRandomLabelImageWithDescription(seed, 3);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    const auto violated = testing::ViolatedQuadraticGuarantees(
      random.Image, mesher, testing::DrawDecimationParameters(seed, 3, mesher));
    EXPECT_TRUE(violated.empty()) << "seed " << seed << "\n" << Violations(violated) << random.Describe();
  }
}

/// Over the shards' images until one is found: the violations containing `what` with `curver`.
int ViolationsWithTheCurver(const std::string& what, const QuadraticParameters& curver)
{
  int found = 0;
  for (std::uint64_t seed = kFirstSeed; seed < kFirstSeed + 4 * kImagesPerShard && found == 0; ++seed)
  {
    const testing::RandomLabelImage random = ShardImage(seed);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    const auto violated = testing::ViolatedQuadraticGuarantees(
      random.Image, mesher, testing::DrawDecimationParameters(seed, 3, mesher), nullptr, &curver);
    for (const std::string& line : violated)
      found += line.find(what) != std::string::npos ? 1 : 0;
  }
  return found;
}

TEST(QuadraticProperties, WithoutTheDistanceCertificateSomeBoundBreaks)
{
  // The fit lands on the staircase's mean, within the bounds on the random sample (which then
  // needs the certificate only for its margin). Offsets of a fit overshooting four times, on
  // smooth shapes: only the certificate keeps the bounds, whatever the offsets.
  int violations = 0;
  for (const LabelImage& image : { testing::MakeSphere(20, 7.3), testing::MakeTorus(22, 6.5, 3.0) })
  {
    MesherParameters mesher;
    mesher.ImageToMeshDistance = mesher.MeshToImageDistance = 1.0;
    DecimationParameters decimation;
    decimation.MinimumAngle = 15.0;
    decimation.ImageToMeshDistance = decimation.MeshToImageDistance = 1.0;
    QuadraticParameters curver;
    curver.ImageToMeshDistance = curver.MeshToImageDistance = 1.0;
    curver.MinimumScaledJacobian = testing::kQuadraticScaledJacobian;
    const SimplexMesh linear = DecimateMesh(image, MeshLabelImage(image, mesher).Mesh, decimation).Mesh;
    for (bool certify : { true, false })
    {
      testing::QuadraticRun run;
      run.Result = FitQuadraticMesh(linear, image, curver);
      ASSERT_GT(run.Result.FittedEdges, 0u);
      for (Point3& offset : run.Result.Mesh.Offset)
        offset = Scale(offset, 4.0);
      curver.CertifyDistances = certify;
      CertifyQuadraticMesh(run.Result, image, curver);
      const auto violated = testing::ViolatedQuadraticMeshGuarantees(image, mesher, linear, run);
      if (certify)
        EXPECT_TRUE(violated.empty()) << Violations(violated);
      else
        for (const std::string& line : violated)
          violations += line.find("beyond the bounds") != std::string::npos ? 1 : 0;
    }
  }
  EXPECT_GT(violations, 0);
}

TEST(QuadraticProperties, WithoutTheJacobianCertificateSomeCellFallsBelowTheBound)
{
  QuadraticParameters curver;
  curver.CertifyValidity = false;
  curver.CertifyDistances = false; // fitted curves as they come, so that some fold their cells
  EXPECT_GT(ViolationsWithTheCurver("det J", curver), 0);
}

TEST(QuadraticProperties, WithoutTheCornerCertificateSomeCornerFallsBelowTheAngle)
{
  QuadraticParameters curver;
  curver.MinimumScaledJacobian = testing::kQuadraticScaledJacobian;
  curver.CertifyCorners = false;
  EXPECT_GT(ViolationsWithTheCurver("corner angle", curver), 0);
}

TEST(QuadraticCurver, RefusesAMeshThatDoesNotFillItsBox)
{
  // Without the background cells the faces of one cell are not all on the box: the interface
  // lookup, which takes those on the box, would miss some. One plain error instead.
  const LabelImage image = testing::MakeSphere(16, 5.3);
  const SimplexMesh whole = DecimateMesh(image, MeshLabelImage(image, MesherParameters{}).Mesh, DecimationParameters{}).Mesh;
  EXPECT_NO_THROW(CurveQuadratic(whole, image, QuadraticParameters{}));
  SimplexMesh foreground;
  foreground.Dimension = 3;
  foreground.Points = whole.Points;
  for (std::size_t c = 0; c < whole.NumberOfCells(); ++c)
    if (whole.Materials[c] != 0)
    {
      foreground.Connectivity.insert(foreground.Connectivity.end(), whole.Cell(c), whole.Cell(c) + 4);
      foreground.Materials.push_back(whole.Materials[c]);
    }
  ASSERT_GT(foreground.NumberOfCells(), 0u);
  try
  {
    CurveQuadratic(foreground, image, QuadraticParameters{});
    ADD_FAILURE() << "a mesh without its background was curved";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("fills its box"), std::string::npos) << e.what();
  }
}

TEST(QuadraticCurver, StopsWithinARoundWhenAsked)
{
  // The certification's reports come at each round and within it (the distance test asks
  // between chunks): stopped at any of them, the run throws instead of finishing. One thread, so
  // that the calling thread takes every chunk and the reports are the same in every run.
  struct OneThread
  {
    OneThread() { SetThreadLimit(1); }
    ~OneThread() { SetThreadLimit(0); }
  } oneThread;
  const LabelImage image = testing::MakeSphere(20, 7.3);
  MesherParameters mesher;
  DecimationParameters decimation;
  const SimplexMesh linear = DecimateMesh(image, MeshLabelImage(image, mesher).Mesh, decimation).Mesh;
  std::size_t reports = 0;
  ProgressObserver counting{ [&](const std::string& stage, double) {
    reports += stage == "quadratic certify" ? 1 : 0;
    return true;
  } };
  const QuadraticResult whole = CurveQuadratic(linear, image, QuadraticParameters{}, counting);
  ASSERT_GT(reports, whole.Rounds) << "no report within a round";
  for (std::size_t stopAt = 1; stopAt <= reports; ++stopAt)
  {
    std::size_t seen = 0;
    ProgressObserver stopping{ [&](const std::string& stage, double) {
      seen += stage == "quadratic certify" ? 1 : 0;
      return seen < stopAt;
    } };
    EXPECT_THROW(CurveQuadratic(linear, image, QuadraticParameters{}, stopping), AbortRequested) << stopAt;
  }
}

struct SmoothShape
{
  const char* Name;
  LabelImage Image;
};

TEST(QuadraticSmoothShapes, FewerMisclassifiedVoxelsWithEveryGuarantee)
{
  const SmoothShape shapes[] = {
    { "sphere r=9", testing::MakeSphere(24, 9.3) },
    { "torus 8/3.5", testing::MakeTorus(26, 8.0, 3.5) },
    { "nested spheres", testing::MakeNestedSpheres(26, { 10.5, 6.2 }, { 1, 2 }) },
    { "Cassini 32", testing::MakeCassiniVolume(32) },
  };
  for (const SmoothShape& shape : shapes)
  {
    MesherParameters mesher;
    mesher.ImageToMeshDistance = mesher.MeshToImageDistance = 2.0;
    DecimationParameters decimation;
    decimation.MinimumAngle = 15.0;
    decimation.ImageToMeshDistance = decimation.MeshToImageDistance = 2.0;
    testing::QuadraticRun run;
    const auto violated = testing::ViolatedQuadraticGuarantees(shape.Image, mesher, decimation, &run);
    EXPECT_TRUE(violated.empty()) << shape.Name << "\n" << Violations(violated);
    EXPECT_LT(run.MisclassifiedCurved, run.MisclassifiedLinear) << shape.Name;
    // The filters' count refines the curved cells one at a time, never holding the refined mesh:
    // it must agree with the count on the whole refined mesh.
    EXPECT_EQ(MeasureVoxelAccuracy(shape.Image, run.Result.Mesh, 4).Misclassified, run.MisclassifiedCurved) << shape.Name;
    std::cout << "[ quadratic ] " << shape.Name << ": " << run.Result.CurvedEdges << " of " << run.Result.FittedEdges
              << " fitted edges curved, misclassified voxels " << run.MisclassifiedLinear << " linear -> "
              << run.MisclassifiedCurved << " quadratic\n";
  }
}

} // namespace
} // namespace labelmesher
