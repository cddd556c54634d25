// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_InterfaceFit_h
#define labelmesher_InterfaceFit_h

/**
 * @file InterfaceFit.h
 * Mid-nodes of interface edges fitted to the image (the 3D counterpart of the
 * 2D curver's fit, Curving/BoundaryFit.h). Each curvable edge's mid-node
 * moves along the mean normal of its two faces by an offset d; a curved face
 * is then its flat triangle plus Σ 4 l_i l_j d_e n_e over its edges. The
 * offsets are the regularised least-squares solution of one equation per
 * voxel face between the two materials of an interface: the curved face
 * through the voxel face's centre, measured along the face normal at the
 * centre's nearest point. The staircase's faces scatter by half a voxel on
 * both sides of the surface they sample, so the fit lands on their mean, where
 * the linear mesh's flat faces cut chords.
 *
 * Nothing here is a guarantee: the curver certifies validity and distances
 * afterwards and pulls back what fails (QuadraticCurver.h).
 */

#include "Quadratic/InterfaceFaces.h"
#include "Support/LabelImage.h"

#include <cstddef>
#include <vector>

namespace labelmesher
{

struct InterfaceFitOptions
{
  double Reach = 3.0;           ///< voxel faces farther than this from every face of their pair are not fitted, voxels
  double Regularization = 0.1;  ///< weight of d² per edge against the samples' squared residuals (1 each)
  double MaximumOffset = 0.25;  ///< |d| at most this fraction of the edge's length
};

/// Sets Offset and Scales (1) of the curvable edges whose fitted offset is not
/// negligible; returns how many.
std::size_t FitInterfaceMidNodes(QuadraticMesh& mesh, const std::vector<MaterialFace>& faces,
  const std::vector<char>& curvable, const LabelImage& image, const InterfaceFitOptions& options);

} // namespace labelmesher

#endif
