// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ImageFingerprint_h
#define labelmesher_ImageFingerprint_h

/**
 * @file ImageFingerprint.h
 * What decides a mesh about a label image, as text: its extent, spacing,
 * origin, direction and a hash (FNV-1a) of its labels' bytes. The processes of a
 * distributed run (the CLI under mpirun, vtkLabelMesher Distributed) compare
 * theirs with rank 0's (DifferenceFromRankZero, MPIPartExchange.h): parts of
 * different images would not join into one mesh. Not installed.
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
