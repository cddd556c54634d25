// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_benchmarks_BenchmarkSupport_h
#define labelmesher_benchmarks_BenchmarkSupport_h

/**
 * @file BenchmarkSupport.h
 * What every benchmark program here shares: where the shared data lives, how
 * a stage name becomes a counter name, and the process's resident memory
 * (Linux /proc), so that each case can report its own peak.
 */

#include <sys/resource.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "Mesh/SimplexMesh.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace labelmesher
{
namespace benchmarks
{

/// $LABELMESHER_DATA_DIR, else the shared data beside the source tree.
inline std::string DataDirectory()
{
  if (const char* env = std::getenv("LABELMESHER_DATA_DIR"))
    return env;
#ifdef LABELMESHER_SHARED_DATA_DIR
  return LABELMESHER_SHARED_DATA_DIR;
#else
  return "../shared/data";
#endif
}

/// "s_" + the stage name with blanks, slashes and commas as underscores.
inline std::string CounterName(const std::string& stage)
{
  std::string name = "s_";
  for (char c : stage)
    name += (c == ' ' || c == '/' || c == ',') ? '_' : c;
  return name;
}

/// Per-stage seconds summed over a benchmark's iterations, in first-seen order.
struct StageTotals
{
  std::vector<std::string> Order;
  std::map<std::string, double> Seconds;

  template <typename Timings>
  void Add(const Timings& timings)
  {
    for (const auto& timing : timings)
    {
      if (!Seconds.count(timing.Stage))
        Order.push_back(timing.Stage);
      Seconds[timing.Stage] += timing.Seconds;
    }
  }
};

/// A field of /proc/self/status in MiB (its values are in kB); -1 if unknown.
inline double StatusMiB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(status, line))
    if (line.rfind(key, 0) == 0)
      return std::atof(line.c_str() + key.size()) / 1024.0;
  return -1.0;
}
/// Peak resident set (VmHWM) since the last ResetPeakRss().
inline double PeakRssMiB() { return StatusMiB("VmHWM"); }
/// Current resident set (VmRSS).
inline double RssMiB() { return StatusMiB("VmRSS"); }
/// Linux >= 4.0: writing 5 to clear_refs resets VmHWM to the current RSS, so
/// each case reports its own peak (ru_maxrss cannot be reset).
inline void ResetPeakRss()
{
#if defined(__GLIBC__)
  // Hand memory freed by earlier cases back to the system first, so the new
  // baseline is close to what this case itself holds.
  malloc_trim(0);
#endif
  std::ofstream clear("/proc/self/clear_refs");
  if (clear)
    clear << "5";
}
/// getrusage's ru_maxrss: the process's lifetime peak, in MiB.
inline double MaxRssMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kB on Linux
}

/// Cells with a non-zero label: what one would simulate on.
inline std::size_t ForegroundCells(const SimplexMesh& mesh)
{
  return std::size_t(std::count_if(mesh.Materials.begin(), mesh.Materials.end(), [](std::int32_t m) { return m != 0; }));
}

} // namespace benchmarks
} // namespace labelmesher

#endif
