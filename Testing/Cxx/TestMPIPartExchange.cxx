// SPDX-License-Identifier: GPL-2.0-or-later
// Once the application has finalized MPI (a front end that finalizes it before a last filter
// runs): MPIPartExchange.h sees this process alone, and meshing is refused with an error, where
// a forest made on MPI_COMM_SELF would call MPI after MPI_Finalize, which Open MPI answers by
// aborting the process. In a death test's child, so that MPI ends only there.
#include "LabelOctreeMesher.h"
#include "MPIPartExchange.h"
#include "MPIStartup.h"
#include "Streaming/PartExchange.h"

#include <gtest/gtest.h>
#include <sc.h> // mpi.h when libsc has MPI

#include <cstdlib>
#include <stdexcept>
#include <string>

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
        FirstFailure("reason") == "reason" && SameAsRankZero("fingerprint");
      std::_Exit(alone ? 0 : 3);
    },
    ::testing::ExitedWithCode(0), "");
#endif
}

TEST(MPIPartExchange, MeshingAfterMPIIsFinalizedIsAnError)
{
#ifndef SC_ENABLE_MPI
  GTEST_SKIP() << "libsc without MPI";
#else
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
    {
      LabelImage image(6, 6, 6);
      image(2, 2, 2) = image(3, 2, 2) = 1;
      StartMPI();
      MeshLabelImage(image, MesherParameters{}); // a forest before, as a session would have made
      MPI_Finalize();
      bool refused = false;
      try
      {
        MeshLabelImage(image, MesherParameters{});
      }
      catch (const std::logic_error& e)
      {
        refused = std::string(e.what()).find("MPI was finalized") != std::string::npos;
      }
      std::_Exit(refused ? 0 : 3);
    },
    ::testing::ExitedWithCode(0), "");
#endif
}

} // namespace
