// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QuadraticCurver_h
#define labelmesher_QuadraticCurver_h

/**
 * @file QuadraticCurver.h
 * A decimated tetrahedral mesh made quadratic, its material interfaces fitted
 * to the image: the 3D curvilinear meshing the dissertation leaves as future
 * work (chapter 5: a linear mesh first, then straight-sided to curved).
 *
 * Edges on the box and junction curves stay straight; the mid-nodes of the
 * other interface edges are fitted (InterfaceFit.h). Then, until nothing
 * fails, a round moves the interior mid-nodes near the curves to the elastic
 * equilibrium of the control nets (InteriorUntangler.h) and certifies
 *   - validity and quality: every curved cell's min det J / max det J at least
 *     MinimumScaledJacobian, by the Bernstein coefficients of det J
 *     (TetraJacobian.h; 0 asks for det J > 0 alone);
 *   - corners: every corner's dihedral angles at least the linear mesh's angle
 *     bound (QuadraticCorners.h);
 *   - both distance bounds on every curved interface face (QuadraticFidelity.h);
 * and the curved interface edges of each failing face and cell (of a failing
 * corner: those through it) are pulled back towards straight (offset × 1/2,
 * 1/4, then 0; for a corner alone by the largest of 0.9, 0.8, ..., 0 under
 * which it holds, straight below 1/20 of the fit); a failing cell with no curved interface edge of its own gets
 * its interior edges pinned straight (a corner: those through it). Straight
 * cells are the linear mesh's, which holds every bound, so the loop ends, at
 * the latest with the linear mesh.
 *
 * Why interfaces cannot cross or touch, and topology is kept: the curved mesh
 * is the image of the linear mesh under a continuous map (neighbours share the
 * nodes of their common face) that is locally injective (det J > 0 in every
 * closed cell) and the identity on the box's boundary (box faces stay flat and
 * box edges straight). Such a map of a ball onto itself is a homeomorphism
 * (a local homeomorphism that is injective on the boundary of a compact,
 * simply connected domain is injective: Meisters & Olech, Duke Math. J. 30,
 * 1963), so every material region is the homeomorphic image of its linear one.
 * This needs the whole box meshed: background cells are curved and certified
 * with the rest.
 */

#include "Quadratic/InterfaceFit.h"
#include "Quadratic/QuadraticFidelity.h"
#include "Quadratic/QuadraticMesh.h"
#include "Support/LabelImage.h"
#include "Support/ProgressObserver.h"

#include <cstddef>
#include <vector>

namespace labelmesher
{

struct QuadraticParameters
{
  double ImageToMeshDistance = 2.0; ///< h(I, M) the curved interfaces keep, voxels
  double MeshToImageDistance = 2.0; ///< h(M, I), voxels
  double MinimumScaledJacobian = 0.1; ///< certified min det J / max det J of every cell, [0, 1)
  /// Every corner of every curved cell keeps this angle (degrees, the dihedral angles of its
  /// tangent trihedron, QuadraticCorners.h), or the linear mesh's smallest dihedral angle when
  /// that is smaller (QuadraticResult::CornerAngleBound); 0: no corner bound. The linear
  /// mesh's own bound is the natural value (vtkLabelMesher passes its MinimumAngle).
  double MinimumCornerAngle = 15.0;
  double Tolerance = 1.0 / 64.0; ///< flattening tolerance of the distance test, voxels
  InterfaceFitOptions Fit;
  bool Untangle = true; ///< move interior mid-nodes by elasticity (off: interior edges stay straight)
  /// For tests only: switch a certificate off to show that the checks catch what it prevents.
  bool CertifyValidity = true;
  bool CertifyDistances = true;
  bool CertifyCorners = true;
};

struct QuadraticResult
{
  QuadraticMesh Mesh;
  std::vector<double> ScaledJacobian; ///< per cell, certified lower bound (1: straight)
  std::vector<double> CornerAngle;    ///< per cell, its smallest corner angle, degrees (straight: its dihedral)
  /// The corner angle every cell keeps: MinimumCornerAngle, or the linear mesh's smallest dihedral
  /// angle when that is smaller; 0 with the bound off.
  double CornerAngleBound = 0.0;
  std::size_t FittedEdges = 0;      ///< interface edges given a fitted mid-node
  std::size_t CurvedEdges = 0;      ///< still curved at the end
  std::size_t ShortenedEdges = 0;   ///< pulled back at least once
  std::size_t StraightenedEdges = 0; ///< pulled back to straight
  std::size_t UntangledEdges = 0;   ///< interior edges moved by the last untangling
  std::size_t PinnedEdges = 0;      ///< interior edges pinned straight
  std::size_t Rounds = 0;
  std::size_t CellsFailedQuality = 0;  ///< cells that failed the Jacobian bound in some round
  std::size_t FacesFailedDistance = 0; ///< faces that failed a distance bound in some round
  std::size_t CellsFailedCornerAngle = 0; ///< cells with a corner below the bound in some round
  double FitSeconds = 0.0, CertifySeconds = 0.0;
  /// Between the two stages: the linear mesh's interface faces and curvable edges, which the fit
  /// finds and the certification takes over (and releases); found again when absent. A caller
  /// that changes Mesh.Linear or the image between the stages must clear them.
  std::vector<MaterialFace> Faces;
  std::vector<char> Curvable;
};

/// `linear`: the whole decimated mesh (every cell of the box, background
/// included), index space, positively oriented tetrahedra; `image` the label
/// image it was made from; its bounds at least as tight as the parameters'
/// (straight faces are not tested again). FitQuadraticMesh then
/// CertifyQuadraticMesh.
/// `observer` sees the stages ("quadratic fit", "quadratic certify": the
/// fraction of curved faces still moving) and may stop the run (AbortRequested
/// is thrown, nothing is returned).
QuadraticResult CurveQuadratic(SimplexMesh linear, const LabelImage& image, const QuadraticParameters& parameters,
  const ProgressObserver& observer = {});

/// The first stage: edges numbered, interface mid-nodes fitted (uncertified).
QuadraticResult FitQuadraticMesh(SimplexMesh linear, const LabelImage& image, const QuadraticParameters& parameters);

/// The second: certifies every cell and face and pulls back what fails, until
/// all hold, whatever the offsets (a fit's, or any other, with Scales in
/// [0, 1]).
void CertifyQuadraticMesh(QuadraticResult& result, const LabelImage& image, const QuadraticParameters& parameters,
  const ProgressObserver& observer = {});

} // namespace labelmesher

#endif
