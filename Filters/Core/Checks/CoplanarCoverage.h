// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CoplanarCoverage_h
#define labelmesher_CoplanarCoverage_h

/**
 * @file CoplanarCoverage.h
 * Internal to the checks (not installed, not part of the public API): the
 * exact zero of the Hausdorff distance check. An element lying in an
 * axis-aligned plane (line in 2D) is at distance 0 from the targets if
 * coplanar targets cover it: the clipped areas (lengths) of pairwise
 * non-overlapping coplanar targets add up to its area (length), to a relative
 * 1e-9. Corner distances alone never reach 0 on a voxel face covered by two
 * mesh triangles (or the converse), so without this h = 0 could not be
 * certified.
 */

#include "Checks/ConvexShape.h"

#include <cstdint>
#include <vector>

namespace labelmesher
{
namespace checks_detail
{

/// True if the flat element e (e.Axis >= 0) is covered by the targets[id],
/// id in `candidates`, that lie in its plane (Shape::Axis, Shape::Plane).
/// False, not "maybe", when coplanar candidates overlap: their sum proves nothing.
bool CoveredByCoplanar(
  const Shape& e, const std::vector<Shape>& targets, const std::vector<std::uint32_t>& candidates);

} // namespace checks_detail
} // namespace labelmesher

#endif
