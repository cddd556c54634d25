// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BoundaryFit_h
#define labelmesher_BoundaryFit_h

/**
 * @file BoundaryFit.h
 * A C1 cubic Bézier path through a chain's vertices that follows the image
 * (an extension of section 4.1): the interpolating constructions of Figure 17
 * are fixed by the vertices alone, and on a decimated mesh, whose vertices are
 * few, they are less accurate than the chords (section 5.2.3 measured on the
 * shared images). Here each vertex P_i gets a free handle vector m_i: segment
 * s from P_s to P_e (chord length c_s) has inner control points
 * P_s + c_s m_s and P_e − c_s m_e. The handles at a joint are parallel and
 * proportional to the chords, so the path is C1 in chord-length
 * parametrisation (G1 geometrically), exactly the family of Figure 17a; and
 * the curve is linear in the m_i, so fitting the boundary samples
 * (BoundarySamples.h) is a linear least-squares problem, one per chain. A
 * small Tikhonov term pulls each m_i towards Figure 17a's handle (so that
 * segments without samples keep that shape), parameters are corrected by
 * projecting the samples on the curve (Hoschek), and handles longer than half
 * their chords are shortened along their own direction. Loops and crossings
 * a fit may still make are found by the curver (CurveCrossings.h).
 */

#include "Curving/BoundarySamples.h"
#include "Curving/QuadraticForm.h"
#include "Curving/SmoothBoundary.h"

#include <array>
#include <vector>

namespace labelmesher
{

struct FitOptions
{
  double Tension = 1.0 / 3.0;      ///< the Figure 17a handle the fit is pulled towards (dimensionless)
  double Regularisation = 0.05;    ///< weight of that pull per vertex, relative to one sample
  int ParameterCorrections = 3;    ///< fit / re-project rounds
};

/// Inner control points of each segment, in the order of SmoothChain. With no
/// samples this is SmoothChain's C1 path with the given tension.
std::vector<std::array<Point2, 2>> FitChain(const std::vector<Point2>& vertices, bool closed,
  const std::vector<BoundarySample>& samples, const FitOptions& options);

/// Quadratic segments (CurvingParameters::Order 2), as cubic inner control points (degree
/// elevation, QuadraticForm.h): each segment's one control point q fitted on its own to its
/// samples, least squares on B(t) = (1 - t)^2 a + 2 t (1 - t) q + t^2 b with the same parameter
/// corrections and a pull (Regularisation, on the squared distance q moves: mesh units like the
/// samples' residuals, so the fit does not depend on the spacing) towards the quadratic nearest
/// to `initial`'s cubic segment (the C1 fit of FitChain), and q moved towards the chord's
/// midpoint until both elevated handles are at most half the chord: one control point cannot
/// keep C1 at both ends, so segments meet with G0, and each follows its own samples.
std::vector<std::array<Point2, 2>> FitQuadraticSegments(const std::vector<Point2>& vertices, bool closed,
  const std::vector<BoundarySample>& samples, const std::vector<std::array<Point2, 2>>& initial,
  const FitOptions& options);

} // namespace labelmesher

#endif
