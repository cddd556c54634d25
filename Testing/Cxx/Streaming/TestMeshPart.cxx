// SPDX-License-Identifier: GPL-2.0-or-later
//
// A part of the streamed pipeline as bytes (Streaming/MeshPart.h): every
// field comes back as sent, a failure with its reason, and bytes that are not
// a whole message are refused with an error instead of read past their end.

#include "Streaming/MeshPart.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace labelmesher
{
namespace
{

MeshPart SmallPart()
{
  MeshPart p;
  p.Mesh.Dimension = 3;
  p.Mesh.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1.5, 0 }, { 0, 0, 2 } };
  p.Mesh.Connectivity = { 0, 1, 2, 3 };
  p.Mesh.Materials = { 7 };
  p.Offered = { 1, 0, 1, 0 };
  p.Border = { 0, 1, 1, 0 };
  p.Counts.CellsBefore = 11;
  p.Counts.Merges = 5;
  p.Counts.FrozenVertices = 3;
  p.Blocks = 2;
  p.LargestBlockCells = 9;
  p.ForegroundCellsBefore = 8;
  p.BorderPasses = 1;
  p.LargestAssembledCells = 4;
  p.Timings = { { "fill", 0.25 }, { "decimation: merges", 1.5 } };
  return p;
}

TEST(MeshPart, ComesBackAsSent)
{
  PartMessage sent;
  sent.Part = SmallPart();
  const PartMessage got = UnpackPartMessage(PackPartMessage(sent));
  const MeshPart &a = sent.Part, &b = got.Part;
  EXPECT_FALSE(got.Failed);
  EXPECT_EQ(b.Mesh.Dimension, 3);
  EXPECT_EQ(b.Mesh.Points, a.Mesh.Points);
  EXPECT_EQ(b.Mesh.Connectivity, a.Mesh.Connectivity);
  EXPECT_EQ(b.Mesh.Materials, a.Mesh.Materials);
  EXPECT_EQ(b.Offered, a.Offered);
  EXPECT_EQ(b.Border, a.Border);
  EXPECT_EQ(b.Counts.CellsBefore, 11u);
  EXPECT_EQ(b.Counts.Merges, 5u);
  EXPECT_EQ(b.Counts.FrozenVertices, 3u);
  EXPECT_EQ(b.Blocks, 2u);
  EXPECT_EQ(b.LargestBlockCells, 9u);
  EXPECT_EQ(b.ForegroundCellsBefore, 8u);
  EXPECT_EQ(b.BorderPasses, 1u);
  EXPECT_EQ(b.LargestAssembledCells, 4u);
  ASSERT_EQ(b.Timings.size(), 2u);
  EXPECT_EQ(b.Timings[1].Stage, "decimation: merges");
  EXPECT_EQ(b.Timings[1].Seconds, 1.5);
}

TEST(MeshPart, AFailureCarriesItsReason)
{
  PartMessage failure;
  failure.Failed = true;
  failure.Reason = "out of memory";
  const PartMessage got = UnpackPartMessage(PackPartMessage(failure));
  EXPECT_TRUE(got.Failed);
  EXPECT_EQ(got.Reason, "out of memory");
}

TEST(MeshPart, BrokenMessagesAreRefused)
{
  PartMessage sent;
  sent.Part = SmallPart();
  const std::vector<char> bytes = PackPartMessage(sent);
  for (std::size_t cut : { std::size_t(0), std::size_t(3), std::size_t(9), bytes.size() / 2, bytes.size() - 1 })
    EXPECT_THROW(UnpackPartMessage(std::vector<char>(bytes.begin(), bytes.begin() + cut)), std::runtime_error)
      << "cut at " << cut;
  std::vector<char> longer = bytes;
  longer.push_back(0);
  EXPECT_THROW(UnpackPartMessage(longer), std::runtime_error);
  // A cell naming a vertex the part does not hold.
  sent.Part.Mesh.Connectivity[2] = 4;
  EXPECT_THROW(UnpackPartMessage(PackPartMessage(sent)), std::runtime_error);
  sent.Part.Mesh.Connectivity[2] = 2;
  sent.Part.Offered.pop_back();
  EXPECT_THROW(UnpackPartMessage(PackPartMessage(sent)), std::runtime_error);
}

