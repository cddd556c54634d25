// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_benchmarks_BenchmarkSupport_h
#define labelmesher_benchmarks_BenchmarkSupport_h

/**
 * @file BenchmarkSupport.h
 * What every benchmark program here shares: where the shared data lives and
 * how a stage name becomes a counter name.
 */

#include <cstdlib>
#include <string>

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

} // namespace benchmarks
} // namespace labelmesher

#endif
