// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BoundaryEars_h
#define labelmesher_BoundaryEars_h

/**
 * @file BoundaryEars.h
 * Ears: triangles with two edges on one smooth interface chain, meeting at a
 * vertex inside the chain. Once the chain is curved C1 or C2, those two edges
 * leave that vertex along the same tangent, so det J = 0 at the corner whatever
 * the interior control points do: no untangling can make the cell valid.
 * Splitting the ear's third edge at its midpoint (and the cell across it, to
 * stay conforming) gives two cells with one chain edge each at that vertex.
 * The dissertation's single closed boundary (section 4.1) rarely has ears;
 * multi-material label meshes (one-pixel lines, speckle) do.
 */

#include "Curving/InterfaceChains.h"
#include "Mesh/SimplexMesh.h"

#include <cstddef>
#include <vector>

namespace labelmesher
{

/// Splits the ears of `mesh` (with respect to `chains`, which are re-extracted
/// with `border` after every round) for at most `maximumRounds` rounds. Returns
/// the number of edges split; `chains` holds the chains of the final mesh.
/// Ears that remain (e.g. a lone triangle whose three edges form a closed
/// chain) are left to the validity check, which reports them.
std::size_t SplitBoundaryEars(SimplexMesh& mesh, std::vector<InterfaceChain>& chains,
  const Box2& border, int maximumRounds = 8);

} // namespace labelmesher

#endif
