// SPDX-License-Identifier: GPL-2.0-or-later
// MPIPartExchange.h once the application has finalized MPI (a front end that finalizes it before
// a last filter runs): this process is alone, and nothing calls MPI after MPI_Finalize, which Open
// MPI refuses by aborting the process. In a death test's child, so that MPI ends only there.
#include "MPIPartExchange.h"
#include "MPIStartup.h"
#include "Streaming/PartExchange.h"

#include <gtest/gtest.h>
#include <sc.h> // mpi.h when libsc has MPI

#include <cstdlib>

namespace
{
using namespace labelmesher;

TEST(MPIPartExchange, AfterMPIIsFinalizedThisProcessIsAlone)
{
#ifndef SC_ENABLE_MPI
  GTEST_SKIP() << "libsc without MPI";
#else
  GTEST_FLAG_SET(death_test_style, "threadsafe"); // a fresh process: MPI never up in the parent's copy
  EXPECT_EXIT(
    {
      StartMPI();
      MPI_Finalize();
      const bool alone = WorldRank() == 0 && WorldSize() == 1 && WorldPartExchange() == nullptr &&
        FirstFailure("reason") == "reason" && DifferenceFromRankZero("fingerprint").empty();
      std::_Exit(alone ? 0 : 3);
    },
    ::testing::ExitedWithCode(0), "");
#endif
}

} // namespace
