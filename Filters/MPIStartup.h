// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MPIStartup_h
#define labelmesher_MPIStartup_h

/**
 * @file MPIStartup.h
 * MPI for a process that nobody started under mpirun: the application's business, kept out of
 * the algorithm core (which only needs MPI running, Octree/OctreeRefinement.h SetMPIStarter).
 * The filters call StartMPI before they mesh; the CLI and the viewer run through them (the viewer
 * starts MPI itself, with thread support, before any filter); tests, benchmarks and the property
 * scan register it with SetMPIStarter in their main. Library LabelMesherMPIStartup.
 */

#include <cstdint>

namespace labelmesher
{

/// Starts MPI when it is not running (a singleton start, about 0.3 s once; under mpirun or
/// pvbatch it is up already and left alone) and finalizes it at exit. Open MPI's line for every
/// optional transport it cannot load (e.g. under ulimit -v) stays off unless the user's
/// environment asks for it. Idempotent and thread-safe; nothing to do where libsc was built
/// without MPI (the 3D Slicer extension's).
void StartMPI();

/// True when MPI is running in this process: started and not finalized (or libsc has no MPI:
/// nothing will start).
bool MPIRunning();

/// Address space a singleton start of MPI still takes in this process: 0 once it runs. Open MPI
/// 4.1 maps its components and starts helper threads, whose stacks and malloc arenas count
/// against ulimit -v: measured here it grows the address space by up to 200 MiB, of which it can
/// do without most (components that fail to map are skipped), but below about 50 MiB of headroom
/// its start crashes or prints its own errors. The memory estimate reserves this much under
/// ulimit -v so that such a run is refused before MPI starts (MemoryBudget.h).
std::uint64_t MPIStartAddressSpace();

} // namespace labelmesher

#endif
