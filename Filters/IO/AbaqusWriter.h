// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_AbaqusWriter_h
#define labelmesher_io_AbaqusWriter_h

/**
 * @file AbaqusWriter.h
 * Abaqus input files (.inp; also read by CalculiX, FEBio's importer, meshio):
 * `*NODE`, then one `*ELEMENT` block per material (C3D4 tetrahedra; in 2D
 * CPS3 plane-stress triangles with x, y nodes when the mesh lies in an axis
 * plane, else S3 shells in 3D space) whose ELSET is the material's name, and
 * one `*NSET` per interface holding the nodes of its faces, named
 * `NAME_A__NAME_B`. Abaqus names are made of letters, digits and `_`, start
 * with a letter, are at most 80 characters and compare case-insensitively:
 * other characters become `_`, and a name that would repeat another gets
 * `_L<label>` appended. Node and element numbers start at 1.
 */

#include <cstdint>
#include <ostream>
#include <string>

namespace labelmesher
{
namespace io
{

struct ExportMesh;

void WriteAbaqus(const ExportMesh& mesh, std::ostream& out);

} // namespace io
} // namespace labelmesher

#endif
