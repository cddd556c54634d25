// SPDX-License-Identifier: GPL-2.0-or-later
//
// Algorithm 1 of the dissertation, stage by stage:
//   1. label pyramid: which labels each octree block holds (LabelPyramid)
//   2. octree: refine a p4est forest until every leaf meets the refinement
//      criteria (Criteria/RefinementCriteria.h: at most two labels, the single
//      manifold condition, both fidelity bounds, the neighbour rule) under 2:1
//      balance across faces and edges (Octree/OctreeRefinement.h)
//   3. fill: each leaf becomes cells, labelled as it is made (LeafFill)
//   4. boundary: faces between different materials (MeshBoundary)
//
// Why there is no separate EDT fidelity zone (octree O1 of section 3.1.1): the
// fidelity test here measures both one-sided distances exactly between each
// leaf's surface patch and the image boundary inside the leaf (DistanceBound),
// which is what the zone approximates at voxel centres.

#include "LabelOctreeMesher.h"

#include "Criteria/RefinementCriteria.h"
#include "Fill/LeafFill.h"
#include "Mesh/MeshBoundary.h"
#include "Octree/LabelPyramid.h"
#include "Octree/OctreeRefinement.h"
#include "Support/StageClock.h"

#include <stdexcept>
#include <string>

namespace labelmesher
{
namespace
{

void Validate(const LabelImage& image, const MesherParameters& parameters)
{
  for (int d = 0; d < 3; ++d)
    if (image.Dimensions[d] <= 0)
      throw std::invalid_argument("the image has an empty extent");
  if (image.NumberOfVoxels() != static_cast<std::size_t>(image.Dimensions[0]) * image.Dimensions[1] * image.Dimensions[2])
    throw std::invalid_argument("the label buffer does not match the image dimensions");
  if (!(parameters.ImageToMeshDistance >= 0.0) || !(parameters.MeshToImageDistance >= 0.0))
    throw std::invalid_argument("Hausdorff distance bounds must be non-negative numbers");
  bool negative = false, foreground = false;
  image.WithLabels([&](const auto* labels) {
    for (std::size_t v = 0; v < image.NumberOfVoxels(); ++v)
    {
      negative = negative || labels[v] < 0;
      foreground = foreground || labels[v] != 0;
    }
  });
  if (negative)
    throw std::invalid_argument("the image has negative labels");
  if (!foreground)
    throw std::invalid_argument("the image has no foreground (every label is 0)");
}

} // namespace

MesherOctree RefineOctree(const LabelImage& image, const MesherParameters& parameters,
  const ProgressObserver& observer, StageClock& clock)
{
  Validate(image, parameters);
  MesherOctree octree;
  octree.Depth = OctreeDepth(image);

  if (!observer.Report("label pyramid", 0.0))
    throw AbortRequested{};
  const LabelPyramid pyramid(image, octree.Depth);
  clock.Finish("label pyramid");

  const RefinementCriteria criteria(image, pyramid, parameters);
  const LeafEvaluator evaluate = [&criteria](const LeafBox& leaf) { return criteria.Judge(leaf); };
  octree.Leaves = BuildOctree(image.Dimension(), octree.Depth, evaluate, observer, 0.1, 0.6);
  clock.Finish("octree");
  return octree;
}

MesherResult MeshLabelImage(const LabelImage& image, const MesherParameters& parameters, const ProgressObserver& observer)
{
  MesherResult result;
  StageClock clock(result.Timings);
  const int dimension = image.Dimension();
  const std::vector<OctreeLeaf> leaves = RefineOctree(image, parameters, observer, clock).Leaves;
  result.NumberOfLeaves = leaves.size();

  MeshAssembler assembler(dimension);
  for (std::size_t i = 0; i < leaves.size(); ++i)
  {
    if (i % 65536 == 0 && !observer.Report("fill", 0.6 + 0.3 * double(i) / double(leaves.size())))
      throw AbortRequested{};
    FillLeaf(image, leaves[i], assembler);
  }
  result.Mesh = assembler.Release();
  clock.Finish("fill");

  if (!observer.Report("boundary", 0.9))
    throw AbortRequested{};
  MaterialInterfaces interfaces = ExtractMaterialInterfaces(result.Mesh);
  result.Interfaces = std::move(interfaces.Faces);
  result.InterfaceMaterials = std::move(interfaces.Sides);
  clock.Finish("boundary");
  observer.Report("done", 1.0);
  return result;
}

} // namespace labelmesher
