// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CurvePieces_h
#define labelmesher_CurvePieces_h

/**
 * @file CurvePieces.h
 * The curved pieces of a mesh's interfaces: one per interface edge, its two
 * inner control points as the smoothing or the fit made them, and a scale
 * that the curver may shorten to keep a bound (CurveFidelity.h) or validity.
 * At scale s > 0 the handles are s times the fitted ones (P_0 + s (F_1 − P_0),
 * P_3 + s (F_2 − P_3)): the end tangents keep their directions, so the joints
 * stay G1 (tangent continuous) while both pieces at a joint are curved at all,
 * and C1 (C2) holds where neither was shortened. At s = 0 the piece is
 * straight with its control points at the thirds (a straight edge whose end
 * derivatives do not vanish, so that its cells stay provably valid).
 * A quadratic piece (CurvingParameters::Order 2, QuadraticForm.h) scales its one
 * control point towards the chord's midpoint instead, m + s (q − m): the piece
 * stays a quadratic at every scale, and at s = 0 it is the same straight edge;
 * quadratic pieces meet with G0 only, so none of the continuity above applies.
 */

#include "Curving/CubicTriangle.h"
#include "Mesh/SimplexMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

struct CurvePiece
{
  std::int64_t From = 0; ///< mesh vertex ids; the control points are ordered from From to To
  std::int64_t To = 0;
  std::array<std::int64_t, 2> ControlIds{ 0, 0 }; ///< ids in the CurvedMesh
  std::array<Point2, 2> Fitted;                     ///< inner control points at scale 1 (mesh coordinates)
  std::int32_t Left = 0;  ///< material on the left of From → To
  std::int32_t Right = 0; ///< material on the right
  double Scale = 1.0;
  /// Fitted is an elevated quadratic, and scales as one (see above).
  bool Quadratic = false;

  /// The four control points at the current scale, From first.
  std::array<Point2, 4> ControlPoints(const SimplexMesh& linear) const;
};

/// Halves a piece's scale, then makes it straight: 1, 1/2, 1/4, 0.
/// Returns false when the piece was straight already.
bool ShortenPiece(CurvePiece& piece);

/// The polyline of a cubic whose points are within `epsilon` of the curve and
/// the other way round (Hausdorff distance at most epsilon): de Casteljau halves
/// until both inner control points lie within epsilon of their chord, so that
/// the convex hull, and with it the piece of curve, does. Ends included.
std::vector<Point2> FlattenCubic(const std::array<Point2, 4>& controlPoints, double epsilon);

} // namespace labelmesher

#endif
