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

} // namespace
} // namespace labelmesher
