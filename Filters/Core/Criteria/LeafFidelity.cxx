// SPDX-License-Identifier: GPL-2.0-or-later
// The two-sided Hausdorff test of a proper boundary leaf's patch (section 3.1.1).
#include "Criteria/LeafFidelity.h"

#include "Fill/LeafSurfacePatch.h"
#include "Octree/LatticeLabels.h"
#include "Octree/LeafFaces.h"

namespace labelmesher
{
namespace
{

/// The face of voxel `centre` at half a voxel along `axis` in direction
/// `step` (a pixel edge in 2D).
ConvexPiece VoxelFace(int dimension, Point3 centre, int axis, int step)
{
  centre[axis] += 0.5 * step;
  if (dimension == 2)
  {
    Point3 a = centre, b = centre;
    a[1 - axis] -= 0.5;
    b[1 - axis] += 0.5;
    return ConvexPiece{ 2, { a, b } };
  }
  const auto others = OtherAxes(axis);
  ConvexPiece square{ 4, {} };
  const int order[4][2] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } };
  for (int c = 0; c < 4; ++c)
  {
    Point3 p = centre;
    p[others[0]] += 0.5 * order[c][0];
    p[others[1]] += 0.5 * order[c][1];
    square.Points[c] = p;
  }
  return square;
}

} // namespace

LeafImageBoundary ImageBoundaryInLeaf(const LabelImage& image, const LeafBox& leaf, std::int32_t first,
  std::int32_t second)
{
  LeafImageBoundary boundary;
  ForEachBoundaryFaceInLeaf(image, leaf,
    [&](const std::array<int, 3>& voxel, int axis, int step, std::int32_t here, std::int32_t there) {
      const Point3 centre{ double(leaf.Origin[0] + voxel[0]), double(leaf.Origin[1] + voxel[1]),
        double(leaf.Origin[2] + voxel[2]) };
      const ConvexPiece face = VoxelFace(leaf.Dimension, centre, axis, step);
      boundary.All.push_back(face);
      if ((here == first && there == second) || (here == second && there == first))
        boundary.Interface.push_back(face);
    });
  return boundary;
}

bool SatisfiesFidelity(const LabelImage& image, const LeafBox& leaf, std::int32_t first, std::int32_t second,
  double imageToMesh, double meshToImage)
{
  const std::vector<ConvexPiece> patch = ConeSurfacePatch(leaf, LeafCornerSigns(image, leaf, first, second));
  if (patch.empty())
    return false;
  const LeafImageBoundary boundary = ImageBoundaryInLeaf(image, leaf, first, second);
  for (const ConvexPiece& piece : patch)
    if (!WithinDistance(piece, boundary.Interface, meshToImage))
      return false;
  for (const ConvexPiece& piece : boundary.All)
    if (!WithinDistance(piece, patch, imageToMesh))
      return false;
  return true;
}

} // namespace labelmesher
