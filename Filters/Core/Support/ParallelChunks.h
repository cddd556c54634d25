// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ParallelChunks_h
#define labelmesher_ParallelChunks_h

/**
 * @file ParallelChunks.h
 * What the core runs on several cores: a loop over independent work items
 * taken in chunks by a few std::threads, and a sort. Callers make results independent of the
 * thread count (each item writes its own slot, or per-thread partials are
 * merged in a fixed order), so output never depends on scheduling or on the
 * thread limit (TestDeterminism.cxx checks it byte for byte).
 */

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace labelmesher
{

namespace detail
{
inline std::atomic<unsigned>& ThreadLimit()
{
  static std::atomic<unsigned> limit{ 0 }; // 0: not set
  return limit;
}
inline unsigned DefaultThreads()
{
  // LABELMESHER_THREADS caps the default, for users on shared machines.
  static const unsigned threads = [] {
    unsigned n = std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
    if (const char* text = std::getenv("LABELMESHER_THREADS"))
    {
      char* end = nullptr;
      const long value = std::strtol(text, &end, 10);
      if (end != text && *end == '\0' && value >= 1)
        n = static_cast<unsigned>(std::min(value, 64L));
    }
    return n;
  }();
  return threads;
}
} // namespace detail

/// The most threads any parallel loop of the core uses: the limit set by
/// SetThreadLimit, else the environment variable LABELMESHER_THREADS (>= 1),
/// else one per core, at most 8. Results never depend on it.
inline unsigned MaxThreads()
{
  const unsigned limit = detail::ThreadLimit().load(std::memory_order_relaxed);
  return limit > 0 ? limit : detail::DefaultThreads();
}

/// Sets the process-wide thread limit (1 to 64; more than the machine's cores
/// is allowed, which the determinism test uses); 0 restores the default.
/// Like vtkSMPTools::Initialize, it is global: set it before work starts.
inline void SetThreadLimit(unsigned threads)
{
  detail::ThreadLimit().store(std::min(threads, 64u), std::memory_order_relaxed);
}

/// Runs body(thread, begin, end) over chunks of [0, n) on up to `maxThreads`
/// threads; one thread when n fits in one chunk. The first exception a body
/// throws stops the remaining chunks and is rethrown here (an exception may
/// not leave a std::thread). Threads that cannot be started leave their share
/// to the others.
template <class Body>
void ParallelChunks(std::size_t n, std::size_t chunk, Body&& body, unsigned maxThreads = MaxThreads())
{
  unsigned threads = std::max(1u, std::min(maxThreads, MaxThreads()));
  if (n <= chunk)
    threads = 1;
  std::atomic<std::size_t> next{ 0 };
  std::atomic<bool> failed{ false };
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto worker = [&](unsigned t) {
    try
    {
      while (!failed.load(std::memory_order_relaxed))
      {
        const std::size_t b = next.fetch_add(chunk);
        if (b >= n)
          return;
        body(t, b, std::min(n, b + chunk));
      }
    }
    catch (...)
    {
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure)
        failure = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (unsigned t = 1; t < threads; ++t)
  {
    try
    {
      pool.emplace_back(worker, t);
    }
    catch (const std::system_error&)
    {
      // No room for another thread's stack (ulimit -v, a cgroup): the threads
      // already started take every chunk; results do not depend on their number.
      break;
    }
  }
  worker(0);
  for (auto& th : pool)
    th.join();
  if (failure)
    std::rethrow_exception(failure);
}

/// std::sort on up to MaxThreads() threads: contiguous parts sorted at once,
/// then merged pairwise. With a strict weak order that ties no two distinct
/// items, the result is the same as std::sort's.
template <class T, class Less>
void ParallelSort(std::vector<T>& items, Less less)
{
  std::size_t parts = 1;
  while (parts * 2 <= MaxThreads() && items.size() / (parts * 2) >= 65536)
    parts *= 2;
  std::vector<std::size_t> bounds(parts + 1);
  for (std::size_t p = 0; p <= parts; ++p)
    bounds[p] = items.size() * p / parts;
  ParallelChunks(parts, 1, [&](unsigned, std::size_t b, std::size_t) {
    std::sort(items.begin() + bounds[b], items.begin() + bounds[b + 1], less);
  });
  for (std::size_t width = 1; width < parts; width *= 2)
    ParallelChunks(parts / (2 * width), 1, [&](unsigned, std::size_t b, std::size_t) {
      const std::size_t first = bounds[2 * width * b], middle = bounds[2 * width * b + width],
                        last = bounds[2 * width * (b + 1)];
      std::inplace_merge(items.begin() + first, items.begin() + middle, items.begin() + last, less);
    });
}

} // namespace labelmesher

#endif
