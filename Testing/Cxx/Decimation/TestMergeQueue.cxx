// SPDX-License-Identifier: GPL-2.0-or-later
// MergeQueue (Algorithm 4's queue): shortest incident edge first with ties to the smaller vertex
// id, or first in first out; a later push of a vertex supersedes the earlier one in either order;
// the stamps are shared, so a push in one region's queue retires the vertex's entry in another's.
#include "Decimation/MergeQueue.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace
{
using labelmesher::MergeOrder;
using labelmesher::MergeQueue;
using labelmesher::VertexId;

std::vector<VertexId> Drain(MergeQueue& queue)
{
  std::vector<VertexId> order;
  VertexId v;
  while (queue.Pop(v))
    order.push_back(v);
  return order;
}

TEST(MergeQueue, ShortestEdgeFirstTiesToTheSmallerId)
{
  std::vector<std::uint32_t> stamps(8, 0);
  MergeQueue queue(MergeOrder::ShortestEdgeFirst, stamps);
  queue.Push(5, 9);
  queue.Push(2, 4);
  queue.Push(7, 4);
  queue.Push(1, 16);
  queue.Push(3, 1);
  EXPECT_EQ(Drain(queue), (std::vector<VertexId>{ 3, 2, 7, 5, 1 }));
  VertexId v;
  EXPECT_FALSE(queue.Pop(v));
}

TEST(MergeQueue, FirstInFirstOutIgnoresEdges)
{
  std::vector<std::uint32_t> stamps(8, 0);
  MergeQueue queue(MergeOrder::Queue, stamps);
  queue.Push(5, 9);
  queue.Push(2, 4);
  queue.Push(7, 1);
  EXPECT_EQ(Drain(queue), (std::vector<VertexId>{ 5, 2, 7 }));
}

TEST(MergeQueue, ALaterPushSupersedesTheEarlierOne)
{
  for (MergeOrder order : { MergeOrder::ShortestEdgeFirst, MergeOrder::Queue })
  {
    std::vector<std::uint32_t> stamps(8, 0);
    MergeQueue queue(order, stamps);
    queue.Push(4, 1);  // superseded below: must not come out first
    queue.Push(6, 2);
    queue.Push(4, 3);
    const std::vector<VertexId> drained = Drain(queue);
    EXPECT_EQ(drained, (std::vector<VertexId>{ 6, 4 })) << static_cast<int>(order);
  }
}

TEST(MergeQueue, SharedStampsRetireAVertexQueuedInAnotherRegion)
{
  std::vector<std::uint32_t> stamps(8, 0);
  MergeQueue first(MergeOrder::ShortestEdgeFirst, stamps);
  MergeQueue second(MergeOrder::ShortestEdgeFirst, stamps);
  first.Push(3, 1);
  first.Push(5, 2);
  second.Push(3, 7); // vertex 3 now waits in the second queue only
  EXPECT_EQ(Drain(first), (std::vector<VertexId>{ 5 }));
  EXPECT_EQ(Drain(second), (std::vector<VertexId>{ 3 }));
}

} // namespace
