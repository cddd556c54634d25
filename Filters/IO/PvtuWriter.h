// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_io_PvtuWriter_h
#define labelmesher_io_PvtuWriter_h

/**
 * @file PvtuWriter.h
 * A mesh as a VTK parallel unstructured grid: the summary `NAME.pvtu` and one
 * `.vtu` piece per process that meshed it (the cell array "Process", which
 * vtkLabelMesher writes for a run under mpirun; one piece without it), named
 * as VTK's vtkXMLPUnstructuredGridWriter names them and listed in its summary.
 * ParaView opens the summary and shows the pieces as one mesh.
 *
 * Every file goes through SafeFile (whole or not at all); the summary is
 * written last, so it never names a piece that is not there, and when any
 * file fails, the pieces already written are removed again. Once all are
 * written, the pieces of an earlier run on more processes that the new
 * summary no longer names are removed (only names VTK gives pieces).
 */

#include <string>
#include <vector>

class vtkUnstructuredGrid;

namespace labelmesher
{
namespace io
{

/// Throws WriteError unless a summary can be written as `path`: SafeFile's
/// checks, and `path` is not a symbolic link to a file (VTK reads a summary's
/// pieces beside the name it is opened by: through a link they would be
/// looked for beside the link or beside its target, never both).
void CheckPvtuPath(const std::string& path);

/// Writes `mesh` as `path` (.pvtu) and its pieces beside it; returns the files
/// written, the summary first. Throws WriteError (one line).
std::vector<std::string> WritePvtu(vtkUnstructuredGrid* mesh, const std::string& path);

} // namespace io
} // namespace labelmesher

#endif
