// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MergeQueue_h
#define labelmesher_MergeQueue_h

/**
 * @file MergeQueue.h
 * The queue of Algorithm 4: vertices waiting to be offered for a merge. A
 * vertex is pushed at the start and again whenever a merge changes its
 * neighbourhood; a later push supersedes an earlier one (stale entries are
 * skipped when popped). Two orders: shortest incident edge first, which merges
 * the finest parts first and gives the fewest cells, or first in first out,
 * the dissertation's plain queue. Ties go to the smaller vertex id, so the
 * order is reproducible.
 */

#include "Decimation/DecimationParameters.h"
#include "Decimation/EditableMesh.h"

#include <cstdint>
#include <deque>
#include <queue>
#include <vector>

namespace labelmesher
{

class MergeQueue
{
public:
  /// `stamps`: one counter per vertex, shared by the queues of disjoint regions.
  MergeQueue(MergeOrder order, std::vector<std::uint32_t>& stamps);

  /// (Re)queues v; `shortestEdge` is its shortest incident edge, squared (doubled lattice).
  void Push(VertexId v, std::int64_t shortestEdge);
  /// The next vertex, or false when none is left.
  bool Pop(VertexId& v);

private:
  struct Entry
  {
    std::int64_t Key;
    VertexId Vertex;
    std::uint32_t Stamp;
    bool operator>(const Entry& o) const { return Key != o.Key ? Key > o.Key : Vertex > o.Vertex; }
  };
  MergeOrder Order;
  std::vector<std::uint32_t>& Stamps;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> Heap;
  std::deque<Entry> Fifo;
  std::int64_t Sequence = 0;
};

} // namespace labelmesher

#endif
