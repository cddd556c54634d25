// SPDX-License-Identifier: GPL-2.0-or-later
// Runs the mesher on one image and checks every guarantee of the initial mesh.
#include "MesherGuarantees.h"

#include "MeshGuarantees.h"
#include "RandomLabelImages.h"

#include <exception>

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
  MesherResult result;
  try
  {
    result = MeshLabelImage(image, parameters);
  }
  catch (const std::exception& e)
  {
    return { std::string("the mesher threw: ") + e.what() };
  }
  const double bound = image.Dimension() == 3 ? kProvenDihedralBound : kProvenPlanarBound;
  return ViolatedGuarantees(
    image, result.Mesh, bound, parameters.ImageToMeshDistance, parameters.MeshToImageDistance);
}

} // namespace testing
} // namespace labelmesher