TEST(MeshPart, AnAssignmentComesBackAsSentAndBrokenOnesAreRefused)
{
  PartAssignment sent;
  sent.ImageDimensions = { 40, 30, 90 };
  sent.Depth = 7;
  for (int i = 0; i < 5; ++i)
  {
    OctreeLeaf leaf;
    leaf.Box.Origin = { 8 * i, 0, 16 };
    leaf.Box.Size = 8;
    leaf.First = 1;
    leaf.Second = i % 2 == 0 ? 1 : 3;
    leaf.EdgeMidpoints = static_cast<std::uint16_t>(i);
    sent.Leaves.push_back(leaf);
  }
  sent.Starts = { 0, 2, 5 };
  sent.EndKey = 123456;
  sent.LeavesBefore = 40;
  sent.OctreeLeaves = 100;
  sent.SlabFirst = 4;
  sent.SlabEnd = 38;
  sent.SlabHash = 0x0123456789abcdefull;
  const std::vector<char> bytes = PackPartAssignment(sent);
  // Leaf by leaf, field by field: 31 bytes each, none of the struct's padding
  // (whatever the memory held there; the same assignment must give the same bytes).
  PartAssignment empty = sent;
  empty.Leaves.clear();
  empty.Starts = { 0 };
  EXPECT_EQ(bytes.size() - PackPartAssignment(empty).size(), 5 * 31u + 2 * sizeof(std::uint64_t));
  const PartAssignment got = UnpackPartAssignment(bytes);
  EXPECT_FALSE(got.Failed);
  EXPECT_EQ(got.ImageDimensions, sent.ImageDimensions);
  EXPECT_EQ(got.Depth, 7);
  ASSERT_EQ(got.Leaves.size(), 5u);
  EXPECT_EQ(got.Leaves[3].Box.Origin, sent.Leaves[3].Box.Origin);
  EXPECT_EQ(got.Leaves[3].Second, 3);
  EXPECT_EQ(got.Leaves[4].EdgeMidpoints, 4);
  EXPECT_EQ(got.Starts, sent.Starts);
  EXPECT_EQ(got.EndKey, 123456u);
  EXPECT_EQ(got.LeavesBefore, 40u);
  EXPECT_EQ(got.OctreeLeaves, 100u);
  EXPECT_EQ(got.SlabFirst, 4);
  EXPECT_EQ(got.SlabEnd, 38);
  EXPECT_EQ(got.SlabHash, 0x0123456789abcdefull);
  for (std::size_t cut : { std::size_t(0), std::size_t(5), bytes.size() / 2, bytes.size() - 1 })
  {
    try
    {
      UnpackPartAssignment(std::vector<char>(bytes.begin(), bytes.begin() + cut));
      ADD_FAILURE() << "cut at " << cut << " accepted";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("assignment"), std::string::npos) << "cut at " << cut << ": " << e.what();
    }
  }
  EXPECT_THROW(UnpackPartMessage(bytes), std::runtime_error); // not a part
  sent.Starts = { 0, 4, 3, 5 };                                // not a run of parts
  EXPECT_THROW(UnpackPartAssignment(PackPartAssignment(sent)), std::runtime_error);

  PartAssignment failed;
  failed.Failed = true;
  failed.Reason = "out of memory";
  const PartAssignment back = UnpackPartAssignment(PackPartAssignment(failed));
  EXPECT_TRUE(back.Failed);
  EXPECT_EQ(back.Reason, "out of memory");
}

} // namespace
} // namespace labelmesher
