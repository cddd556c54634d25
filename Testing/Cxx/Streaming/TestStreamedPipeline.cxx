// SPDX-License-Identifier: GPL-2.0-or-later
//
// The block-streamed pipeline (Streaming/StreamedPipeline.h):
//   - one block is exactly mesher then decimator (DecimateMesh(MeshLabelImage));
//   - with blocks of a few leaves, so that every image crosses many block
//     borders, every guarantee of the decimated mesh holds (the independent
//     measurements of MeshGuarantees.h) on smooth, box and thin-feature
//     random images, 2D and 3D;
//   - with a merge check switched off, the same tests find broken guarantees;
//   - the mesh is the same on 1, 2, 3 and 8 threads, and on 1, 2, 3 and 8
//     processes (ranks run one after another in this process, their parts
//     passed as bytes); a process that fails makes rank 0 fail naming it,
//     after taking every message still on its way.
// Block keys (BlockPlan.h): a box of voxels lies in a run of leaves exactly
// when the keys of its corners do.

#include "DecimatorGuarantees.h"
#include "MesherGuarantees.h"
#include "LabelOctreeMesher.h"
#include "RandomLabelImages.h"
#include "Streaming/BlockPlan.h"
#include "Streaming/MeshPart.h"
#include "QueuedPartExchange.h"
#include "Streaming/StreamedPipeline.h"
#include "Support/ParallelChunks.h"
#include "Support/StageClock.h"
#include "ThinFeatureImages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <sstream>
#include <stdexcept>

