// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_CurvingChecks_h
#define labelmesher_testing_CurvingChecks_h

/**
 * @file CurvingChecks.h
 * Independent checks of a curved mesh for the curver's tests: det J sampled
 * densely (not via Table 1 or subdivision), and the continuity of the curved
 * interfaces measured at every joint on the output control points.
 */

#include "Curving/BezierCurver.h"
#include "LabelOctreeMesher.h"

#include <string>

namespace labelmesher
{
namespace testing
{

/// The cells of non-zero material of a mesher result, with compacted points.
SimplexMesh ForegroundMesh(const SimplexMesh& mesh);

/// Smallest det J over a barycentric grid of `n` steps per side (corners included).
double SampledMinimumJacobian(const CubicTriangle& triangle, int n = 24);
/// The smallest over the largest det J at the same samples: at least the true min det J / max
/// det J, so at least any certified lower bound of it (JacobianBounds::ScaledJacobian).
double SampledJacobianRatio(const CubicTriangle& triangle, int n = 24);
/// The smallest angle between the tangents of two edges at a corner, degrees, each tangent taken
/// from points evaluated along its edge (not from the control points), accurate to about 1e-7
/// degrees on cells of up to a few hundred voxels: kCornerAngleTolerance covers it.
double SampledCornerAngle(const CubicTriangle& triangle);
constexpr double kCornerAngleTolerance = 1e-6;

/// The largest distance, over a barycentric grid of `n` steps per side, between the cell's map and
/// the 6-node quadratic (Lagrange) triangle through its corners and its edges' points at their
/// middle: 0 (up to rounding) exactly when the cell is a quadratic triangle written as a cubic.
double QuadraticNodesMismatch(const CubicTriangle& triangle, int n = 12);

struct JointContinuity
{
  std::size_t Joints = 0;
  /// Largest mismatch of first derivatives at a joint (C2: of the vectors,
  /// relative to the largest first or second derivative there; C1: of the unit tangents).
  double FirstDerivativeMismatch = 0.0;
  /// Same for second derivatives (measured for C2 only).
  double SecondDerivativeMismatch = 0.0;
  /// Largest distance of a chain vertex from its linear position.
  double VertexMovement = 0.0;
  /// Joints next to a straightened piece (no continuity asked), and joints
  /// next to a shortened one (tangent continuity only).
  std::size_t StraightJoints = 0;
  std::size_t ShortenedJoints = 0;
};

/// Measures continuity at every interior joint of every chain of `linear`
/// (extracted with `border`) on the control points of `curved`: C1 (unit
/// tangents) or C2 (first and second derivatives) where both pieces at the
/// joint are at scale 1 in `pieces` (CurvePieces.h; edges not listed count as
/// scale 1), unit tangents where both are curved, nothing where one is straight.
/// `earCorners`: the chains turn at the vertices of ears (the curver's corner
/// angle bound on: BoundaryEars.h), which are then no joints.
JointContinuity MeasureJointContinuity(const SimplexMesh& linear, const CurvedMesh& curved,
  const Box2& border, Smoothness smoothness, const std::vector<CurvePiece>& pieces = {}, bool earCorners = false);

} // namespace testing
} // namespace labelmesher

#endif
