// SPDX-License-Identifier: GPL-2.0-or-later
// The memory estimate's inputs (Support/MemoryEstimate.h) and libsc's
// allocation failures as exceptions (Octree/OctreeRefinement.cxx).
#include "Decimation/ImageBoundary.h"
#include "Octree/OctreeRefinement.h"
#include "Support/MemoryEstimate.h"

#include "RandomLabelImages.h"

#include <gtest/gtest.h>

#include <p4est_base.h>

#include <cstdint>
#include <new>

namespace labelmesher
{
namespace
{

TEST(MemoryEstimate, CountsTheFacesOfSmallImagesByHand)
{
  LabelImage one(3, 3, 3);
  one(1, 1, 1) = 5;
  EXPECT_EQ(CountInterfaceFaces(one), 6u);
  LabelImage full(2, 2, 2);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        full(i, j, k) = 1;
  EXPECT_EQ(CountInterfaceFaces(full), 24u); // the image's own border, outside = 0
  full(0, 0, 0) = 2;
  EXPECT_EQ(CountInterfaceFaces(full), 27u); // and the three faces of the corner voxel inside
  LabelImage pixel(4, 4, 1);
  pixel(3, 0, 0) = 1; // on the image's corner: two of its edges are the border
  EXPECT_EQ(CountInterfaceFaces(pixel), 4u);
}

TEST(MemoryEstimate, CountsWhatTheDecimatorsImageBoundaryLists)
{
  // ImageBoundary builds the list the fidelity checks use, by its own code.
  for (int dimension : { 2, 3 })
    for (std::uint64_t seed = 0; seed < 40; ++seed)
    {
      const LabelImage image = testing::GenerateRandomLabelImage(seed, dimension);
      EXPECT_EQ(CountInterfaceFaces(image), ImageBoundary(image).Faces().size())
        << "seed " << seed << ", " << dimension << "D";
    }
}

TEST(MemoryEstimate, GrowsWithTheBoundaryAndCountsDecimation)
{
  LabelImage small(32, 32, 32), large(32, 32, 32);
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i)
      {
        small(i, j, k) = i < 16 ? 1 : 2;
        large(i, j, k) = 1 + (i + j + k) % 2; // a checkerboard: every face an interface
      }
  const MemoryEstimate a = EstimateMemory(small, false), b = EstimateMemory(large, false);
  EXPECT_EQ(a.Voxels, 32768u);
  EXPECT_LT(a.InterfaceFaces, b.InterfaceFaces);
  EXPECT_LT(a.InitialCells, b.InitialCells);
  EXPECT_LT(a.RunBytes, b.RunBytes);
  EXPECT_GE(EstimateMemory(large, true).RunBytes, b.RunBytes);
  EXPECT_EQ(a.InterfaceFaces, 7168u); // the cut 32 x 32 and the border 6 x 32 x 32
  EXPECT_EQ(DescribeEstimate(a), "32,768 voxels, 7,168 voxel faces between labels");
  EXPECT_GT(EstimateDecimationMemory(2000000), EstimateDecimationMemory(1000000));
}

TEST(MemoryEstimate, StreamedRunsNeedLessWithSmallerBlocks)
{
  LabelImage checkerboard(48, 48, 48);
  for (int k = 0; k < 48; ++k)
    for (int j = 0; j < 48; ++j)
      for (int i = 0; i < 48; ++i)
        checkerboard(i, j, k) = 1 + (i + j + k) % 2;
  const MemoryEstimate whole = EstimateStreamedMemory(checkerboard, 0);
  const MemoryEstimate blocks = EstimateStreamedMemory(checkerboard, 50000);
  ASSERT_GT(whole.InitialCells, 500000u) << "the image must span several blocks";
  EXPECT_EQ(whole.InterfaceFaces, blocks.InterfaceFaces);
  EXPECT_LT(blocks.RunBytes, whole.RunBytes);
  // One block that holds the whole mesh is the same as no blocks; either
  // needs less than mesher and decimator apart (no VTK grid of the initial mesh).
  EXPECT_EQ(EstimateStreamedMemory(checkerboard, whole.InitialCells + 1).RunBytes, whole.RunBytes);
  EXPECT_LT(whole.RunBytes, EstimateMemory(checkerboard, true).RunBytes);
}

TEST(MemoryEstimate, TheQuadraticStageAddsPerInterfaceFaceAndMoreWhenMeasured)
{
  LabelImage small(20, 20, 20), large(40, 40, 40);
  for (LabelImage* image : { &small, &large })
    for (int k = 0; k < image->Dimensions[2]; ++k)
      for (int j = 0; j < image->Dimensions[1]; ++j)
        for (int i = 0; i < image->Dimensions[0]; ++i)
          (*image)(i, j, k) = 1 + (i / 4 + j / 4 + k / 4) % 3;
  for (const LabelImage* image : { &small, &large })
  {
    const MemoryEstimate linear = EstimateStreamedMemory(*image, 0);
    const MemoryEstimate quadratic = WithQuadraticStage(linear, false), measured = WithQuadraticStage(linear, true);
    EXPECT_EQ(quadratic.InterfaceFaces, linear.InterfaceFaces);
    EXPECT_GT(quadratic.RunBytes, linear.RunBytes);
    EXPECT_GT(measured.RunBytes, quadratic.RunBytes);
  }
  // The larger image has more interface: the stage needs more.
  const MemoryEstimate a = EstimateStreamedMemory(small, 0), b = EstimateStreamedMemory(large, 0);
  ASSERT_GT(b.InterfaceFaces, a.InterfaceFaces);
  EXPECT_GT(WithQuadraticStage(b, false).RunBytes - b.RunBytes, WithQuadraticStage(a, false).RunBytes - a.RunBytes);
}

TEST(MemoryEstimate, LibscAllocationFailureThrowsInsteadOfAborting)
{
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reports the impossible allocation itself";
#else
  detail::InitializeP4est(); // MPI through the starter GTestMain.cxx registers
  // Without the abort handler this ends the process (MPI_Abort's banner).
  EXPECT_THROW(sc_malloc(p4est_package_id, std::size_t(1) << 62), std::bad_alloc);
  // The process goes on: p4est still works.
  void* p = sc_malloc(p4est_package_id, 64);
  EXPECT_NE(p, nullptr);
  sc_free(p4est_package_id, p);
#endif
}

} // namespace
} // namespace labelmesher
