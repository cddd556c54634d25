// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_MesherGuarantees_h
#define labelmesher_testing_MesherGuarantees_h

/**
 * @file MesherGuarantees.h
 * Every guarantee of the initial ORD mesh, checked on one image with the
 * independent measuring code (Checks/): the angle bound that the enumeration
 * proves (TestAngleBoundEnumeration) and no inverted cell, conformity and a
 * watertight boundary, both one-sided Hausdorff bounds overall and per
 * material, and per material the components and Euler characteristic of the
 * voxel region. Shared by the property tests and the long property scan
 * (labelmesher_property_scan), so both assert exactly the same.
 */

#include "Support/LabelImage.h"
#include "LabelOctreeMesher.h"

#include <cstdint>
#include <string>
#include <vector>

namespace labelmesher
{
namespace testing
{

constexpr double kProvenDihedralBound = 30.0; ///< degrees, 3D (TestAngleBoundEnumeration)
constexpr double kProvenPlanarBound = 45.0;   ///< degrees, 2D

/// The distance bounds a property test uses for `seed`: h(I,M) and h(M,I)
/// each drawn from {0, 1, 2, 3} voxels.
MesherParameters DrawDistanceBounds(std::uint64_t seed);

/// Meshes `image` and returns one line per violated guarantee (empty: all
/// hold). A mesher exception is reported as a violation too.
std::vector<std::string> ViolatedMesherGuarantees(const LabelImage& image, const MesherParameters& parameters);

} // namespace testing
} // namespace labelmesher

#endif
