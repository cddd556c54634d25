// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_SmoothBoundary_h
#define labelmesher_SmoothBoundary_h

/**
 * @file SmoothBoundary.h
 * A smooth cubic Bézier path through given vertices (section 4.1, Figure 17).
 *
 * C1: the tangent construction of Figure 17a. The inner control point after
 * vertex P1 on segment P1→P2 is P1 + t·(P2 − P0)·|P1P2| / (|P0P1| + |P1P2|),
 * t the tension (t = 1/3 on evenly spaced points is the Catmull–Rom spline;
 * t = 0 gives straight segments). At the ends of an open chain the handle lies
 * on the end chord: P0 + t·(P1 − P0).
 * C2: B-spline points B solve 6 S_i = B_{i-1} + 4 B_i + B_{i+1} (Figure 17c);
 * the segment S_i→S_{i+1} has inner control points at 1/3 and 2/3 of B_i B_{i+1}.
 * Closed chains are periodic. Open chains keep their end vertices and use
 * natural end conditions (B_0 = S_0, B_n = S_n: zero second derivative).
 * Chains too short to bend (one open segment, a closed chain of at most two
 * vertices) stay straight, with control points at 1/3 and 2/3.
 */

#include "Curving/CubicTriangle.h"

#include <array>
#include <vector>

namespace labelmesher
{

enum class Smoothness
{
  C1 = 1,
  C2 = 2
};

struct SmoothingOptions
{
  Smoothness Continuity = Smoothness::C2;
  double Tension = 1.0 / 3.0; ///< C1 only: handle length factor (dimensionless)
};

/// Inner control points of each segment of the path: entry s belongs to the
/// segment vertices[s] → vertices[s + 1] (for a closed chain also the last
/// segment vertices[n-1] → vertices[0]), ordered from its start to its end.
std::vector<std::array<Point2, 2>> SmoothChain(
  const std::vector<Point2>& vertices, bool closed, const SmoothingOptions& options);

} // namespace labelmesher

#endif
