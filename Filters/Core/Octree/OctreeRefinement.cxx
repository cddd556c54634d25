// SPDX-License-Identifier: GPL-2.0-or-later
// Refines and balances the p4est forest until every leaf passes the refinement criteria (Algorithm 2).
#include "Octree/OctreeRefinement.h"

#include <p4est_base.h>
#include <sc.h> // includes mpi.h when libsc was built with MPI (SC_ENABLE_MPI)

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>

namespace labelmesher
{
namespace detail
{
namespace
{
// libsc ends a failed allocation (or any failed check) by logging a message,
// calling the abort handler and then abort() or MPI_Abort, which prints Open
// MPI's eleven-line banner. Instead, its message is kept here and the handler
// throws, so that the failure reaches the user as one line like any other
// error: the forest left behind is leaked, which an exiting run can afford.
thread_local std::string lastLibscMessage;
thread_local int errnoAtLibscMessage = 0;

void KeepLibscMessage(FILE*, const char*, int, int, int, int, const char* message)
{
  errnoAtLibscMessage = errno;
  lastLibscMessage = message ? message : "";
  while (!lastLibscMessage.empty() && (lastLibscMessage.back() == '\n' || lastLibscMessage.back() == ' '))
    lastLibscMessage.pop_back();
}

void ThrowOnLibscAbort()
{
  const std::string message = lastLibscMessage;
  // sc_malloc's failed check names only its source line; malloc's errno says why.
  if (errnoAtLibscMessage == ENOMEM)
    throw std::bad_alloc();
  throw std::runtime_error("p4est stopped: " + (message.empty() ? std::string("no reason given") : message));
}
} // namespace

namespace
{
std::atomic<MPIStarter> registeredStarter{ nullptr };
std::mutex initializationMutex;
bool initialized = false; ///< guarded by initializationMutex
} // namespace

void InitializeP4est()
{
  // A mutex and a flag rather than std::call_once: a refusal below must leave the set-up to be
  // tried again (after the application registers a starter), and call_once's retry after an
  // exception is not reliable everywhere.
  std::lock_guard<std::mutex> lock(initializationMutex);
#ifdef SC_ENABLE_MPI
  // Every forest, not only the first: a forest is made on MPI_COMM_SELF, and any MPI call after
  // the application finalized MPI makes Open MPI abort the process.
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized)
    throw std::logic_error("MPI was finalized already in this process: meshing needs it running "
                           "(finalize it only after the last filter has run)");
#endif
  if (initialized)
    return;
#ifdef SC_ENABLE_MPI
  // MPI start-up is the application's: under mpirun or pvbatch MPI is up already; a plain
  // process has it started by the starter its front end registered (SetMPIStarter).
  int running = 0;
  MPI_Initialized(&running);
  if (!running)
  {
    if (const MPIStarter starter = registeredStarter.load())
    {
      starter();
      MPI_Initialized(&running);
    }
  }
  if (!running)
    throw std::logic_error("MPI is not running: start it before meshing (labelmesher::StartMPI, "
                           "Filters/MPIStartup.h), or register a starter with SetMPIStarter");
#endif
  // A libsc built without MPI (the Slicer extension's) has MPI stubs and nothing to start.
  sc_init(sc_MPI_COMM_SELF, 0, 0, KeepLibscMessage, SC_LP_ERROR);
  p4est_init(KeepLibscMessage, SC_LP_ERROR);
  sc_set_abort_handler(ThrowOnLibscAbort);
  initialized = true;
}

} // namespace detail

void SetMPIStarter(MPIStarter starter)
{
  detail::registeredStarter.store(starter);
}

int OctreeDepth(const LabelImage& image)
{
  int largest = std::max(image.Dimensions[0], image.Dimensions[1]);
  if (image.Dimension() == 3)
    largest = std::max(largest, image.Dimensions[2]);
  int depth = 1;
  while ((1 << depth) < largest)
    ++depth;
  return depth;
}

std::vector<OctreeLeaf> BuildOctree(int dimension, int depth, const LeafEvaluator& evaluate,
  const ProgressObserver& observer, double progressStart, double progressEnd)
{
  return dimension == 2 ? detail::BuildForest2(depth, evaluate, observer, progressStart, progressEnd)
                        : detail::BuildForest3(depth, evaluate, observer, progressStart, progressEnd);
}

} // namespace labelmesher
