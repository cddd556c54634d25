// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_PieceHandOut_h
#define labelmesher_PieceHandOut_h

/**
 * @file PieceHandOut.h
 * Each process's own piece of a mesh meshed on several: what vtkLabelMesher
 * does when a parallel pipeline (pvbatch, ParaView's server) asks every
 * process for its piece. Not installed.
 */

#include <string>

class vtkUnstructuredGrid;

namespace labelmesher
{

/// Collective over the world's processes. Rank 0 passes the whole mesh, whose
/// cell array "Process" names the process each cell goes to (without it, rank
/// 0 keeps every cell; with no cell, rank 0 made no mesh, which fails); the
/// others pass a grid that receives their piece. Rank
/// 0 sends one piece at a time (only one piece's bytes are held at once), then
/// keeps its own. Returns "" when every process holds its piece, else the
/// lowest failing process's reason, the same on every process, every `mesh`
/// then left empty: a piece missing would be a mesh silently wrong.
std::string HandOutPieces(vtkUnstructuredGrid* mesh);

} // namespace labelmesher

#endif
