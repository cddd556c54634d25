// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_testing_VoxelMeshes_h
#define labelmesher_testing_VoxelMeshes_h

/**
 * @file VoxelMeshes.h
 * Reference meshes for testing the checks: every voxel of a label image as a
 * cube of six Kuhn tetrahedra (two triangles per pixel in 2D), whose boundary
 * is the image boundary exactly, and random voxel-noise label images.
 */

#include "Support/LabelImage.h"
#include "Mesh/SimplexMesh.h"

#include <random>

namespace labelmesher
{
namespace testing
{

/// Six times the signed volume of tetrahedron (a, b, c, d).
double Det(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// Every voxel as 6 Kuhn tetrahedra (a pixel as 2 triangles in 2D), material =
/// label; background voxels only if withBackground; all points moved by shift.
SimplexMesh VoxelMesh(const LabelImage& image, bool withBackground = false, Point3 shift = { 0, 0, 0 });

/// Independent voxels: non-zero (1..labels) with probability fillPercent %.
LabelImage RandomImage(std::mt19937& rng, int nx, int ny, int nz, int labels, int fillPercent);

} // namespace testing
} // namespace labelmesher

#endif
