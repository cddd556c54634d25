// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MemoryBudget_h
#define labelmesher_MemoryBudget_h

/**
 * @file MemoryBudget.h
 * How much more memory this process may take, and the one-line refusal when a
 * run's estimate (Support/MemoryEstimate.h) does not fit. Linux: MemAvailable
 * of /proc/meminfo, the cgroup's memory.max, and ulimit -v (RLIMIT_AS against
 * the process's present virtual size); elsewhere only a user's limit counts.
 */

#include "LabelMesherFiltersModule.h" // For export macro

#include <cstdint>
#include <string>

namespace labelmesher
{

struct MemoryBudget
{
  std::uint64_t Bytes = UINT64_MAX; ///< what the process may still allocate
  std::string Source;               ///< which limit decided it, for the message
};

/// Resident memory of this process now, and its peak so far (bytes; 0 when unknown).
LABELMESHERFILTERS_EXPORT std::uint64_t ResidentBytes();
LABELMESHERFILTERS_EXPORT std::uint64_t PeakResidentBytes();

/// What a run may still allocate. `limitMiB` > 0: the whole process may hold
/// at most that many MiB, in place of the machine's available memory (so a
/// user may also raise it, e.g. counting on swap); 0: the available memory.
/// The cgroup's memory.max and ulimit -v bound both. `startsMPI`: the run will start MPI if it
/// is not running yet (the mesher's), which under ulimit -v first takes its own address space
/// (MPIStartup.h MPIStartAddressSpace).
LABELMESHERFILTERS_EXPORT MemoryBudget AvailableMemory(double limitMiB, bool startsMPI = false);

/// Empty when `neededBytes` more fit `budget`; otherwise one sentence naming
/// both figures, e.g. "this run needs about 1,370 MiB more (estimated from
/// ...) but 400 MiB are available (ulimit -v)".
LABELMESHERFILTERS_EXPORT std::string RefuseIfTooLarge(std::uint64_t neededBytes, const std::string& basis, const MemoryBudget& budget);

/// `bytes` in MiB with thousands separators: "1,370 MiB".
LABELMESHERFILTERS_EXPORT std::string FormatMiB(std::uint64_t bytes);

} // namespace labelmesher

#endif
