// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_GmshWriter_h
#define labelmesher_io_GmshWriter_h

/**
 * @file GmshWriter.h
 * Gmsh MSH files, ASCII, version 4.1 (Gmsh's own) or 2.2 (what many solvers
 * still read: FEniCS' dolfin-convert, Elmer, older FEBio).
 *
 * Each material is one elementary entity of the mesh's dimension (volumes in
 * 3D, surfaces in 2D), numbered 1, 2, ... in label order, in a physical group
 * whose tag is the image label and whose name is the material's
 * (MaterialTable::NameOf). Gmsh tags must be positive, so the background
 * (label 0, kept with --include-background) gets the physical tag
 * `largest label + 1`. Each interface between two materials is one entity of
 * one dimension less (triangles in 3D, segments in 2D), in a physical group
 * numbered 1, 2, ... in pair order and named `NAME_A|NAME_B`. All nodes lie in
 * one block on the first entity.
 */

#include <ostream>

namespace labelmesher
{
namespace io
{

struct ExportMesh;

/// The physical tag of a material in both versions.
int GmshPhysicalTag(const ExportMesh& mesh, int label);

void WriteGmsh41(const ExportMesh& mesh, std::ostream& out);
void WriteGmsh22(const ExportMesh& mesh, std::ostream& out);

} // namespace io
} // namespace labelmesher

#endif
