// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CornerHandles_h
#define labelmesher_CornerHandles_h

/**
 * @file CornerHandles.h
 * A curve leaves a vertex along its handle, not its chord, so each cell next
 * to the curve there has a corner larger or smaller than in the linear mesh by
 * the angle between the two. A decimated mesh has many angles at its bound
 * (the merges go as far as it allows), and a fitted handle turned a few
 * degrees towards one of those cells takes its corner below the bound; the
 * curver then has to make the curve straight (CurvingParameters::
 * MinimumCornerAngle). Turning the handle back, as little as it takes, keeps
 * the curve: each cell at the vertex that has the curve's edge allows the
 * handle an interval of directions (its linear angle minus the bound, towards
 * the cell), and at a vertex where a chain passes smoothly one rotation turns
 * both sides' handles, so the path stays C1. The cell's other edge is taken
 * as its chord: where it is curved too, or untangling bends it, the curver's
 * own check decides (this only makes its work rarer).
 */

#include "Curving/CurvePieces.h"
#include "Curving/QuadraticForm.h"
#include "Curving/InterfaceChains.h"
#include "Mesh/SimplexMesh.h"

#include <vector>

namespace labelmesher
{

/// Turns the handles of `pieces` (one per chain segment, in the order of
/// `chains`: SmoothInterfaces) at every chain vertex where a rotation exists
/// that keeps every corner next to the curves there at `bound` degrees or
/// more; where none exists they stay as fitted. Returns the vertices turned.
std::size_t TurnHandlesToKeepCorners(const SimplexMesh& linear, const std::vector<InterfaceChain>& chains,
  std::vector<CurvePiece>& pieces, double bound);

/// The quadratic analogue (CurvingParameters::Order 2): a quadratic's one control point sets the
/// tangents at both ends, so no rotation at a vertex can turn one without the other; instead each
/// quadratic piece whose ends leave a corner below `bound` degrees (the cells' other edges taken
/// as their chords) has its control point pulled towards its chord's midpoint, to the largest of
/// 1, 0.9, ..., 0 of its offset that keeps both ends, which turns both tangents towards the chord.
/// Returns the pieces pulled.
std::size_t PullQuadraticsToKeepCorners(const SimplexMesh& linear, std::vector<CurvePiece>& pieces, double bound);

} // namespace labelmesher

#endif
