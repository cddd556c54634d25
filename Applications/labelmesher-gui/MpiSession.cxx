// SPDX-License-Identifier: GPL-2.0-or-later
#include "MpiSession.h"

#include <mpi.h>

namespace labelmesher
{
namespace gui
{

MpiSession::MpiSession()
{
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized)
  {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    this->Started = true;
  }
}

MpiSession::~MpiSession()
{
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (this->Started && !finalized)
  {
    MPI_Finalize();
  }
}

} // namespace gui
} // namespace labelmesher
