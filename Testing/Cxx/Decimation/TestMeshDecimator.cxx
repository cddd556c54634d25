// SPDX-License-Identifier: GPL-2.0-or-later
// The decimator's core function (Filters/Core/Decimation/MeshDecimator.h):
// what it refuses (parameters, meshes that are not the whole box of this
// image's mesh, inputs that already break a bound), that it reports progress
// and stops on request, that it decimates, and that each of its three checks
// is what keeps its guarantee: with one switched off (a test-only parameter)
// the independent measurements (MeshGuarantees.h) find that guarantee broken,
// so the property tests would fail if the check were lost.

#include "Checks/MeshChecks.h"
#include "DecimatorGuarantees.h"
#include "Decimation/MeshDecimator.h"
#include "LabelOctreeMesher.h"
#include "Mesh/MeshSelection.h"
#include "MesherGuarantees.h"
#include "MeshGuarantees.h"
#include "RandomLabelImages.h"
#include "SyntheticShapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace labelmesher
{
namespace
{

std::string ErrorOf(const LabelImage& image, const SimplexMesh& mesh, const DecimationParameters& p)
{
  try
  {
    DecimateMesh(image, mesh, p);
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return "";
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

TEST(MeshDecimator, RefusesBadParametersAndMeshesNotOfThisImage)
{
  const LabelImage image = testing::MakeCassiniVolume(24);
  const SimplexMesh mesh = MeshLabelImage(image, {}).Mesh;
  DecimationParameters p;
  p.MinimumAngle = 31.0; // above the proven 30 degrees in 3D
  EXPECT_TRUE(Contains(ErrorOf(image, mesh, p), "minimum angle")) << ErrorOf(image, mesh, p);
  p.MinimumAngle = 0.0;
  EXPECT_TRUE(Contains(ErrorOf(image, mesh, p), "minimum angle"));
  p = {};
  p.ImageToMeshDistance = -1.0;
  EXPECT_TRUE(Contains(ErrorOf(image, mesh, p), "non-negative"));
  p = {};
  // Without its background the mesh does not fill its box.
  EXPECT_TRUE(Contains(ErrorOf(image, SelectMaterials(mesh), p), "fill its box"));
  // Another image's mesh: off this image's extent.
  const LabelImage larger = testing::MakeCassiniVolume(40);
  EXPECT_TRUE(Contains(ErrorOf(larger, mesh, p), "does not cover the image"));
  // A 2D image for a 3D mesh.
  EXPECT_TRUE(Contains(ErrorOf(testing::MakeDisc(16, 5.0), mesh, p), "3D"));
  // A point off the half-voxel lattice.
  SimplexMesh moved = mesh;
  moved.Points[moved.Connectivity[0]][0] += 0.1;
  EXPECT_TRUE(Contains(ErrorOf(image, moved, p), "lattice"));
  // Decimation cannot bring a mesh closer to the image: meshed at h = 2, it
  // cannot be decimated at h = 0 (the pixel-exact image has no room at all).
  p.ImageToMeshDistance = p.MeshToImageDistance = 0.0;
  const LabelImage disc = testing::MakeDisc(40, 13.3);
  const SimplexMesh coarse = MeshLabelImage(disc, {}).Mesh;
  const std::string error = ErrorOf(disc, coarse, p);
  EXPECT_TRUE(Contains(error, "does not hold h(")) << error;
}

TEST(MeshDecimator, RefusesAnInputWithASmallerAngleThanAskedFor)
{
  // The initial mesh's smallest angle in 2D is 45 degrees: asking for 45 is
  // fine, but a mesh decimated at 10 cannot be decimated again at 40.
  const LabelImage disc = testing::MakeDisc(48, 17.0);
  DecimationParameters p;
  p.MinimumAngle = 10.0;
  const DecimationResult once = DecimateMesh(disc, MeshLabelImage(disc, {}).Mesh, p);
  p.MinimumAngle = 40.0;
  EXPECT_TRUE(Contains(ErrorOf(disc, once.Mesh, p), "below the minimum angle")) << ErrorOf(disc, once.Mesh, p);
  p.MinimumAngle = 10.0;
  EXPECT_EQ(ErrorOf(disc, once.Mesh, p), "") << "a decimated mesh can be decimated again at its own bound";
}

TEST(MeshDecimator, DecimatesAndKeepsEveryGuaranteeOnASmoothShape)
{
  for (const int dimension : { 2, 3 })
  {
    const LabelImage image = dimension == 2 ? testing::MakeDisc(64, 22.3) : testing::MakeCassiniVolume(40);
    const MesherParameters mesher;
    DecimationParameters p;
    DecimationCounts counts;
    const auto problems = testing::ViolatedDecimatorGuarantees(image, mesher, p, &counts);
    EXPECT_TRUE(problems.empty()) << problems.front();
    EXPECT_LT(counts.CellsAfter * 5, counts.CellsBefore) << dimension << "D: " << counts.CellsBefore << " -> "
                                                         << counts.CellsAfter;
    EXPECT_EQ(counts.CellsBefore - counts.CellsAfter > 0, counts.Merges > 0);
    EXPECT_GT(counts.Offers, counts.Merges);
  }
}

TEST(MeshDecimator, NoMergeIsTheInputMesh)
{
  const LabelImage image = testing::MakeDisc(32, 10.5);
  const SimplexMesh mesh = MeshLabelImage(image, {}).Mesh;
  DecimationParameters p;
  p.MaximumMerges = 0;
  const DecimationResult result = DecimateMesh(image, mesh, p);
  EXPECT_EQ(result.Counts.Merges, 0u);
  EXPECT_EQ(result.Mesh.NumberOfCells(), mesh.NumberOfCells());
  EXPECT_EQ(result.Mesh.Materials, mesh.Materials);
}

TEST(MeshDecimator, ReportsProgressAndHonoursAbort)
{
  const LabelImage image = testing::MakeCassiniVolume(40);
  const SimplexMesh mesh = MeshLabelImage(image, {}).Mesh;
  double last = -1.0;
  bool monotone = true;
  std::vector<std::string> stages;
  ProgressObserver watch;
  watch.Callback = [&](const std::string& stage, double fraction) {
    monotone = monotone && fraction >= last - 1e-12 && fraction <= 1.0;
    last = fraction;
    if (stages.empty() || stages.back() != stage)
      stages.push_back(stage);
    return true;
  };
  DecimateMesh(image, mesh, {}, watch);
  EXPECT_TRUE(monotone);
  EXPECT_EQ(last, 1.0);
  EXPECT_NE(std::find(stages.begin(), stages.end(), "decimation"), stages.end());

  for (const std::string stopAt : { "decimation setup", "decimation" })
  {
    ProgressObserver stop;
    bool reached = false;
    stop.Callback = [&](const std::string& stage, double) {
      reached = reached || stage == stopAt;
      return stage != stopAt;
    };
    EXPECT_THROW(DecimateMesh(image, mesh, {}, stop), AbortRequested) << stopAt;
    EXPECT_TRUE(reached) << stopAt;
  }
}

/// Images of the property tests' generator, with their drawn parameters, on
/// which the decimator runs with `off` switched off; counts those whose
/// measured violations include one containing `symptom`.
int ImagesBrokenWithout(void (*off)(DecimationParameters&), const std::string& symptom, int dimension, int images)
{
  int broken = 0;
  for (int seed = 0; seed < images; ++seed)
  {
    const testing::RandomLabelImage random = testing::GenerateRandomLabelImageWithDescription(seed, dimension);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    DecimationParameters p = testing::DrawDecimationParameters(seed, dimension, mesher);
    if (off)
      off(p);
    for (const std::string& problem : testing::ViolatedDecimatorGuarantees(random.Image, mesher, p))
      if (Contains(problem, symptom))
      {
        ++broken;
        break;
      }
  }
  return broken;
}

TEST(MeshDecimatorChecks, WithAllChecksNoGuaranteeBreaksOnTheseImages)
{
  EXPECT_EQ(ImagesBrokenWithout(nullptr, "", 2, 20), 0);
  EXPECT_EQ(ImagesBrokenWithout(nullptr, "", 3, 4), 0);
}

TEST(MeshDecimatorChecks, WithoutTheQualityCheckAnglesFallBelowTheBound)
{
  auto off = [](DecimationParameters& p) { p.Checks.Quality = false; };
  EXPECT_GE(ImagesBrokenWithout(off, "minimum angle", 2, 5), 4);
  // 3D: measured directly (the distance and topology checks of a tangled
  // mesh take long and say nothing more).
  const LabelImage image = testing::MakeCassiniVolume(24);
  DecimationParameters p;
  off(p);
  const QualityReport quality = MeasureQuality(DecimateMesh(image, MeshLabelImage(image, {}).Mesh, p).Mesh);
  EXPECT_TRUE(quality.InvertedCells > 0 || quality.MinimumAngle < p.MinimumAngle) << quality.MinimumAngle;
}

TEST(MeshDecimatorChecks, WithoutTheTopologyCheckMaterialsChangeTopology)
{
  auto off = [](DecimationParameters& p) { p.Checks.Topology = false; };
  EXPECT_GE(ImagesBrokenWithout(off, "components, chi", 2, 20), 3);
}

TEST(MeshDecimatorChecks, WithoutTheFidelityCheckTheDistancesExceedTheirBounds)
{
  auto off = [](DecimationParameters& p) { p.Checks.Fidelity = false; };
  EXPECT_GE(ImagesBrokenWithout(off, "Hausdorff bound exceeded", 2, 5), 4);
  EXPECT_GE(ImagesBrokenWithout(off, "Hausdorff bound exceeded", 3, 2), 2);
}

} // namespace
} // namespace labelmesher
