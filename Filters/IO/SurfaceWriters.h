// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_SurfaceWriters_h
#define labelmesher_io_SurfaceWriters_h

/**
 * @file SurfaceWriters.h
 * The interface surface (every face between two materials, background
 * included) for surface tools: binary STL (triangles only, so 3D; single
 * precision by the format's definition; the 16-bit attribute of each facet is
 * its interface's position 1, 2, ... in pair order) for all interfaces or for
 * one of them, and Wavefront OBJ with one group `g NAME_A|NAME_B` per interface
 * (triangles in 3D, `l` segments in 2D), coordinates exact.
 */

#include <cstddef>
#include <ostream>

namespace labelmesher
{
namespace io
{

struct ExportMesh;

/// Every interface (`interface` < 0) or only mesh.Interfaces[interface].
void WriteStl(const ExportMesh& mesh, std::ostream& out, long interface = -1);
void WriteObj(const ExportMesh& mesh, std::ostream& out);

} // namespace io
} // namespace labelmesher

#endif
