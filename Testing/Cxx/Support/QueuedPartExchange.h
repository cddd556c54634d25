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
 * Reassigned, to be compared. MeshOnQueuedRanks runs a whole such run. For the
 * tests, the property scan and the part balance benchmark.
 */

#include "Streaming/PartExchange.h"
#include "Streaming/StreamedPipeline.h"

#include <array>
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

/// The streamed pipeline on `ranks` processes run one after another (rank 0
/// last), every one but rank 0 from its slab of `image` only (the slabs taken
/// go to `slabs`, if given). Rank `failing` (if any, not 0) is stopped by its
/// progress observer at its first report of stage `stopAt`; rank 0 reports to
/// `rootObserver`. Returns rank 0's result and throws what rank 0 throws; in
/// either case `problems` gets what went wrong between the processes: a rank
/// that did not fail as asked or returned a mesh, a message or notice rank 0
/// left, an assignment rank 0 made that differs from the one used. With a
/// `failingImage`, rank `failing` takes its slab from that image instead (a
/// process given another file) and is expected to fail for it.
inline StreamedResult MeshOnQueuedRanks(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming, int ranks,
  std::vector<std::string>& problems, std::vector<std::array<int, 2>>* slabs = nullptr, int failing = -1,
  const std::string& stopAt = "", const ProgressObserver& rootObserver = {},
  const LabelImage* failingImage = nullptr)
{
  QueuedRun run;
  run.AssignFirst = [&] {
    AssignBeforehand(run, ranks, [&](QueuedPartExchange& zero) {
      MeshAndDecimate(image, mesher, decimation, streaming, {}, &zero);
    });
  };
  const ProgressObserver stop{ [&](const std::string& stage, double) { return stage != stopAt; } };
  const LabelImage none; // the processes other than rank 0 read only their slab
  for (int rank = ranks - 1; rank > 0; --rank)
  {
    const LabelImage& source = rank == failing && failingImage ? *failingImage : image;
    const SlabSource slabOf = [&](int first, int end) {
      if (slabs != nullptr)
        slabs->push_back({ first, end });
      return LabelImage::Slab(source, first, end);
    };
    QueuedPartExchange exchange(rank, ranks, run);
    try
    {
      const StreamedResult other =
        MeshAndDecimate(none, mesher, decimation, streaming, rank == failing ? stop : ProgressObserver{}, &exchange, slabOf);
      if (rank == failing)
        problems.push_back("process " + std::to_string(rank) + " did not stop at " + stopAt);
      if (other.HoldsMesh || !other.Decimated.Mesh.Points.empty())
        problems.push_back("process " + std::to_string(rank) + " returned a mesh");
    }
    catch (const std::exception& e)
    {
      if (rank != failing)
        problems.push_back("process " + std::to_string(rank) + " failed: " + e.what());
    }
    catch (...)
    {
      if (rank != failing)
        problems.push_back("process " + std::to_string(rank) + " failed");
    }
  }
  QueuedPartExchange root(0, ranks, run);
  const auto check = [&] {
    for (const auto& [rank, queue] : run.Queues)
      if (!queue.empty())
        problems.push_back("rank 0 left a message of process " + std::to_string(rank));
    for (const auto& [rank, notices] : run.Notices)
      if (!notices.empty())
        problems.push_back("rank 0 left a failure notice of process " + std::to_string(rank));
    if (!run.Reassigned.empty() && run.Reassigned != run.Assignments)
      problems.push_back("rank 0 assigned other parts than those the processes meshed");
  };
  try
  {
    StreamedResult result = MeshAndDecimate(image, mesher, decimation, streaming, rootObserver, &root);
    check();
    return result;
  }
  catch (...)
  {
    check();
    throw;
  }
}

} // namespace testing
} // namespace labelmesher

#endif
