// SPDX-License-Identifier: GPL-2.0-or-later
// Starts MPI as a singleton for a plain process, once, and finalizes it at exit.
#include "MPIStartup.h"

#include <sc.h> // includes mpi.h when libsc was built with MPI (SC_ENABLE_MPI)

#include <cstdlib>
#include <mutex>

namespace labelmesher
{

void StartMPI()
{
  static std::once_flag once;
  std::call_once(once, [] {
#ifdef SC_ENABLE_MPI
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (initialized)
      return;
    // Open MPI prints a line for every optional transport it cannot load (e.g. under ulimit -v)
    // and then carries on without it: noise around our one-line errors. The user's own setting,
    // if any, stands.
    setenv("OMPI_MCA_mca_base_component_show_load_errors", "0", 0);
    MPI_Init(nullptr, nullptr);
    std::atexit([] {
      int finalized = 0;
      MPI_Finalized(&finalized);
      if (!finalized)
        MPI_Finalize();
    });
#endif
  });
}

bool MPIRunning()
{
#ifdef SC_ENABLE_MPI
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  if (initialized)
    MPI_Finalized(&finalized);
  return initialized != 0 && finalized == 0;
#else
  return true;
#endif
}

std::uint64_t MPIStartAddressSpace()
{
  return MPIRunning() ? 0 : std::uint64_t(48) << 20;
}

} // namespace labelmesher
