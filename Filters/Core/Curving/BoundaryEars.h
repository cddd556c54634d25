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
 * stay conforming) gives two cells with one chain edge each at that vertex,
 * but may halve an angle of the linear mesh. Breaking the chain at the ear's
 * vertex instead lets the curve turn there (a corner, each side's tangent its
 * own), and keeps the linear mesh as it is.
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

/// The vertices where `chains` pass smoothly through an ear of `mesh`, in increasing order.
std::vector<std::int64_t> EarVertices(const SimplexMesh& mesh, const std::vector<InterfaceChain>& chains);

/// `chains` broken at `vertices` (sorted): a closed chain through one becomes an open chain that
/// starts and ends there, an open chain through one becomes two. Materials are kept.
std::vector<InterfaceChain> BreakChainsAt(const std::vector<InterfaceChain>& chains,
  const std::vector<std::int64_t>& vertices);

} // namespace labelmesher

#endif
