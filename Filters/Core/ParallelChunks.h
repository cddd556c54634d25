// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ParallelChunks_h
#define labelmesher_ParallelChunks_h

/**
 * @file ParallelChunks.h
 * The one loop the core runs on several cores: independent work items taken
 * in chunks by a few std::threads. Callers make results independent of the
 * thread count (each item writes its own slot, or per-thread partials are
 * merged in a fixed order), so output never depends on scheduling.
 */

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace labelmesher
{

/// Threads ParallelChunks uses by default: one per core, at most 8.
inline unsigned MaxThreads()
{
  return std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
}

/// Runs body(thread, begin, end) over chunks of [0, n) on up to `maxThreads`
/// threads; one thread when n fits in one chunk. The first exception a body
/// throws stops the remaining chunks and is rethrown here (an exception may
/// not leave a std::thread).
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
  for (unsigned t = 1; t < threads; ++t)
    pool.emplace_back(worker, t);
  worker(0);
  for (auto& th : pool)
    th.join();
  if (failure)
    std::rethrow_exception(failure);
}

} // namespace labelmesher

#endif
