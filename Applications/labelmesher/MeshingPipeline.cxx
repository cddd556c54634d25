// SPDX-License-Identifier: GPL-2.0-or-later
#include "MeshingPipeline.h"

#include "vtkImageData.h"
#include "vtkLabelOctreeMesher.h"
#include "vtkMeshDecimator.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

namespace labelmesher_cli
{
namespace
{
/// A filter stopped on request leaves an empty output (its abort path); a request that came
/// during a stage that cannot stop (measuring) leaves a complete one, which is kept.
bool StoppedOnRequest(vtkAlgorithm* filter, vtkUnstructuredGrid* output)
{
  return filter->GetAbortExecute() != 0 && output->GetNumberOfCells() == 0;
}

template <typename T>
vtkSmartPointer<T> CopyOf(T* data)
{
  auto copy = vtkSmartPointer<T>::New();
  copy->ShallowCopy(data);
  return copy;
}
} // namespace

MeshingOutcome RunMeshingPipeline(vtkImageData* image, const MeshingSettings& settings, const FilterProgress& progress)
{
  MeshingOutcome out;
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetImageToMeshDistance(settings.ImageToMeshDistance);
  mesher->SetMeshToImageDistance(settings.MeshToImageDistance);
  mesher->SetIncludeBackground(settings.Decimate || settings.IncludeBackground);
  mesher->SetMeasureOutput(settings.Measure && !settings.Decimate);
  mesher->SetInputData(image);
  FilterMessages messages = UpdateFilter(mesher, progress);
  out.Warning = messages.Warning;
  if (!messages.Error.empty())
  {
    throw MeshingError(messages.Error);
  }
  if (StoppedOnRequest(mesher, mesher->GetOutput()))
  {
    out.Aborted = true;
    return out;
  }
  if (mesher->GetOutput()->GetNumberOfCells() == 0)
  {
    throw MeshingError(messages.Warning.empty() ? "the mesher produced no cells" : messages.Warning);
  }
  out.Initial = CopyOf(mesher->GetOutput());
  out.Mesh = out.Initial;
  out.Interfaces = CopyOf(mesher->GetBoundaryOutput());
  if (!settings.Decimate)
  {
    return out;
  }

  vtkNew<vtkMeshDecimator> decimator;
  decimator->SetMinimumAngle(settings.MinimumAngle);
  decimator->SetRelocateInteriorVertices(settings.RelocateInteriorVertices);
  decimator->SetIncludeBackground(settings.IncludeBackground);
  decimator->SetMeasureOutput(settings.Measure);
  decimator->SetInputDataObject(0, out.Initial);
  decimator->SetInputDataObject(1, image);
  messages = UpdateFilter(decimator, progress);
  if (out.Warning.empty())
  {
    out.Warning = messages.Warning;
  }
  if (!messages.Error.empty())
  {
    throw MeshingError(messages.Error);
  }
  if (StoppedOnRequest(decimator, decimator->GetOutput()))
  {
    out = MeshingOutcome{};
    out.Aborted = true;
    return out;
  }
  if (decimator->GetOutput()->GetNumberOfCells() == 0)
  {
    throw MeshingError(messages.Warning.empty() ? "the decimator produced no cells" : messages.Warning);
  }
  out.Mesh = CopyOf(decimator->GetOutput());
  out.Interfaces = CopyOf(decimator->GetBoundaryOutput());
  return out;
}

} // namespace labelmesher_cli
