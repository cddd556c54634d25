// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ImageFingerprint_h
#define labelmesher_ImageFingerprint_h

/**
 * @file ImageFingerprint.h
 * What decides a mesh about a label image, as text: its extent, spacing,
 * origin, direction and, given its labels, a hash (FNV-1a) of their bytes. The
 * processes of a distributed run (the CLI under mpirun, vtkLabelMesher
 * Distributed) compare its geometry with rank 0's (DifferenceFromRankZero,
 * MPIPartExchange.h): parts of different images would not join into one mesh.
 * Their labels are compared slab by slab as each process takes its slab
 * (PartAssignment::SlabHash), since a process may hold no more. Not installed.
 */

#include <string>

class vtkDataArray;
class vtkImageData;

namespace labelmesher
{

/// "" for a null image; `labels` may be null (then only the geometry).
std::string ImageFingerprint(vtkImageData* image, vtkDataArray* labels);

} // namespace labelmesher

#endif
