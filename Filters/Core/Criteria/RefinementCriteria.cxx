// SPDX-License-Identifier: GPL-2.0-or-later
// What an octree leaf must satisfy to be kept, in the order Algorithm 2 checks it (section 3.1.1).
#include "Criteria/RefinementCriteria.h"

#include "Criteria/LeafFidelity.h"
#include "Criteria/SingleManifoldCondition.h"
#include "Octree/LatticeLabels.h"

namespace labelmesher
{
namespace
{

int Log2(int size)
{
  int l = 0;
  while ((1 << l) < size)
    ++l;
  return l;
}

} // namespace

RefinementCriteria::RefinementCriteria(
  const LabelImage& image, const LabelPyramid& pyramid, const MesherParameters& parameters)
  : Image(image)
  , Pyramid(pyramid)
  , Parameters(parameters)
{
}

LeafVerdict RefinementCriteria::Judge(const LeafBox& leaf) const
{
  LeafVerdict split;
  split.Refine = true;
  const LabelSummary labels = Pyramid.Block(Log2(leaf.Size), leaf.Origin[0], leaf.Origin[1], leaf.Origin[2]);
  if (labels.HasMoreThanTwo())
    return split;
  if (labels.IsUniform())
    return LeafVerdict{ false, labels.First, labels.First, 0 };
  auto manifold = [&] { return SatisfiesSingleManifoldCondition(Image, leaf, labels.First, labels.Second); };
  auto fidelity = [&] {
    return SatisfiesFidelity(Image, leaf, labels.First, labels.Second, Parameters.ImageToMeshDistance,
      Parameters.MeshToImageDistance);
  };
  // 0.35 s for the manifold test on one leaf of 128^3, milliseconds for a
  // failing fidelity test: the cheaper likely verdict first.
  const bool accepted = leaf.Size >= 8 ? fidelity() && manifold() : manifold() && fidelity();
  if (!accepted)
    return split;
  const CornerSigns signs = LeafCornerSigns(Image, leaf, labels.First, labels.Second);
  return LeafVerdict{ false, labels.First, labels.Second, static_cast<std::uint8_t>(RigidFaces(signs, leaf.Dimension)) };
}

} // namespace labelmesher
