// SPDX-License-Identifier: GPL-2.0-or-later
// The order of Algorithm 4's merges: shortest incident edge first, or a plain queue.
#include "Decimation/MergeQueue.h"

namespace labelmesher
{

MergeQueue::MergeQueue(MergeOrder order, std::vector<std::uint32_t>& stamps)
  : Order(order)
  , Stamps(stamps)
{
}

void MergeQueue::Push(VertexId v, std::int64_t shortestEdge)
{
  const std::uint32_t stamp = ++Stamps[v];
  if (Order == MergeOrder::ShortestEdgeFirst)
    Heap.push(Entry{ shortestEdge, v, stamp });
  else
    Fifo.push_back(Entry{ Sequence++, v, stamp });
}

bool MergeQueue::Pop(VertexId& v)
{
  for (;;)
  {
    Entry e;
    if (Order == MergeOrder::ShortestEdgeFirst)
    {
      if (Heap.empty())
        return false;
      e = Heap.top();
      Heap.pop();
    }
    else
    {
      if (Fifo.empty())
        return false;
      e = Fifo.front();
      Fifo.pop_front();
    }
    if (Stamps[e.Vertex] == e.Stamp)
    {
      v = e.Vertex;
      return true;
    }
  }
}

} // namespace labelmesher
