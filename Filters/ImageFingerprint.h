// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ImageFingerprint_h
#define labelmesher_ImageFingerprint_h

/**
 * @file ImageFingerprint.h
 * Where a label image places its mesh, as text: its extent, spacing, origin
 * and direction. The processes of a distributed run (the CLI under mpirun,
 * vtkLabelMesher Distributed) compare it with rank 0's (SameAsRankZero,
 * MPIPartExchange.h): parts of different images would not join into one mesh.
 * Their labels are compared slab by slab as each process takes its slab
 * (PartAssignment::SlabHash), since a process may hold no more. Not installed.
 */

#include <string>

class vtkImageData;

namespace labelmesher
{

/// "" for a null image.
std::string ImageFingerprint(vtkImageData* image);

} // namespace labelmesher

#endif
