// SPDX-License-Identifier: GPL-2.0-or-later
// main() of the GoogleTest programs: GoogleTest's, plus the application's MPI start-up registered
// with the core (it starts MPI itself nowhere), used only by tests that build an octree.
#include "MPIStartup.h"
#include "Octree/OctreeRefinement.h"

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  labelmesher::SetMPIStarter(&labelmesher::StartMPI);
  return RUN_ALL_TESTS();
}