namespace labelmesher
{
namespace
{

bool SameMesh(const SimplexMesh& a, const SimplexMesh& b)
{
  return a.Dimension == b.Dimension && a.Points == b.Points && a.Connectivity == b.Connectivity &&
    a.Materials == b.Materials;
}

/// Blocks of a few leaves: 25 initial cells a block in 2D, 150 in 3D.
StreamingParameters TinyBlocks(int dimension)
{
  StreamingParameters p;
  p.BlockCells = dimension == 2 ? 25 : 150;
  return p;
}

TEST(StreamedPipeline, OneBlockIsMesherThenDecimator)
{
  for (int dimension : { 2, 3 })
    for (std::uint64_t seed = 40; seed < 46; ++seed)
    {
      const auto random = testing::GenerateRandomLabelImageWithDescription(seed, dimension);
      const MesherParameters mesher = testing::DrawDistanceBounds(seed);
      const DecimationParameters decimation = testing::DrawDecimationParameters(seed, dimension, mesher);
      StreamingParameters oneBlock;
      oneBlock.BlockCells = 0;
      const StreamedResult streamed = MeshAndDecimate(random.Image, mesher, decimation, oneBlock);
      const DecimationResult direct = DecimateMesh(random.Image, MeshLabelImage(random.Image, mesher).Mesh, decimation);
      EXPECT_EQ(streamed.Streaming.Blocks, 1u);
      EXPECT_EQ(streamed.Streaming.AssembledCells, 0u);
      EXPECT_TRUE(SameMesh(streamed.Decimated.Mesh, direct.Mesh)) << "seed " << seed << ", " << dimension << "D";
      EXPECT_EQ(streamed.Decimated.Counts.Merges, direct.Counts.Merges);
    }
}

struct Family
{
  const char* Name;
  int Dimension;
  std::uint64_t FirstSeed;
  int Images;
  std::size_t BlockCells;
  int MinimumBlocks; ///< per image, on average
};

class StreamedGuarantees : public ::testing::TestWithParam<Family>
{
};

testing::RandomLabelImage Generate(const std::string& family, std::uint64_t seed, int dimension)
{
  if (family == "boxes")
    return testing::GenerateRandomBoxImage(seed, dimension, dimension == 3 ? 14 : 24);
  if (family == "thin")
    return testing::GenerateThinFeatureImage(seed, dimension, dimension == 3 ? 12 : 20);
  return testing::GenerateRandomLabelImageWithDescription(seed, dimension);
}

TEST_P(StreamedGuarantees, EveryGuaranteeHoldsAcrossManyBlocks)
{
  const Family family = GetParam();
  std::size_t blocks = 0, images = 0, before = 0, after = 0, mergesInBlocks = 0, borderPasses = 0;
  for (int i = 0; i < family.Images; ++i)
  {
    const std::uint64_t seed = family.FirstSeed + static_cast<std::uint64_t>(i);
    const auto random = Generate(family.Name, seed, family.Dimension);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    const DecimationParameters decimation = testing::DrawDecimationParameters(seed, family.Dimension, mesher);
    DecimationCounts counts;
    StreamingCounts streamed;
    StreamingParameters streaming;
    streaming.BlockCells = family.BlockCells;
    const auto problems =
      testing::ViolatedStreamedGuarantees(random.Image, mesher, decimation, streaming, &counts, &streamed);
    std::ostringstream listed;
    for (const std::string& problem : problems)
      listed << "  " << problem << "\n";
    ASSERT_TRUE(problems.empty()) << listed.str() << "seed " << seed << ", h(I,M) <= " << mesher.ImageToMeshDistance
                                  << ", h(M,I) <= " << mesher.MeshToImageDistance << ", angle >= "
                                  << decimation.MinimumAngle << "\n"
                                  << random.Describe();
    blocks += streamed.Blocks;
    mergesInBlocks += streamed.MergesInBlocks;
    borderPasses += streamed.BorderPasses;
    ++images;
    before += counts.CellsBefore;
    after += counts.CellsAfter;
  }
  // Many borders per image, merges in the blocks as well as in the last
  // pass, border passes between blocks, and still a decimation.
  EXPECT_GE(blocks, static_cast<std::size_t>(family.MinimumBlocks) * images);
  EXPECT_GT(mergesInBlocks, 0u);
  EXPECT_GT(borderPasses, 0u);
  EXPECT_LT(after * 2, before);
}

INSTANTIATE_TEST_SUITE_P(Families, StreamedGuarantees,
  ::testing::Values(Family{ "smooth", 2, 910000, 60, 25, 5 }, Family{ "smooth", 3, 911000, 12, 150, 5 },
    Family{ "boxes", 2, 912000, 120, 25, 5 }, Family{ "boxes", 3, 913000, 12, 150, 5 },
    Family{ "thin", 2, 914000, 60, 25, 5 }, Family{ "thin", 3, 915000, 8, 150, 5 },
    // Larger blocks: most merges in the blocks, fewer borders.
    Family{ "smooth", 2, 916000, 60, 100, 2 }, Family{ "smooth", 3, 917000, 12, 2000, 2 }),
  [](const ::testing::TestParamInfo<Family>& info) {
    return std::string(info.param.Name) + std::to_string(info.param.Dimension) + "D" +
      std::to_string(info.param.BlockCells) + "cells";
  });

TEST(StreamedPipeline, WithAMergeCheckOffTheTestsFindBrokenGuarantees)
{
  // The blocks and the last pass merge with the decimator's checks; with one
  // of them off, the measurements above must see what it guards.
  for (int check = 0; check < 3; ++check)
  {
    int broken = 0;
    for (int dimension : { 2, 3 })
      for (std::uint64_t seed = 910000; seed < 910040 && broken == 0; ++seed)
      {
        const auto random = testing::GenerateRandomLabelImageWithDescription(seed, dimension);
        const MesherParameters mesher = testing::DrawDistanceBounds(seed);
        DecimationParameters decimation = testing::DrawDecimationParameters(seed, dimension, mesher);
        decimation.Checks.Quality = check != 0;
        decimation.Checks.Topology = check != 1;
        decimation.Checks.Fidelity = check != 2;
        broken += !testing::ViolatedStreamedGuarantees(random.Image, mesher, decimation, TinyBlocks(dimension)).empty();
      }
    EXPECT_GT(broken, 0) << "check " << check << " (quality, topology, fidelity) switched off";
  }
}

TEST(StreamedPipeline, SameMeshOnAnyNumberOfThreads)
{
  const auto random = testing::GenerateRandomLabelImageWithDescription(911003, 3);
  const MesherParameters mesher = testing::DrawDistanceBounds(911003);
  DecimationParameters decimation;
  StreamingParameters blocks;
  blocks.BlockCells = 2000;
  SetThreadLimit(1);
  const StreamedResult reference = MeshAndDecimate(random.Image, mesher, decimation, blocks);
  ASSERT_GT(reference.Streaming.Blocks, 2u);
  ASSERT_GT(reference.Streaming.BorderPasses, 0u);
  for (unsigned threads : { 2u, 3u, 8u })
  {
    SetThreadLimit(threads);
    const StreamedResult other = MeshAndDecimate(random.Image, mesher, decimation, blocks);
    EXPECT_TRUE(SameMesh(reference.Decimated.Mesh, other.Decimated.Mesh)) << threads << " threads";
  }
  SetThreadLimit(0);
}

/// The pipeline on `ranks` processes (testing::MeshOnQueuedRanks), with
/// whatever went wrong between them reported as a test failure.
StreamedResult MeshOnRanks(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming, int ranks, int failing = -1,
  const std::string& stopAt = "", const ProgressObserver& rootObserver = {},
  std::vector<std::array<int, 2>>* slabs = nullptr)
{
  std::vector<std::string> problems;
  struct Reported
  {
    const std::vector<std::string>& Problems;
    ~Reported()
    {
      for (const std::string& problem : Problems)
        ADD_FAILURE() << problem;
    }
  } reported{ problems };
  return testing::MeshOnQueuedRanks(
    image, mesher, decimation, streaming, ranks, problems, slabs, failing, stopAt, rootObserver);
}

TEST(StreamedPipeline, SameMeshOnAnyNumberOfProcesses)
{
  for (int dimension : { 2, 3 })
  {
    const std::uint64_t seed = dimension == 2 ? 912002 : 912003;
    const auto random = testing::GenerateRandomLabelImageWithDescription(seed, dimension);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    const DecimationParameters decimation = testing::DrawDecimationParameters(seed, dimension, mesher);
    StreamingParameters streaming;
    streaming.BlockCells = dimension == 2 ? 40 : 400;
    streaming.PartBlocks = 2;
    const StreamedResult one = MeshAndDecimate(random.Image, mesher, decimation, streaming);
    ASSERT_GE(one.Streaming.Parts, 4u) << "dimension " << dimension;
    EXPECT_GT(one.Streaming.Blocks, one.Streaming.Parts);
    const auto problems = testing::ViolatedStreamedGuarantees(random.Image, mesher, decimation, streaming);
    EXPECT_TRUE(problems.empty()) << problems.front();
    for (int ranks : { 1, 2, 3, 8 })
    {
      const StreamedResult shared = MeshOnRanks(random.Image, mesher, decimation, streaming, ranks);
      EXPECT_TRUE(shared.HoldsMesh);
      EXPECT_TRUE(SameMesh(one.Decimated.Mesh, shared.Decimated.Mesh)) << ranks << " processes, dimension " << dimension;
      EXPECT_EQ(shared.Streaming.Parts, one.Streaming.Parts);
      EXPECT_EQ(shared.Streaming.Processes, std::min<std::size_t>(ranks, one.Streaming.Parts)) << ranks;
      EXPECT_EQ(shared.Streaming.Blocks, one.Streaming.Blocks);
      EXPECT_EQ(shared.Decimated.Counts.Merges, one.Decimated.Counts.Merges);
    }
  }
}

TEST(StreamedPipeline, AProcessReadsOnlyTheSlabItsPartsNeed)
{
  // Images tall along the slab axis, so that the parts of a process other
  // than rank 0 need a fraction of them: the same mesh as one process, every
  // slab within the image and the slabs together short of every process
  // holding the whole (the memory they save).
  for (int dimension : { 2, 3 })
  {
    const std::uint64_t seed = dimension == 2 ? 912102 : 912103;
    const auto random = testing::GenerateRandomLabelImageWithDescription(seed, dimension);
    const LabelImage image = testing::StackedAlongLastAxis(random.Image, dimension == 2 ? 6 : 4);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    const DecimationParameters decimation = testing::DrawDecimationParameters(seed, dimension, mesher);
    StreamingParameters streaming;
    streaming.BlockCells = dimension == 2 ? 60 : 600;
    streaming.PartBlocks = 1;
    const StreamedResult one = MeshAndDecimate(image, mesher, decimation, streaming);
    ASSERT_GE(one.Streaming.Parts, 6u) << "dimension " << dimension;
    const int slices = image.Dimensions[static_cast<std::size_t>(image.SlabAxis())];
    for (int ranks : { 3, 6 })
    {
      std::vector<std::array<int, 2>> slabs;
      const StreamedResult shared =
        MeshOnRanks(image, mesher, decimation, streaming, ranks, -1, "", {}, &slabs);
      EXPECT_TRUE(SameMesh(one.Decimated.Mesh, shared.Decimated.Mesh)) << ranks << " processes, dimension " << dimension;
      ASSERT_EQ(slabs.size(), static_cast<std::size_t>(ranks - 1));
      int held = 0;
      for (const auto& [first, end] : slabs)
      {
        EXPECT_TRUE(0 <= first && first < end && end <= slices) << first << " " << end;
        held += end - first;
      }
      EXPECT_LT(held, (ranks - 1) * slices) << "every process held the whole image, dimension " << dimension;
    }
  }
}

TEST(StreamedPipeline, AProcessGivenAnotherImageIsNamedWhenItTakesItsSlab)
{
  // A process that reads its slab itself compares its labels with rank 0's (the assignment's
  // hash of those slices): one voxel differing in every slice, whichever slab it takes, stops
  // the run with rank 0 naming it.
  const auto random = testing::GenerateRandomLabelImageWithDescription(912104, 3);
  const LabelImage image = testing::StackedAlongLastAxis(random.Image, 3);
  LabelImage other = image;
  for (int k = 0; k < image.Dimensions[2]; ++k)
    other(0, 0, k) = other(0, 0, k) == 1 ? 2 : 1;
  const MesherParameters mesher = testing::DrawDistanceBounds(912104);
  const DecimationParameters decimation = testing::DrawDecimationParameters(912104, 3, mesher);
  StreamingParameters streaming;
  streaming.BlockCells = 600;
  streaming.PartBlocks = 1;
  std::vector<std::string> problems;
  try
  {
    testing::MeshOnQueuedRanks(image, mesher, decimation, streaming, 3, problems, nullptr, 2, "", {}, &other);
    ADD_FAILURE() << "a process given another image was not refused";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("process 2 of 3: it was given another image than process 0"),
      std::string::npos)
      << e.what();
  }
  for (const std::string& problem : problems)
    ADD_FAILURE() << problem;
}

TEST(StreamedPipeline, OnePartIsTheBlocksOfOneProcess)
{
  // PartBlocks 0: every block in one part, the pipeline as before parts
  // existed; more processes than parts leave the others idle.
  const auto random = testing::GenerateRandomLabelImageWithDescription(912005, 3);
  const MesherParameters mesher = testing::DrawDistanceBounds(912005);
  const DecimationParameters decimation;
  StreamingParameters streaming;
  streaming.BlockCells = 400;
  streaming.PartBlocks = 0;
  const StreamedResult one = MeshAndDecimate(random.Image, mesher, decimation, streaming);
  EXPECT_EQ(one.Streaming.Parts, 1u);
  ASSERT_GT(one.Streaming.Blocks, 2u);
  const StreamedResult three = MeshOnRanks(random.Image, mesher, decimation, streaming, 3);
  EXPECT_TRUE(SameMesh(one.Decimated.Mesh, three.Decimated.Mesh));
  EXPECT_EQ(three.Streaming.Processes, 1u); // the two others had no part
  streaming.PartBlocks = 1000;
  EXPECT_TRUE(SameMesh(one.Decimated.Mesh, MeshAndDecimate(random.Image, mesher, decimation, streaming).Decimated.Mesh));
}

TEST(StreamedPipeline, AProcessThatFailsIsNamedByRankZero)
{
  const auto random = testing::GenerateRandomLabelImageWithDescription(912007, 3);
  const MesherParameters mesher = testing::DrawDistanceBounds(912007);
  const DecimationParameters decimation;
  StreamingParameters streaming;
  streaming.BlockCells = 300;
  streaming.PartBlocks = 1;
  // Stopped while filling a block: its reason comes in place of its part.
  for (int failing : { 1, 2 })
  {
    // Rank 0 runs last here, so the failure's notice is there before it
    // fills its first block: it must stop at once, not after meshing its part.
    std::vector<std::string> rootStages;
    const ProgressObserver record{ [&](const std::string& s, double) {
      rootStages.push_back(s);
      return true;
    } };
    try
    {
      MeshOnRanks(random.Image, mesher, decimation, streaming, 3, failing, "fill", record);
      ADD_FAILURE() << "rank 0 did not fail with process " << failing << " stopped";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_EQ(std::string(e.what()), "process " + std::to_string(failing) + " of 3: stopped");
    }
    EXPECT_EQ(std::count(rootStages.begin(), rootStages.end(), "fill"), 0)
      << "rank 0 filled a block after process " << failing << " had failed";
  }
}

TEST(StreamedPipeline, AFailureWhilePlanningStopsEveryProcess)
{
  // Rank 0 alone refines the octree and finds the parts: stopped there, it
  // says why itself, and every other process hears of it before it asks for
  // its parts (run first here, so that the others see its failure).
  const auto random = testing::GenerateRandomLabelImageWithDescription(912007, 3);
  const MesherParameters mesher = testing::DrawDistanceBounds(912007);
  StreamingParameters streaming;
  streaming.BlockCells = 300;
  streaming.PartBlocks = 1;
  testing::QueuedRun run;
  const ProgressObserver stop{ [](const std::string& stage, double) { return stage != "octree"; } };
  testing::QueuedPartExchange zero(0, 3, run);
  EXPECT_THROW(MeshAndDecimate(random.Image, mesher, {}, streaming, stop, &zero), AbortRequested);
  for (int rank : { 2, 1 })
  {
    testing::QueuedPartExchange exchange(rank, 3, run);
    try
    {
      MeshAndDecimate(LabelImage(), mesher, {}, streaming, {}, &exchange, [](int, int) -> LabelImage {
        throw std::logic_error("a process read its slab after rank 0 had failed");
      });
      ADD_FAILURE() << "process " << rank << " went on after rank 0 had failed";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_EQ(std::string(e.what()), "stopped");
    }
  }
  EXPECT_TRUE(run.Assignments.empty() && run.Reassigned.empty());
  for (const auto& [rank, queue] : run.Queues)
    EXPECT_TRUE(queue.empty()) << "process " << rank << " sent a part";

  // Rank 0 failing after that, while making the assignments, sends its reason
  // in their place: a process stops on it without meshing or sending anything.
  testing::QueuedRun after;
  PartAssignment failed;
  failed.Failed = true;
  failed.Reason = "out of memory";
  after.Assignments[1] = PackPartAssignment(failed);
  testing::QueuedPartExchange one(1, 2, after);
  try
  {
    MeshAndDecimate(LabelImage(), mesher, {}, streaming, {}, &one, [](int, int) -> LabelImage {
      throw std::logic_error("a process read its slab after rank 0 had failed");
    });
    ADD_FAILURE() << "a process went on after rank 0's failed assignment";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_EQ(std::string(e.what()), "out of memory");
  }
  EXPECT_TRUE(after.Queues[1].empty() && after.Notices[1].empty());
}

TEST(StreamedPipeline, BorderPassesKeepTheAssembledBlocksSmall)
{
  // Without border passes every block's border zone waits for the last
  // pass; with them the assembled blocks are resolved as they grow, so the
  // most cells they hold at once is smaller, and every guarantee still holds.
  std::size_t with = 0, without = 0, passes = 0;
  for (std::uint64_t seed = 918000; seed < 918006; ++seed)
  {
    const auto random = testing::GenerateRandomLabelImageWithDescription(seed, 3);
    const MesherParameters mesher = testing::DrawDistanceBounds(seed);
    const DecimationParameters decimation = testing::DrawDecimationParameters(seed, 3, mesher);
    StreamingParameters streaming;
    streaming.BlockCells = 400;
    StreamingCounts on, off;
    auto problems = testing::ViolatedStreamedGuarantees(random.Image, mesher, decimation, streaming, nullptr, &on);
    EXPECT_TRUE(problems.empty()) << "seed " << seed << ": " << (problems.empty() ? "" : problems.front());
    streaming.BorderPasses = false;
    problems = testing::ViolatedStreamedGuarantees(random.Image, mesher, decimation, streaming, nullptr, &off);
    EXPECT_TRUE(problems.empty()) << "seed " << seed << ", no border passes: " << (problems.empty() ? "" : problems.front());
    EXPECT_EQ(off.BorderPasses, 0u);
    EXPECT_EQ(off.LargestAssembledCells, off.AssembledCells);
    EXPECT_GE(on.LargestAssembledCells, on.AssembledCells);
    passes += on.BorderPasses;
    with += on.LargestAssembledCells;
    without += off.LargestAssembledCells;
  }
  EXPECT_GT(passes, 6u);
  EXPECT_LT(with, without);
}

TEST(BlockPlan, ABoxLiesInARunOfLeavesExactlyWhenItsCornerKeysDo)
{
  // Every box of a random image's octree against every run of its leaves:
  // Holds says every voxel of the box is the run's, MayMeet is true whenever
  // one is (checked voxel by voxel).
  const auto random = testing::GenerateRandomLabelImageWithDescription(7, 3);
  std::vector<StageTiming> timings;
  StageClock clock(timings);
  const MesherOctree octree = RefineOctree(random.Image, MesherParameters{}, {}, clock);
  const auto& leaves = octree.Leaves;
  ASSERT_GT(leaves.size(), 20u);
  const int n = 1 << octree.Depth;
  std::vector<std::size_t> leafOf(static_cast<std::size_t>(n) * n * n);
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    const LeafBox& b = leaves[i].Box;
    for (int z = 0; z < b.Size; ++z)
      for (int y = 0; y < b.Size; ++y)
        for (int x = 0; x < b.Size; ++x)
          leafOf[(static_cast<std::size_t>(b.Origin[2] + z) * n + b.Origin[1] + y) * n + b.Origin[0] + x] = i;
  }
  testing::SeededRandom draw(99);
  for (int trial = 0; trial < 300; ++trial)
  {
    std::size_t first = static_cast<std::size_t>(draw.Int(0, static_cast<int>(leaves.size()) - 1));
    std::size_t last = static_cast<std::size_t>(draw.Int(static_cast<int>(first) + 1, static_cast<int>(leaves.size())));
    const KeyRange run = LeafRunKeys(leaves, first, last, 3, octree.Depth);
    std::array<double, 3> lo, hi;
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = draw.Int(0, n - 1) - 0.5;
      hi[a] = lo[a] + draw.Int(0, 3);
    }
    const VoxelBox box = GrownVoxelBox(lo, hi, 0.3 * draw.Int(0, 5), 3, octree.Depth);
    bool all = true, any = false;
    for (int z = box.Low[2]; z <= box.High[2]; ++z)
      for (int y = box.Low[1]; y <= box.High[1]; ++y)
        for (int x = box.Low[0]; x <= box.High[0]; ++x)
        {
          const std::size_t leaf = leafOf[(static_cast<std::size_t>(z) * n + y) * n + x];
          const bool inRun = leaf >= first && leaf < last;
          all = all && inRun;
          any = any || inRun;
        }
    EXPECT_EQ(run.Holds(box), all) << "trial " << trial;
    if (any)
      EXPECT_TRUE(run.MayMeet(box)) << "trial " << trial;
  }
}

} // namespace
} // namespace labelmesher
