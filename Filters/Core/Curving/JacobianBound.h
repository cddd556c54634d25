// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_JacobianBound_h
#define labelmesher_JacobianBound_h

/**
 * @file JacobianBound.h
 * Validity of a cubic Bézier triangle (dissertation section 4.2).
 *
 * The Jacobian determinant det J = det ∂(x, y)/∂(x̂, ŷ) of a cubic triangle is a
 * quartic Bézier triangle whose 15 control values are those of Table 1; for a
 * straight triangle it is twice the signed area everywhere. Control values
 * bound the Jacobian from below and above (convex hull property); subdividing
 * the quartic tightens the bounds. Theorem 4.2.1 offers a faster test on the
 * control net alone; as printed (no inverted control triangle) it does not prove
 * validity, so HasUntwistedControlNet also asks the control triangles not to be
 * twisted against each other.
 */

#include "Curving/CubicTriangle.h"

#include <array>

namespace labelmesher
{

/// A scalar quartic Bézier triangle: 15 control values indexed by QuarticIndex(i, j, k).
struct QuarticTriangle
{
  std::array<double, 15> Values;
};

/// Storage index (0..14) of the control value with multi-index (i, j, k), i + j + k = 4.
int QuarticIndex(int i, int j, int k);

/// Table 1: the control values of det J.
QuarticTriangle JacobianControlValues(const CubicTriangle& triangle);

/// det J at (u, v, w) computed from the cubic's derivatives (independent of Table 1).
double EvaluateJacobian(const CubicTriangle& triangle, double u, double v, double w);

/// The quartic at (u, v, w).
double EvaluateQuartic(const QuarticTriangle& quartic, double u, double v, double w);

/// Algorithm 5: true when the quartic Bézier curve with these control values is
/// proven positive on [0, 1]; false when a non-positive value was found or the
/// subdivision depth ran out (conservative).
bool IsQuarticCurvePositive(const std::array<double, 5>& controlValues, int maximumDepth = 20);

/// Theorem 4.2.1, corrected: true when none of the six upward control triangles
/// (P_{i+1,j,k}, P_{i,j+1,k}, P_{i,j,k+1}), i + j + k = 2, is inverted (signed area > 0)
/// and every pair of them has a non-negative mixed term D1_m × D2_n + D1_n × D2_m
/// (D1, D2: the edge vectors from the first vertex), which proves det J > 0 on the
/// whole triangle. Positive areas alone do not (see JacobianBound.cxx).
bool HasUntwistedControlNet(const CubicTriangle& triangle);

/// Validity is decided against a degeneracy threshold τ = 1e-9 × the largest
/// |Table 1 control value|: a Jacobian that vanishes to within rounding (e.g. at
/// a corner where two curved edges leave along one tangent) is not positive.
enum class Validity
{
  Valid,    ///< det J > τ proven everywhere
  Invalid,  ///< a point with det J <= τ was found
  Undecided ///< neither could be shown within the subdivision depth (treat as invalid)
};

struct JacobianBoundOptions
{
  int MaximumDepth = 10;          ///< levels of 4-way subdivision of the quartic
  double RelativeTolerance = 1e-3; ///< stop when (found - lower) <= tolerance * |upper|
};

struct JacobianBounds
{
  double Lower = 0.0;        ///< proven: det J >= Lower everywhere
  double Upper = 0.0;        ///< proven: det J <= Upper everywhere
  double MinimumFound = 0.0; ///< a value det J actually takes (Lower <= min det J <= MinimumFound)
  Validity Result = Validity::Undecided;

  /// Lower / Upper: a conservative scaled Jacobian (1 for a straight triangle).
  double ScaledJacobian() const { return Upper > 0.0 ? Lower / Upper : 0.0; }
};

/// Tight bounds on det J by recursive subdivision of the quartic triangle.
JacobianBounds BoundJacobian(const CubicTriangle& triangle, const JacobianBoundOptions& options = {});

/// Fast classification: the control-net test first, then the control values,
/// Algorithm 5 on the three boundary curves (which can only find an invalid
/// cell), and triangle subdivision (until the sign of min det J is known) last.
Validity ClassifyValidity(const CubicTriangle& triangle, const JacobianBoundOptions& options = {});

} // namespace labelmesher

#endif
