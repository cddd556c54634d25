// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CurveCrossings_h
#define labelmesher_CurveCrossings_h

/**
 * @file CurveCrossings.h
 * A proof that boundary curves do not meet, themselves or one another, except
 * at the mesh vertices they share, by the convex hull property of Bézier curves: two pieces of curve
 * whose control polygons' hulls are disjoint do not meet; two pieces that end
 * at one vertex V meet only at V when the cones from V spanned by their other
 * control points are convex (narrower than a half turn) and disjoint.
 * Otherwise both pieces are split at their middles (de Casteljau) and the
 * halves tested, down to a depth limit; what is still undecided there counts
 * as meeting, so the answer errs only towards shortening a curve. The cone
 * test is what decides curves leaving a vertex at nearly the same angle, which
 * can cross arbitrarily close to it, below any polyline's resolution.
 */

#include "Curving/CubicTriangle.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

namespace labelmesher
{

struct BoundaryCurve
{
  std::array<Point2, 4> ControlPoints; ///< from the vertex From to the vertex To
  std::int64_t From = -1;
  std::int64_t To = -1;
};

/// Indices of the curves that may meet another curve away from a shared end
/// vertex, or loop. Curves are first cut into pieces within `flatness` of
/// their chords (which bins them compactly), and the pieces of one curve are
/// tested against each other too, consecutive ones at their shared cut point
/// as at a vertex; straight curves that meet are reported too.
std::set<std::size_t> MeetingCurves(const std::vector<BoundaryCurve>& curves, double flatness, int maxDepth = 12);

} // namespace labelmesher

#endif
