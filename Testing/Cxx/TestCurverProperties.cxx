// SPDX-License-Identifier: GPL-2.0-or-later
//
// The curver on seeded random 2D label images (RandomLabelImages.h: 2-4
// labels, touching materials, one-pixel lines, holes, rings, border contact,
// speckle) meshed with distance bounds from {0, 1, 2, 3}, curved C1 or C2:
//   - the result is either Valid, and then every cell is positive under dense
//     sampling of det J (an independent check of the proof), or not Valid with
//     the failing cells listed, each of them indeed not provable; never an
//     invalid mesh reported as valid;
//   - the curved interfaces are C1/C2 at every joint and interpolate the
//     linear mesh's boundary vertices.
// A failure prints the seed and what its image contains.

#include "Curving/BezierCurver.h"
#include "CurvingChecks.h"
#include "LabelOctreeMesher.h"
#include "RandomLabelImages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace labelmesher
{
namespace
{

constexpr int kImagesPerShard = 50;
constexpr std::uint64_t kFirstSeed = 7000;

void CheckCurving(std::uint64_t seed, std::size_t& invalidMeshes)
{
  const testing::RandomLabelImage random = testing::GenerateRandomLabelImageWithDescription(seed, 2);
  testing::SeededRandom draw(seed ^ 0x5851f42d4c957f2dull);
  MesherParameters meshing;
  meshing.ImageToMeshDistance = static_cast<double>(draw.Int(0, 3));
  meshing.MeshToImageDistance = static_cast<double>(draw.Int(0, 3));
  CurvingParameters parameters;
  parameters.Smoothing.Continuity = draw.Chance(0.5) ? Smoothness::C1 : Smoothness::C2;
  parameters.HasBorder = true;
  parameters.Border = { -0.5, random.Image.Dimensions[0] - 0.5, -0.5, random.Image.Dimensions[1] - 0.5 };
  std::ostringstream context;
  context << "seed " << seed << ", h = " << meshing.ImageToMeshDistance << "/"
          << meshing.MeshToImageDistance << ", C"
          << (parameters.Smoothing.Continuity == Smoothness::C1 ? 1 : 2) << "\n"
          << random.Describe();

  const SimplexMesh linear = testing::ForegroundMesh(MeshLabelImage(random.Image, meshing).Mesh);
  CurvingResult result;
  ASSERT_NO_THROW(result = CurveMesh(linear, parameters)) << context.str();
  ASSERT_EQ(result.Mesh.Cells.size(), result.Linear.NumberOfCells()) << context.str();

  std::vector<bool> listed(result.Mesh.Cells.size(), false);
  for (std::size_t c : result.InvalidCells)
  {
    listed[c] = true;
  }
  ASSERT_EQ(result.Valid, result.InvalidCells.empty()) << context.str();
  for (std::size_t c = 0; c < result.Mesh.Cells.size(); ++c)
  {
    const CubicTriangle cell = result.Mesh.Cell(c);
    const bool proven = ClassifyValidity(cell) == Validity::Valid;
    ASSERT_EQ(proven, !listed[c]) << "cell " << c << "\n" << context.str();
    if (proven)
    {
      ASSERT_GT(testing::SampledMinimumJacobian(cell), 0.0)
        << "cell " << c << " proven valid but det J <= 0 at a sample\n" << context.str();
    }
  }
  invalidMeshes += result.Valid ? 0 : 1;

  const testing::JointContinuity joints = testing::MeasureJointContinuity(
    result.Linear, result.Mesh, parameters.Border, parameters.Smoothing.Continuity);
  EXPECT_LT(joints.FirstDerivativeMismatch, 1e-9) << context.str();
  EXPECT_LT(joints.SecondDerivativeMismatch, 1e-9) << context.str();
  EXPECT_EQ(joints.VertexMovement, 0.0) << context.str();
}

class CurverProperties : public ::testing::TestWithParam<int>
{
};

TEST_P(CurverProperties, ValidOrReportedOnRandomImages)
{
  std::size_t invalidMeshes = 0;
  const std::uint64_t first = kFirstSeed + static_cast<std::uint64_t>(GetParam()) * kImagesPerShard;
  for (std::uint64_t seed = first; seed < first + kImagesPerShard; ++seed)
  {
    CheckCurving(seed, invalidMeshes);
    if (HasFatalFailure())
    {
      return;
    }
  }
  std::cout << "[ curver ] seeds " << first << "-" << first + kImagesPerShard - 1 << ": "
            << invalidMeshes << " meshes with cells that could not be made valid\n";
}

INSTANTIATE_TEST_SUITE_P(Shards, CurverProperties, ::testing::Range(0, 4));

} // namespace
} // namespace labelmesher
