// SPDX-License-Identifier: GPL-2.0-or-later
// What the machine lets this process still allocate, and the refusal line.
#include "MemoryBudget.h"

#include "MPIStartup.h"

#include "Support/MemoryEstimate.h"

#include <fstream>
#include <sstream>

#if defined(__linux__)
#include <sys/resource.h>
#endif

namespace labelmesher
{
namespace
{
constexpr std::uint64_t kMiB = 1024 * 1024;

/// The "Name:   value kB" field of a /proc file, in bytes; 0 when absent.
std::uint64_t ProcField(const char* path, const std::string& name)
{
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, name.size() + 1, name + ":") == 0)
    {
      std::istringstream fields(line.substr(name.size() + 1));
      std::uint64_t kB = 0;
      fields >> kB;
      return kB * 1024;
    }
  return 0;
}

/// A cgroup v2 file holding one number ("max" when unlimited); 0 when absent.
std::uint64_t CgroupValue(const char* path)
{
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max")
    return 0;
  try
  {
    return std::stoull(text);
  }
  catch (...)
  {
    return 0;
  }
}

void Lower(MemoryBudget& budget, std::uint64_t bytes, const std::string& source)
{
  if (bytes < budget.Bytes)
  {
    budget.Bytes = bytes;
    budget.Source = source;
  }
}
} // namespace

std::uint64_t ResidentBytes()
{
  return ProcField("/proc/self/status", "VmRSS");
}

std::uint64_t PeakResidentBytes()
{
  return ProcField("/proc/self/status", "VmHWM");
}

MemoryBudget AvailableMemory(double limitMiB, bool startsMPI)
{
  MemoryBudget budget;
  const std::uint64_t resident = ResidentBytes();
  // A user's limit replaces the machine's available memory (a soft figure:
  // caches, swap), not the hard limits below.
  if (limitMiB > 0)
  {
    const auto limit = static_cast<std::uint64_t>(limitMiB * kMiB);
    Lower(budget, limit > resident ? limit - resident : 0,
      "a memory limit of " + FormatMiB(limit) + ", " + FormatMiB(resident) + " of it in use");
  }
#if defined(__linux__)
  if (limitMiB <= 0)
    if (const std::uint64_t free = ProcField("/proc/meminfo", "MemAvailable"))
      Lower(budget, free, "the machine's available memory");
  const std::uint64_t cgroupMax = CgroupValue("/sys/fs/cgroup/memory.max");
  if (cgroupMax > 0)
  {
    const std::uint64_t used = CgroupValue("/sys/fs/cgroup/memory.current");
    Lower(budget, cgroupMax > used ? cgroupMax - used : 0, "the cgroup's memory.max");
  }
  rlimit address{};
  if (getrlimit(RLIMIT_AS, &address) == 0 && address.rlim_cur != RLIM_INFINITY)
  {
    // Address space, not resident memory: threads' stacks and malloc arenas
    // count too, so a run that passes may still stop, with one line, out of memory.
    // MPI's start, when this run brings it, takes its share first (MPIStartup.h).
    const std::uint64_t mpi = startsMPI ? MPIStartAddressSpace() : 0;
    const std::uint64_t size = ProcField("/proc/self/status", "VmSize") + mpi;
    const std::uint64_t limit = address.rlim_cur;
    Lower(budget, limit > size ? limit - size : 0,
      mpi == 0 ? "ulimit -v" : "ulimit -v, less " + FormatMiB(mpi) + " to start MPI");
  }
#endif
  return budget;
}

std::string FormatMiB(std::uint64_t bytes)
{
  return WithThousandsSeparators((bytes + kMiB / 2) / kMiB) + " MiB";
}

std::string RefuseIfTooLarge(std::uint64_t neededBytes, const std::string& basis, const MemoryBudget& budget)
{
  if (neededBytes <= budget.Bytes)
    return {};
  return "this run needs about " + FormatMiB(neededBytes) + " more memory (estimated from " + basis + ") but " +
    FormatMiB(budget.Bytes) + " are available (" + budget.Source + ")";
}

} // namespace labelmesher
