// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BezierCurver_h
#define labelmesher_BezierCurver_h

/**
 * @file BezierCurver.h
 * The 2D curvilinear mesher of dissertation chapter 4 as one free function: a
 * linear labelled triangle mesh in, a mesh of cubic Bézier triangles out whose
 * material interfaces are C1 or C2 smooth Bézier paths through the linear
 * mesh's boundary vertices (section 4.1), whose interior control points are
 * placed by iterative linear elasticity (section 4.3), and whose every cell's
 * Jacobian is bounded from below by Bézier subdivision (section 4.2). Cells
 * with two edges on one smooth chain are split first (BoundaryEars.h), unless
 * corner angles are bounded (CurvingParameters::MinimumCornerAngle).
 *
 * With the image (CurvingParameters::Image), C1 curves are fitted to it
 * (BoundaryFit.h), and with distance bounds the curves keep both of them and
 * are proven not to cross or loop (CurveFidelity.h, CurveCrossings.h): pieces
 * that fail are shortened (CurvePieces.h). Cells that untangling leaves
 * invalid get the curves around them shortened and untangling runs again, up
 * to MaximumShorteningRounds rounds.
 */

#include "Curving/BoundaryEars.h"
#include "Curving/BoundaryFit.h"
#include "Curving/CornerHandles.h"
#include "Curving/CurveFidelity.h"
#include "Curving/CurvePieces.h"
#include "Curving/CurvedMesh.h"
#include "Curving/ElasticUntangler.h"
#include "Curving/InterfaceChains.h"
#include "Curving/JacobianBound.h"
#include "Curving/QuadraticForm.h"
#include "Support/ProgressObserver.h"
#include "Support/StageClock.h"
#include "Mesh/SimplexMesh.h"
#include "Curving/SmoothBoundary.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace labelmesher
{

struct CurvingParameters
{
  SmoothingOptions Smoothing;
  UntanglingOptions Untangling;
  /// Edges on this box's sides stay straight and end interface chains (the
  /// image border). Unset: no border, every interface is curved.
  bool HasBorder = false;
  Box2 Border{ 0.0, 0.0, 0.0, 0.0 };
  /// The image the mesh came from (optional). With it, C1 interfaces are
  /// fitted to the image's boundary (BoundaryFit.h).
  ImageOnMesh Image;
  /// Pixel edges farther than this from every segment of their materials are
  /// not fitted (voxels).
  double SampleReach = 3.0;
  /// Weight of the pull towards Figure 17a's handles (dimensionless, >= 0).
  double FitRegularisation = 0.05;
  /// With an image: the distance bounds the curves keep (voxels; both must be
  /// >= 0 to be enforced), and the polyline tolerance that certifies them.
  CurveBounds Bounds{ -1.0, -1.0, 1.0 / 256.0 };
  /// Most untangling rounds, each after shortening the pieces of the cells the
  /// previous one left invalid (or below MinimumScaledJacobian or MinimumCornerAngle);
  /// then, once untangling has made the mesh valid, up to 8 more that straighten
  /// those pieces at once, and if cells still fail, every curve is made straight
  /// (the linear mesh's cells are valid). A mesh no round made valid is returned
  /// with Valid false and its cells listed.
  int MaximumShorteningRounds = 8;
  /// Every cell's scaled Jacobian, min det J / max det J certified by the Bernstein coefficients
  /// of det J with subdivision (JacobianBounds::ScaledJacobian, a lower bound of the true ratio),
  /// at least this, in [0, 1): cells below it get the curves around them shortened like invalid
  /// ones, and when the rounds run out with cells still below it, every curve is made straight
  /// (the linear mesh's cells have ratio 1). 0: validity (det J > 0) only.
  double MinimumScaledJacobian = 0.0;
  /// Every corner of every curved cell, the angle between the tangents of its two edges there
  /// (SmallestCornerAngle), at least this, in degrees [0, 180): the linear mesh's own bound, which
  /// curving would otherwise lower (a curve leaves a vertex along its tangent, not its chord).
  /// Cells below it get the curves around them shortened like invalid ones, and when the rounds
  /// run out with cells still below it, every curve is made straight. The bound kept is the
  /// smaller of this and the linear mesh's smallest angle (CurvingResult::CornerAngleBound): a
  /// straight cell's corners are its angles. When it is above 0, ears are not split (a split
  /// halves angles of the linear mesh); the chains turn at them instead (EarVertices). 0: corner
  /// angles are measured only, and ears are split (BoundaryEars.h).
  double MinimumCornerAngle = 0.0;
  /// 3: cubic Bézier triangles. 2: every cell is exactly a quadratic triangle (6 nodes), held in
  /// the cubic form the proofs work on (QuadraticForm.h): each fitted curve is replaced by its
  /// nearest quadratic, refitted on its own (BoundaryFit.h), shortened as one (CurvePieces.h),
  /// pulled towards its chord where a corner needs it instead of having its handles turned
  /// (CornerHandles.h), and what untangling moves is brought back to quadratics before every
  /// certificate.
  int Order = 3;
};

struct CurvingResult
{
  /// The linear mesh that was curved: the input with its boundary ears split
  /// (BoundaryEars.h); same geometry, possibly more cells.
  SimplexMesh Linear;
  std::size_t SplitEars = 0;
  /// With a corner angle bound: the vertices where a chain turns instead of passing smoothly, the
  /// apexes of ears (BoundaryEars.h), which are then not split.
  std::size_t EarCorners = 0;
  /// With a corner angle bound and C1 curves: chain vertices whose handles were turned towards
  /// their chords to keep it (CornerHandles.h); with Order 2, quadratic pieces pulled towards
  /// their chords for it.
  std::size_t HandlesTurnedForCorners = 0;
  CurvedMesh Mesh;
  /// Per cell: proven lower and upper bounds of det J (same order as Mesh.Cells).
  std::vector<JacobianBounds> CellBounds;
  /// True when every cell is proven valid (det J > 0 everywhere).
  bool Valid = false;
  std::vector<std::size_t> InvalidCells;
  /// Cells with a non-positive Jacobian somewhere (or undecided) once the curved
  /// boundary is in place and before untangling (interior edges straight).
  std::size_t InvalidBeforeUntangling = 0;
  int UntanglingSteps = 0;
  std::size_t NumberOfChains = 0;
  std::size_t NumberOfClosedChains = 0;
  std::size_t NumberOfCurvedEdges = 0;
  /// The interface pieces at their final scales (CurvePieces.h).
  std::vector<CurvePiece> Pieces;
  /// Pieces left below scale 1, and of those the straight ones.
  std::size_t ShortenedPieces = 0;
  std::size_t StraightenedPieces = 0;
  /// Pieces shortened at least once to keep a distance bound, and to let untangling succeed.
  std::size_t PiecesShortenedForBounds = 0;
  std::size_t PiecesShortenedForValidity = 0;
  /// Straight pieces the distance test could not certify (expected 0).
  std::size_t UncertifiedPieces = 0;
  int UntanglingRounds = 0;
  /// Cells whose certified scaled Jacobian stayed below MinimumScaledJacobian after the rounds
  /// (before every curve was made straight for them), and whether that happened.
  std::size_t CellsBelowScaledJacobian = 0;
  bool StraightenedForScaledJacobian = false;
  /// The corner angle bound kept (degrees): MinimumCornerAngle, or the linear mesh's smallest
  /// angle when that is smaller; 0 when none was asked. Cells below it after the rounds (before
  /// every curve was made straight for them), and whether that happened.
  double CornerAngleBound = 0.0;
  std::size_t CellsBelowCornerAngle = 0;
  bool StraightenedForCornerAngle = false;
  /// Every curve made straight because the rounds left cells invalid after untangling had made
  /// the mesh valid in an earlier round (the linear mesh's cells are valid).
  bool StraightenedForValidity = false;
  std::vector<StageTiming> Timings;
};

/// Curves `linear` (Dimension 2, counter-clockwise triangles in the x-y plane).
/// Throws std::invalid_argument for bad input (not 2D, no cells, inverted or
/// degenerate triangles, an order other than 2 or 3) and AbortRequested when `observer` says stop. An
/// untangling failure is not an exception: Valid is false and InvalidCells
/// lists the cells, so that callers can report and mark them.
CurvingResult CurveMesh(const SimplexMesh& linear, const CurvingParameters& parameters,
  const ProgressObserver& observer = {});

} // namespace labelmesher

#endif
