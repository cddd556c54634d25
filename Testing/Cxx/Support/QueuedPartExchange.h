// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_QueuedPartExchange_h
#define labelmesher_testing_QueuedPartExchange_h

/**
 * @file QueuedPartExchange.h
 * Ranks of the streamed pipeline run one after another in one process
 * (Streaming/PartExchange.h without MPI): each rank other than 0 runs first,
 * highest first, queuing its messages; then rank 0 takes them. Agree sees the
 * failures of the ranks that ran before. The others need rank 0's
 * assignments before it runs: the first to ask runs QueuedRun::AssignFirst,
 * which runs rank 0 on a run of its own until it has assigned every process
 * (AssignBeforehand); rank 0's assignments of the real run are kept in
 * Reassigned, to be compared. For the tests and the part balance benchmark.
 */

#include "Streaming/PartExchange.h"

#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

/// What the ranks of one run share: their queued messages and what each passed to Agree.
struct QueuedRun
{
  std::map<int, std::deque<std::vector<char>>> Queues;
  std::map<int, std::string> Failures;
  std::map<int, std::size_t> BytesSent;
  std::map<int, std::deque<std::string>> Notices;
  std::map<int, std::vector<char>> Assignments, Reassigned;
  std::function<void()> AssignFirst;
  bool StopOnceAssigned = false; ///< a run of AssignBeforehand's
};

/// Thrown by rank 0's last assignment in a run of AssignBeforehand's.
struct EveryProcessAssigned
{
};

class QueuedPartExchange final : public PartExchange
{
public:
  QueuedPartExchange(int rank, int ranks, QueuedRun& run)
    : RankOfThis(rank)
    , Size(ranks)
    , Run(run)
  {
  }
  int Rank() const override { return RankOfThis; }
  int Ranks() const override { return Size; }
  void Assign(int rank, std::vector<char> assignment) override
  {
    if (!Run.StopOnceAssigned)
    {
      Run.Reassigned[rank] = std::move(assignment);
      return;
    }
    Run.Assignments[rank] = std::move(assignment);
    if (rank == Size - 1)
      throw EveryProcessAssigned{};
  }
  std::vector<char> ReceiveAssignment() override
  {
    if (Run.Assignments.empty() && Run.AssignFirst)
      Run.AssignFirst();
    const auto it = Run.Assignments.find(RankOfThis);
    if (it == Run.Assignments.end())
      throw std::logic_error("rank " + std::to_string(RankOfThis) + " waits for an assignment rank 0 never sends");
    return it->second;
  }
  void Send(std::vector<char> message) override
  {
    Run.BytesSent[RankOfThis] += message.size();
    Run.Queues[RankOfThis].push_back(std::move(message));
  }
  std::vector<char> Receive(int rank) override
  {
    auto& queue = Run.Queues[rank];
    if (queue.empty())
      throw std::logic_error("rank 0 waits for a message rank " + std::to_string(rank) + " never sends");
    std::vector<char> message = std::move(queue.front());
    queue.pop_front();
    return message;
  }
  void Notify(const std::string& reason) override { Run.Notices[RankOfThis].push_back(reason); }
  int PollNotice(std::string& reason) override
  {
    for (auto& [rank, notices] : Run.Notices)
      if (!notices.empty())
      {
        reason = notices.front();
        notices.pop_front();
        return rank;
      }
    return -1;
  }
  void TakeNotice(int rank) override
  {
    auto& notices = Run.Notices[rank];
    if (notices.empty())
      throw std::logic_error("rank 0 waits for a notice rank " + std::to_string(rank) + " never sent");
    notices.pop_front();
  }
  std::string Agree(const std::string& failure) override
  {
    Run.Failures[RankOfThis] = failure;
    for (const auto& [rank, reason] : Run.Failures)
      if (!reason.empty())
        return ProcessFailure(rank, Size, reason);
    return {};
  }

private:
  int RankOfThis, Size;
  QueuedRun& Run;
};

/// Rank 0's assignments for `run`, made by `rankZero(exchange)` (rank 0's
/// MeshAndDecimate) on a run of its own that stops once every process is
/// assigned; a failure before that is rank 0's own, thrown.
template <typename RankZero>
void AssignBeforehand(QueuedRun& run, int ranks, RankZero&& rankZero)
{
  QueuedRun first;
  first.StopOnceAssigned = true;
  QueuedPartExchange exchange(0, ranks, first);
  try
  {
    rankZero(exchange);
  }
  catch (const EveryProcessAssigned&)
  {
  }
  run.Assignments = std::move(first.Assignments);
}

} // namespace testing
} // namespace labelmesher

#endif
