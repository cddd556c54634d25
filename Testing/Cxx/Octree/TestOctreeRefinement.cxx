// SPDX-License-Identifier: GPL-2.0-or-later
// The core starts no MPI (issue 34): without MPI running and without a starter registered by the
// application, building the forest is refused with one clear error, not started behind the
// application's back; with the starter (as every front end and GTestMain.cxx register it) the same
// image meshes. Runs in its own process under ctest (MPI not yet up); skipped otherwise.
#include "LabelOctreeMesher.h"
#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"

#include <gtest/gtest.h>
#include <sc.h> // mpi.h when libsc has MPI

#include <stdexcept>
#include <string>

namespace
{
using namespace labelmesher;

TEST(OctreeRefinement, TheCoreStartsNoMPIItself)
{
#ifndef SC_ENABLE_MPI
  GTEST_SKIP() << "libsc without MPI: nothing to start";
#else
  int running = 0;
  MPI_Initialized(&running);
  if (running)
    GTEST_SKIP() << "MPI is up already in this process (run this test on its own, as ctest does)";
  LabelImage image(6, 6, 6);
  image(2, 2, 2) = image(3, 2, 2) = 1;
  SetMPIStarter(nullptr);
  try
  {
    MeshLabelImage(image, MesherParameters{});
    FAIL() << "meshed without MPI";
  }
  catch (const std::logic_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("MPI is not running"), std::string::npos) << e.what();
  }
  MPI_Initialized(&running);
  EXPECT_EQ(running, 0) << "the core started MPI";
  SetMPIStarter(&StartMPI);
  const MesherResult result = MeshLabelImage(image, MesherParameters{});
  EXPECT_GT(result.Mesh.NumberOfCells(), 0u);
  MPI_Initialized(&running);
  EXPECT_EQ(running, 1);
#endif
}

} // namespace
