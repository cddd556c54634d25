// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_MeditWriter_h
#define labelmesher_io_MeditWriter_h

/**
 * @file MeditWriter.h
 * Medit / INRIA .mesh files, ASCII, `MeshVersionFormatted 2` (doubles), as
 * MMG, FreeFem++, TetGen and CGAL read them. The elements carry their
 * material's image label as reference; each interface face is written once
 * (Triangles in 3D, Edges in 2D) with the reference
 * `a * (L + 1) + b` for materials a < b and L the largest label (when that
 * fits in 31 bits; otherwise the interface's position 1, 2, ... in pair
 * order). Comment lines list every reference with the material names. A 2D
 * mesh in an axis plane is written with `Dimension 2` (the two in-plane
 * coordinates, triangles counter-clockwise); any other 2D mesh with
 * `Dimension 3`. Indices start at 1; vertices have reference 0.
 */

#include <cstdint>
#include <ostream>

namespace labelmesher
{
namespace io
{

struct ExportMesh;

/// The reference of interface `index` (into mesh.Interfaces).
std::int64_t MeditInterfaceReference(const ExportMesh& mesh, std::size_t index);

void WriteMedit(const ExportMesh& mesh, std::ostream& out);

} // namespace io
} // namespace labelmesher

#endif
