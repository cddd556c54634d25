// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_StageClock_h
#define labelmesher_StageClock_h

/**
 * @file StageClock.h
 * Wall time per stage of a core run (label pyramid, octree, fill, ...), which
 * the adapters put in the field data and the CLI prints: users see where the
 * time goes without a profiler.
 */

#include <chrono>
#include <string>
#include <vector>

namespace labelmesher
{

struct StageTiming
{
  std::string Stage;
  double Seconds = 0.0;
};

/// Appends one timing per Finish call: the time since the previous one (or
/// since construction).
class StageClock
{
public:
  explicit StageClock(std::vector<StageTiming>& timings)
    : Timings(timings)
  {
  }
  void Finish(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    Timings.push_back({ stage, std::chrono::duration<double>(now - Start).count() });
    Start = now;
  }
  /// The next stage starts now: the time since the last Finish was counted elsewhere.
  void Restart() { Start = std::chrono::steady_clock::now(); }

private:
  std::vector<StageTiming>& Timings;
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};

} // namespace labelmesher

#endif
