// SPDX-License-Identifier: GPL-2.0-or-later
#include "MesherGuarantees.h"

#include "Checks/MeshChecks.h"
#include "RandomLabelImages.h"

#include <exception>
#include <sstream>

namespace labelmesher
{
namespace testing
{

MesherParameters DrawDistanceBounds(std::uint64_t seed)
{
  SeededRandom draw(seed ^ 0x9e3779b97f4a7c15ull);
  MesherParameters parameters;
  parameters.ImageToMeshDistance = static_cast<double>(draw.Int(0, 3));
  parameters.MeshToImageDistance = static_cast<double>(draw.Int(0, 3));
  return parameters;
}

std::vector<std::string> ViolatedMesherGuarantees(const LabelImage& image, const MesherParameters& parameters)
{
  std::vector<std::string> problems;
  MesherResult result;
  try
  {
    result = MeshLabelImage(image, parameters);
  }
  catch (const std::exception& e)
  {
    return { std::string("the mesher threw: ") + e.what() };
  }
  const SimplexMesh& mesh = result.Mesh;
  if (mesh.NumberOfCells() == 0)
    return { "the mesh has no cells" };

  std::ostringstream line;
  const QualityReport quality = MeasureQuality(mesh);
  const double bound = image.Dimension() == 3 ? kProvenDihedralBound : kProvenPlanarBound;
  if (quality.MinimumAngle < bound - 1e-9)
  {
    line << "minimum angle " << quality.MinimumAngle << " below the proven " << bound;
    problems.push_back(line.str());
    line.str("");
  }
  if (quality.InvertedCells != 0)
    problems.push_back(std::to_string(quality.InvertedCells) + " inverted cells");

  const ConformityReport conformity = MeasureConformity(mesh);
  if (!conformity.Conforming())
  {
    line << "not conforming: over-shared " << conformity.OverSharedFaces << ", hanging "
         << conformity.HangingVertices << ", non-manifold boundary " << conformity.NonManifoldBoundaryEdges;
    problems.push_back(line.str());
    line.str("");
  }

  if (!WithinHausdorff(image, mesh, parameters.ImageToMeshDistance, parameters.MeshToImageDistance))
  {
    const HausdorffReport measured = MeasureHausdorff(image, mesh);
    line << "Hausdorff bound exceeded: overall h(I,M) " << measured.Overall.ImageToMesh << ", h(M,I) "
         << measured.Overall.MeshToImage;
    for (const auto& [label, d] : measured.PerMaterial)
      if (d.ImageToMesh > parameters.ImageToMeshDistance + 1e-9 || d.MeshToImage > parameters.MeshToImageDistance + 1e-9)
        line << "; material " << label << " h(I,M) " << d.ImageToMesh << ", h(M,I) " << d.MeshToImage;
    problems.push_back(line.str());
    line.str("");
  }

  for (const auto& [label, topology] : CompareTopology(image, mesh))
    if (!topology.Matches())
    {
      line << "material " << label << ": image " << topology.Image.Components << " components, chi "
           << topology.Image.EulerCharacteristic << "; mesh " << topology.Mesh.Components << " components, chi "
           << topology.Mesh.EulerCharacteristic;
      problems.push_back(line.str());
      line.str("");
    }
  return problems;
}

} // namespace testing
} // namespace labelmesher
