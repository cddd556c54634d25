// SPDX-License-Identifier: GPL-2.0-or-later
// Measures the guarantees of one mesh with the independent checks and lists what fails.
#include "MeshGuarantees.h"

#include "Checks/MeshChecks.h"

#include <sstream>

namespace labelmesher
{
namespace testing
{

std::vector<std::string> ViolatedGuarantees(const LabelImage& image, const SimplexMesh& mesh, double angleBound,
  double imageToMesh, double meshToImage)
{
  if (mesh.NumberOfCells() == 0)
    return { "the mesh has no cells" };
  std::vector<std::string> problems;
  std::ostringstream line;
  const QualityReport quality = MeasureQuality(mesh);
  if (quality.MinimumAngle < angleBound - 1e-9)
  {
    line << "minimum angle " << quality.MinimumAngle << " below the bound " << angleBound;
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

  if (!WithinHausdorff(image, mesh, imageToMesh, meshToImage))
  {
    const HausdorffReport measured = MeasureHausdorff(image, mesh);
    line << "Hausdorff bound exceeded: overall h(I,M) " << measured.Overall.ImageToMesh << ", h(M,I) "
         << measured.Overall.MeshToImage;
    for (const auto& [label, d] : measured.PerMaterial)
      if (d.ImageToMesh > imageToMesh + 1e-9 || d.MeshToImage > meshToImage + 1e-9)
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
