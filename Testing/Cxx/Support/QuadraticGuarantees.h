// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_QuadraticGuarantees_h
#define labelmesher_testing_QuadraticGuarantees_h

/**
 * @file QuadraticGuarantees.h
 * Every guarantee of the quadratic 3D mesh on one image, through the pipeline
 * of `labelmesher mesh --order 2`: mesher, decimator, quadratic curver with
 * the image and the mesher's distance bounds. Asserted independently of the
 * curver's certificates (Checks/QuadraticVolume.h): det J sampled on a dense
 * barycentric lattice of every cell (positive, and its min over max at least
 * the bound); every corner's angles (tangents from points of the map) at
 * least the decimator's angle; both distance bounds per material on the boundary faces
 * flattened at step 1/8 (allowing that flattening's stated tolerance and the
 * measure's resolution); the image's topology per material and conformity on
 * the cells refined into linear ones.
 * Shared by the property test and labelmesher_property_scan --order2.
 */

#include "Decimation/MeshDecimator.h"
#include "LabelOctreeMesher.h"
#include "Quadratic/QuadraticCurver.h"

#include <cstdint>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

struct QuadraticRun
{
  QuadraticResult Result;
  /// The angle the corners must keep, degrees (the decimator's; ViolatedQuadraticGuarantees sets
  /// it): asserted as the smaller of it and the linear mesh's smallest dihedral angle.
  double CornerAngle = 15.0;
  std::size_t MisclassifiedLinear = 0; ///< voxels, of the decimated mesh
  std::size_t MisclassifiedCurved = 0; ///< voxels, of the quadratic mesh refined at step 1/4
};

/// The scaled Jacobian every cell keeps (`labelmesher mesh --order 2`'s default), asserted here.
constexpr double kQuadraticScaledJacobian = 0.1;

/// Runs the pipeline on `image`; one line per violated guarantee (empty: all
/// hold). A thrown exception counts as a violation. `curver` switches
/// certificates off (QuadraticParameters' test switches); the guarantees are
/// asserted whatever it says.
std::vector<std::string> ViolatedQuadraticGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, QuadraticRun* run = nullptr, const QuadraticParameters* curver = nullptr);

/// The same guarantees of an existing quadratic mesh (the pipeline's run
/// without the pipeline): `linear` is the mesh it was curved from.
std::vector<std::string> ViolatedQuadraticMeshGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const SimplexMesh& linear, QuadraticRun& run);

} // namespace testing
} // namespace labelmesher

#endif
