// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_ThinFeatureImages_h
#define labelmesher_testing_ThinFeatureImages_h

/**
 * @file ThinFeatureImages.h
 * Seeded images aimed at the shapes that found the last guarantee bugs, which
 * the smooth and box generators reach only once in thousands of images:
 *  - a thin feature (a one-voxel plate, line or single voxel) one voxel away
 *    from another piece, of the same label or of another one, the gap being
 *    background or a one-voxel layer of a third label;
 *  - pieces whose faces lie on the sides of octree leaves (multiples of 2, 4
 *    or 8 voxels) or one voxel beyond them, so that a piece touches a leaf side
 *    from outside;
 *  - pieces that touch another only along an edge or at a corner.
 * Seeded like RandomLabelImages.h (SeededRandom); the description names every
 * piece in painting order.
 */

#include "RandomLabelImages.h"

#include <cstdint>

namespace labelmesher
{
namespace testing
{

/// A `size`-voxel square (2D) or cube (3D) of such pieces over background; labels from
/// {1, 2, 3, 5}; never all background.
RandomLabelImage GenerateThinFeatureImage(std::uint64_t seed, int dimension, int size);

} // namespace testing
} // namespace labelmesher

#endif
