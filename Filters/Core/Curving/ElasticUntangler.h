// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ElasticUntangler_h
#define labelmesher_ElasticUntangler_h

/**
 * @file ElasticUntangler.h
 * Mesh untangling by linear elasticity on the control nets (section 4.3,
 * Figures 20 and 21). The control nets of all cells (nine sub-triangles per
 * cell) form the undeformed elastic body; prescribed control points (those of
 * curved boundary edges) are moved to their targets, mesh vertices and the
 * points of unprescribed mesh-boundary edges stay fixed, and every other
 * control point (interior edge points, cell interior points) moves to the
 * equilibrium of a plane-strain linear elasticity problem (P1 elements on the
 * sub-triangles, stiffened by 1/area; Eigen CG, sparse Cholesky as fallback).
 * A prescribed mesh vertex moves like any prescribed point. When cells remain
 * invalid the displacement is applied in 2, 4, 8, ... increasing fractions,
 * each step's solution becoming the next step's undeformed body, up to
 * MaximumSteps fractions.
 */

#include "Curving/CurvedMesh.h"
#include "Support/ProgressObserver.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace labelmesher
{

struct UntanglingOptions
{
  int MaximumSteps = 64;      ///< most load fractions tried (1, 2, 4, ... up to this)
  int QualityIterations = 0;  ///< further doublings of the fractions (within MaximumSteps), kept when the worst scaled Jacobian improves
  double PoissonRatio = 0.3;  ///< of the elastic body, in [0, 0.5)
};

struct UntanglingResult
{
  bool Valid = false;                 ///< every cell proven valid (ClassifyValidity)
  int Steps = 0;                      ///< load fractions used by the accepted solution (0: nothing to move, or no solve succeeded)
  std::vector<std::size_t> InvalidCells; ///< cells not proven valid (empty when Valid)
  double MinimumScaledJacobian = 0.0; ///< over all cells, JacobianBounds::ScaledJacobian
};

/// Moves `mesh`'s prescribed control points to their targets and the free ones
/// to equilibrium. On return `mesh` holds the best solution found (valid if
/// any was). Throws AbortRequested when the observer asks to stop (`mesh` is
/// then unchanged) and std::invalid_argument for a prescribed id that does not
/// exist or options out of range.
UntanglingResult UntangleControlNets(CurvedMesh& mesh,
  const std::vector<std::pair<std::int64_t, Point2>>& prescribed, const UntanglingOptions& options,
  const ProgressObserver& observer = {});

} // namespace labelmesher

#endif
