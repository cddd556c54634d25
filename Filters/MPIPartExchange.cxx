// SPDX-License-Identifier: GPL-2.0-or-later
// Parts and output pieces as byte messages over a duplicate of MPI_COMM_WORLD: a length, then
// chunks (MPI counts are ints); an output piece waits for its process's room between the two.
#include "MPIPartExchange.h"

#include "MPIStartup.h"
#include "Streaming/PartExchange.h"

#include <sc.h> // includes mpi.h when libsc was built with MPI (SC_ENABLE_MPI)

#include <algorithm>
#include <cstdlib>
#include <cstdint>
#include <deque>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace labelmesher
{

#ifdef SC_ENABLE_MPI
namespace
{

constexpr int kPartTag = 7311;
constexpr int kNoticeTag = 7312;
constexpr int kAssignmentTag = 7313;
constexpr int kOutputPieceTag = 7314;
/// A part or an assignment travels in messages of at most this many bytes (MPI counts are ints).
constexpr std::size_t kPiece = std::size_t(1) << 30;
/// An output piece travels in messages of at most this many bytes: any size below 2 GiB would do;
/// this one lets MPI.PieceExchange cross a message's end with a piece of a size a test affords.
constexpr std::size_t kOutputChunk = std::size_t(64) << 20;

/// Calls `chunk(at, n)` for the consecutive runs of at most `most` of `size` bytes.
template <class Chunk>
void ForEachChunk(std::size_t size, std::size_t most, Chunk&& chunk)
{
  for (std::size_t at = 0; at < size; at += most)
    chunk(at, static_cast<int>(std::min(most, size - at)));
}

void Check(int status, const char* what)
{
  if (status != MPI_SUCCESS)
    throw std::runtime_error(std::string("MPI could not ") + what);
}

/// The world's processes on a communicator of our own, so that no other
/// traffic on the world's (ParaView's, say) can meet ours, whatever its tags.
/// Made once, by the first collective call of this file, which every process
/// makes at the same point; MPI frees it at its finalize.
MPI_Comm Parts()
{
  static MPI_Comm communicator = [] {
    MPI_Comm dup = MPI_COMM_NULL;
    Check(MPI_Comm_dup(MPI_COMM_WORLD, &dup), "make a communicator for the parts");
    return dup;
  }();
  return communicator;
}

/// `root`'s `value` on every rank (collective): its length, then its bytes.
std::string BroadcastString(const std::string& value, int root, const char* what)
{
  std::uint64_t length = value.size();
  Check(MPI_Bcast(&length, 1, MPI_UINT64_T, root, Parts()), what);
  std::vector<char> bytes(value.begin(), value.end());
  bytes.resize(static_cast<std::size_t>(length));
  Check(MPI_Bcast(bytes.data(), static_cast<int>(length), MPI_CHAR, root, Parts()), what);
  return std::string(bytes.begin(), bytes.end());
}

/// MPI started and not finalized: the only time it may be called.
bool MPIUsable()
{
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  if (!initialized)
    return false;
  MPI_Finalized(&finalized);
  return !finalized;
}

/// The lowest failing rank's reason, the same on every rank (collective).
std::string FirstFailureOf(const std::string& failure, int size)
{
  int failed = failure.empty() ? 0 : 1;
  std::vector<int> all(static_cast<std::size_t>(size));
  Check(MPI_Allgather(&failed, 1, MPI_INT, all.data(), 1, MPI_INT, Parts()), "gather the processes' state");
  const auto first = std::find(all.begin(), all.end(), 1);
  if (first == all.end())
    return {};
  const int root = static_cast<int>(first - all.begin());
  return ProcessFailure(root, size, BroadcastString(failure, root, "share a failure"));
}

class MPIPartExchange final : public PartExchange
{
public:
  MPIPartExchange(int rank, int size)
    : RankOfThis(rank)
    , Size(size)
  {
    Parts(); // collective the first time: made here, where every process constructs one
  }
  ~MPIPartExchange() override
  {
    try
    {
      Flush();
    }
    catch (...)
    {
    }
  }
  int Rank() const override { return RankOfThis; }
  int Ranks() const override { return Size; }

  /// Sent without waiting: the message is kept until Flush sees rank 0 has it.
  void Send(std::vector<char> message) override { Post(0, kPartTag, std::move(message), "send a part"); }

  /// Sent without waiting, as a part is: kept until Flush.
  void Assign(int rank, std::vector<char> assignment) override
  {
    Post(rank, kAssignmentTag, std::move(assignment), "send a process its parts");
  }

  std::vector<char> ReceiveAssignment() override { return Take(0, kAssignmentTag, "receive this process's parts"); }

  void Notify(const std::string& reason) override
  {
    Outgoing& out = Pending.emplace_back();
    out.Bytes.assign(reason.begin(), reason.end());
    out.Requests.emplace_back();
    Check(MPI_Isend(out.Bytes.data(), static_cast<int>(out.Bytes.size()), MPI_CHAR, 0, kNoticeTag, Parts(),
            &out.Requests.back()),
      "send a failure");
  }

  int PollNotice(std::string& reason) override
  {
    int arrived = 0;
    MPI_Status status;
    Check(MPI_Iprobe(MPI_ANY_SOURCE, kNoticeTag, Parts(), &arrived, &status), "look for failures");
    if (!arrived)
      return -1;
    reason = ReceiveNotice(status.MPI_SOURCE);
    return status.MPI_SOURCE;
  }

  void TakeNotice(int rank) override { ReceiveNotice(rank); }

  void Flush() override
  {
    for (Outgoing& out : Pending)
      Check(MPI_Waitall(static_cast<int>(out.Requests.size()), out.Requests.data(), MPI_STATUSES_IGNORE),
        "finish sending a part");
    Pending.clear();
  }

  std::vector<char> Receive(int rank) override { return Take(rank, kPartTag, "receive a part"); }

  std::string Agree(const std::string& failure) override { return FirstFailureOf(failure, Size); }

private:
  /// A message to `to` without waiting: its length, then pieces of at most kPiece bytes.
  void Post(int to, int tag, std::vector<char> message, const char* what)
  {
    Outgoing& out = Pending.emplace_back();
    out.Length = static_cast<std::uint64_t>(message.size());
    out.Bytes = std::move(message);
    out.Requests.emplace_back();
    Check(MPI_Isend(&out.Length, 1, MPI_UINT64_T, to, tag, Parts(), &out.Requests.back()), what);
    ForEachChunk(out.Bytes.size(), kPiece, [&](std::size_t at, int n) {
      out.Requests.emplace_back();
      Check(MPI_Isend(out.Bytes.data() + at, n, MPI_BYTE, to, tag, Parts(), &out.Requests.back()), what);
    });
  }

  /// The next message from `from` with `tag`, as Post sent it.
  std::vector<char> Take(int from, int tag, const char* what)
  {
    std::uint64_t length = 0;
    Check(MPI_Recv(&length, 1, MPI_UINT64_T, from, tag, Parts(), MPI_STATUS_IGNORE), what);
    std::vector<char> message(static_cast<std::size_t>(length));
    ForEachChunk(message.size(), kPiece, [&](std::size_t at, int n) {
      Check(MPI_Recv(message.data() + at, n, MPI_BYTE, from, tag, Parts(), MPI_STATUS_IGNORE), what);
    });
    return message;
  }

  std::string ReceiveNotice(int rank)
  {
    MPI_Status status;
    Check(MPI_Probe(rank, kNoticeTag, Parts(), &status), "receive a failure");
    int length = 0;
    Check(MPI_Get_count(&status, MPI_CHAR, &length), "receive a failure");
    std::string reason(static_cast<std::size_t>(std::max(length, 0)), '\0');
    Check(MPI_Recv(reason.data(), length, MPI_CHAR, rank, kNoticeTag, Parts(), MPI_STATUS_IGNORE),
      "receive a failure");
    return reason;
  }

  struct Outgoing
  {
    std::uint64_t Length = 0;
    std::vector<char> Bytes;
    std::vector<MPI_Request> Requests;
  };
  int RankOfThis, Size;
  std::deque<Outgoing> Pending; // a deque: the buffers MPI reads from stay in place as it grows
};

} // namespace
#endif

int WorldRank()
{
  int rank = 0;
#ifdef SC_ENABLE_MPI
  if (MPIUsable())
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
#endif
  return rank;
}

int WorldSize()
{
  int size = 1;
#ifdef SC_ENABLE_MPI
  if (MPIUsable())
    MPI_Comm_size(MPI_COMM_WORLD, &size);
#endif
  return size;
}

namespace
{
/// The first of the launchers' variables `names` that is set, as a number (-1: none set).
int LauncherVariable(std::initializer_list<const char*> names)
{
  for (const char* name : names)
    if (const char* value = std::getenv(name))
      return std::atoi(value);
  return -1;
}
} // namespace

// Open MPI's variables and MPICH's (Hydra; also Intel MPI's and srun --mpi=pmi2's). PMIx sets no
// size variable every launcher shares, so its rank is not read either: size and rank come in pairs.
int LaunchedRank()
{
  return std::max(0, LauncherVariable({ "OMPI_COMM_WORLD_RANK", "PMI_RANK" }));
}

int LaunchedProcesses()
{
  return std::max(1, LauncherVariable({ "OMPI_COMM_WORLD_SIZE", "PMI_SIZE" }));
}

bool LaunchedOnSeveralProcesses()
{
  return LaunchedProcesses() > 1;
}

std::string FirstFailure(const std::string& failure)
{
#ifdef SC_ENABLE_MPI
  if (WorldSize() > 1)
    return FirstFailureOf(failure, WorldSize());
#endif
  return failure;
}

bool SameAsRankZero(const std::string& value)
{
#ifdef SC_ENABLE_MPI
  if (WorldSize() > 1)
    return BroadcastString(value, 0, "share the run's parameters") == value;
#endif
  (void)value;
  return true;
}

bool SendPieceTo(int rank, const std::string* bytes)
{
#ifdef SC_ENABLE_MPI
  // Its length (-1: none); the process answers whether it made room; then the bytes, in chunks.
  const char* what = "send a process its piece of the output";
  const std::int64_t length = bytes ? static_cast<std::int64_t>(bytes->size()) : -1;
  Check(MPI_Send(&length, 1, MPI_INT64_T, rank, kOutputPieceTag, Parts()), what);
  if (!bytes)
    return false;
  int room = 0;
  Check(MPI_Recv(&room, 1, MPI_INT, rank, kOutputPieceTag, Parts(), MPI_STATUS_IGNORE), what);
  if (room)
    ForEachChunk(bytes->size(), kOutputChunk, [&](std::size_t at, int n) {
      Check(MPI_Send(bytes->data() + at, n, MPI_BYTE, rank, kOutputPieceTag, Parts()), what);
    });
  return room != 0;
#else
  (void)rank;
  (void)bytes;
  return false;
#endif
}

bool ReceivePieceFromRankZero(std::string& bytes, std::string& problem)
{
  problem.clear();
  bytes.clear();
#ifdef SC_ENABLE_MPI
  const char* what = "receive this process's piece of the output";
  std::int64_t length = -1;
  Check(MPI_Recv(&length, 1, MPI_INT64_T, 0, kOutputPieceTag, Parts(), MPI_STATUS_IGNORE), what);
  if (length < 0)
    return false;
  int room = 1;
  try
  {
    bytes.assign(static_cast<std::size_t>(length), '\0');
  }
  catch (const std::exception&) // std::bad_alloc, or std::length_error beyond what a string holds
  {
    bytes.clear();
    bytes.shrink_to_fit();
    room = 0;
    problem = "it had no memory for its piece of the output (" + std::to_string(length) + " bytes)";
  }
  Check(MPI_Send(&room, 1, MPI_INT, 0, kOutputPieceTag, Parts()), what);
  if (room)
    ForEachChunk(bytes.size(), kOutputChunk, [&](std::size_t at, int n) {
      Check(MPI_Recv(bytes.data() + at, n, MPI_BYTE, 0, kOutputPieceTag, Parts(), MPI_STATUS_IGNORE), what);
    });
  return room != 0;
#else
  (void)bytes;
  return false;
#endif
}

std::unique_ptr<PartExchange> WorldPartExchange()
{
#ifdef SC_ENABLE_MPI
  if (WorldSize() > 1)
    return std::make_unique<MPIPartExchange>(WorldRank(), WorldSize());
#endif
  return nullptr;
}

} // namespace labelmesher
