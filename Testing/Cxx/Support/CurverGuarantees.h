// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_CurverGuarantees_h
#define labelmesher_testing_CurverGuarantees_h

/**
 * @file CurverGuarantees.h
 * Every guarantee of the curved 2D mesh on one image, through the whole
 * pipeline of `labelmesher curve` (and of a 2D `labelmesher mesh --order 2`:
 * quadratic triangles): mesher, decimator, foreground, curver with the image
 * and the mesher's distance bounds. Asserted independently of the
 * curver's own tests: det J sampled densely on every cell proven valid,
 * continuity at every joint on the output control points (CurvingChecks.h),
 * both distance bounds per material measured on the curves, no crossing
 * interfaces and the image's topology (Checks/CurvedBoundary.h). Shared by the
 * curver's property test and labelmesher_property_scan --curve.
 */

#include "Curving/BezierCurver.h"
#include "Decimation/MeshDecimator.h"
#include "LabelOctreeMesher.h"

#include <cstdint>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

struct CurverRun
{
  SimplexMesh Linear;   ///< the decimated foreground mesh that was curved
  CurvingResult Result;
  std::size_t MisclassifiedLinear = 0;
  std::size_t MisclassifiedCurved = 0;
};

/// The curving a test uses for `seed`: C1 or C2 with even odds.
Smoothness DrawSmoothness(std::uint64_t seed);

/// The scaled Jacobian every curved cell keeps (`labelmesher curve`'s default), asserted here.
constexpr double kCurvedScaledJacobian = 0.1;

/// Runs the pipeline on `image`; one line per violated guarantee (empty: all
/// hold). A thrown exception counts as a violation. `run`, when given,
/// receives the meshes and the pixel accuracy of both. `curverScaledJacobian`
/// is what the curver is asked for (kCurvedScaledJacobian is asserted whatever
/// it is: 0 switches the curver's bound off, which the tests use to show the
/// check can fail). Likewise `curverCornerAngle` (negative: the decimation's
/// MinimumAngle, what `labelmesher curve` asks): every corner angle of the
/// curved cells, measured from points evaluated along the edges, is asserted
/// at least the decimation's MinimumAngle whatever the curver is asked.
/// `curverOrder` is the curver's CurvingParameters::Order; `assertedOrder` 2 also asserts that every
/// cell is exactly a quadratic triangle (its control points those of an elevated quadratic, and
/// the 6-node triangle of its corners and mid-nodes the same map at dense points), and skips the
/// joints' C1/C2 continuity (quadratics meet with G0 only); it is the curver's order unless given
/// (the tests ask a cubic curver for it, to show that check can fail).
std::vector<std::string> ViolatedCurverGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, Smoothness smoothness, CurverRun* run = nullptr,
  double curverScaledJacobian = kCurvedScaledJacobian, double curverCornerAngle = -1.0, int curverOrder = 3,
  int assertedOrder = 0);

} // namespace testing
} // namespace labelmesher

#endif
