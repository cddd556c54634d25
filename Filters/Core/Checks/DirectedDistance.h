// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_DirectedDistance_h
#define labelmesher_DirectedDistance_h

/**
 * @file DirectedDistance.h
 * Internal to the checks (not installed, not part of the public API): one
 * side of the Hausdorff distance, h(A, T) = sup over x in A of d(x, T), for
 * finite unions A (the elements) and T (the targets) of convex pieces,
 * bounded rigorously by branch and bound (DirectedDistance.cxx).
 */

#include "Checks/ConvexShape.h"

#include <vector>

namespace labelmesher
{
namespace checks_detail
{

/// Upper bound on h(elements, targets), tight to `tolerance` unless the depth
/// or work limit is hit (then still an upper bound, only less tight).
/// 0 if there are no elements, +infinity if there are elements but no targets.
double MeasureDirected(
  const std::vector<Shape>& elements, const std::vector<Shape>& targets, double tolerance);

/// True only if h(elements, targets) <= h is certified (up to RoundOff); an
/// element left undecided at the depth or work limit makes it false.
bool WithinDirected(const std::vector<Shape>& elements, const std::vector<Shape>& targets, double h);

} // namespace checks_detail
} // namespace labelmesher

#endif
