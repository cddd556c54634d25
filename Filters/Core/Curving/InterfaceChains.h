// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_InterfaceChains_h
#define labelmesher_InterfaceChains_h

/**
 * @file InterfaceChains.h
 * The curves a 2D mesh's material boundaries are made of (section 4.1,
 * generalised to many materials): edges between cells of different materials,
 * and edges used by one cell (the outside counts as material 0), grouped into
 * maximal chains. A chain breaks where the interface graph does not have
 * degree 2 (three or more materials meet, or a pinch) and at the image border:
 * edges lying on the border box are not interfaces (they stay straight) and
 * their vertices end chains. Chains without an end are closed loops.
 */

#include "Mesh/SimplexMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

struct InterfaceChain
{
  /// Mesh point ids in order along the chain; a closed chain does not repeat its first vertex.
  /// An open chain may end where it starts (a loop through a junction or a border vertex).
  std::vector<std::int64_t> Vertices;
  bool Closed = false;
  /// Materials on either side: First on the left of the chain's direction, Second on the right.
  /// First is the larger label, so a region in the background is walked counter-clockwise.
  std::int32_t FirstMaterial = 0;
  std::int32_t SecondMaterial = 0;
};

/// Axis-aligned box [xmin, xmax] × [ymin, ymax] in the mesh's coordinates.
using Box2 = std::array<double, 4>;

/// Chains of a 2D mesh (Dimension == 2). Edges with both ends on one side of
/// `border` (to within 1e-9 of its size) are left out; pass the mesh's own
/// bounding box when no image border is known.
std::vector<InterfaceChain> ExtractInterfaceChains(const SimplexMesh& mesh, const Box2& border);

/// The bounding box of the mesh's points (x and y).
Box2 BoundingBox2(const SimplexMesh& mesh);

} // namespace labelmesher

#endif
