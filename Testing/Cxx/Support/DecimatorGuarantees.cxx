// SPDX-License-Identifier: GPL-2.0-or-later
// Runs mesher and decimator on one image and checks every guarantee of the decimated mesh.
#include "DecimatorGuarantees.h"

#include "MeshGuarantees.h"
#include "RandomLabelImages.h"

#include <exception>

namespace labelmesher
{
namespace testing
{

DecimationParameters DrawDecimationParameters(std::uint64_t seed, int dimension, const MesherParameters& mesher)
{
  SeededRandom draw(seed ^ 0x5851f42d4c957f2dull);
  const double angles[] = { 5.0, 10.0, 15.0, 19.47, ProvenAngleBound(dimension) };
  DecimationParameters parameters;
  parameters.MinimumAngle = angles[draw.Int(0, 4)];
  parameters.ImageToMeshDistance = mesher.ImageToMeshDistance;
  parameters.MeshToImageDistance = mesher.MeshToImageDistance;
  return parameters;
}

std::vector<std::string> ViolatedDecimatorGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, DecimationCounts* counts)
{
  DecimationResult result;
  try
  {
    result = DecimateMesh(image, MeshLabelImage(image, mesher).Mesh, decimation);
  }
  catch (const std::exception& e)
  {
    return { std::string("mesher or decimator threw: ") + e.what() };
  }
  if (counts)
    *counts = result.Counts;
  return ViolatedGuarantees(
    image, result.Mesh, decimation.MinimumAngle, decimation.ImageToMeshDistance, decimation.MeshToImageDistance);
}

std::vector<std::string> ViolatedStreamedGuarantees(const LabelImage& image, const MesherParameters& mesher,
  const DecimationParameters& decimation, const StreamingParameters& streaming, DecimationCounts* counts,
  StreamingCounts* streamed)
{
  StreamedResult result;
  try
  {
    result = MeshAndDecimate(image, mesher, decimation, streaming);
  }
  catch (const std::exception& e)
  {
    return { std::string("streamed pipeline threw: ") + e.what() };
  }
  if (counts)
    *counts = result.Decimated.Counts;
  if (streamed)
    *streamed = result.Streaming;
  return ViolatedGuarantees(image, result.Decimated.Mesh, decimation.MinimumAngle, decimation.ImageToMeshDistance,
    decimation.MeshToImageDistance);
}

} // namespace testing
} // namespace labelmesher
