// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_MeshGuarantees_h
#define labelmesher_testing_MeshGuarantees_h

/**
 * @file MeshGuarantees.h
 * The guarantees a LabelMesher mesh promises, measured on one mesh with the
 * independent checks (Checks/): no angle below a bound and no inverted cell,
 * conformity and a watertight boundary, both one-sided Hausdorff bounds
 * overall and per material, and per material the components and Euler
 * characteristic of the voxel region. The mesher's and the decimator's
 * property tests (MesherGuarantees.h, DecimatorGuarantees.h) both assert them
 * through this one function.
 */

#include "Mesh/SimplexMesh.h"
#include "Support/LabelImage.h"

#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

/// One line per violated guarantee (empty: all hold). `angleBound` in
/// degrees, distances in voxels.
std::vector<std::string> ViolatedGuarantees(const LabelImage& image, const SimplexMesh& mesh, double angleBound,
  double imageToMesh, double meshToImage);

} // namespace testing
} // namespace labelmesher

#endif
