// SPDX-License-Identifier: GPL-2.0-or-later
#include "MeshingPipeline.h"

#include "vtkBezierCurver.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkLabelMesher.h"
#include "vtkLabelOctreeMesher.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

namespace labelmesher_cli
{
namespace
{
/// What a filter's error means: the stage failed, or (the curver's untangling) the output is a
/// marked mesh kept with the error.
enum class OnError
{
  Throw,
  KeepOutput
};

/// What every stage does once its filter ran: keeps the run's first warning, turns the filter's
/// error into a MeshingError (OnError::Throw) and refuses an output without cells. Returns false
/// when the filter stopped on request, which leaves an empty output (its abort path); `out` then
/// becomes an aborted outcome. A request during a stage that cannot stop (measuring) leaves a
/// complete output, which is kept.
bool FinishStage(vtkAlgorithm* filter, vtkUnstructuredGrid* output, const FilterMessages& messages,
  const char* name, OnError onError, MeshingOutcome& out)
{
  if (out.Warning.empty())
  {
    out.Warning = messages.Warning;
  }
  if (!messages.Error.empty() && onError == OnError::Throw)
  {
    throw MeshingError(messages.Error);
  }
  if (filter->GetAbortExecute() != 0 && output->GetNumberOfCells() == 0)
  {
    out = MeshingOutcome{};
    out.Aborted = true;
    return false;
  }
  if (output->GetNumberOfCells() == 0)
  {
    throw MeshingError(!messages.Error.empty() ? messages.Error
        : !messages.Warning.empty()            ? messages.Warning
                                               : std::string("the ") + name + " produced no cells");
  }
  return true;
}

template <typename T>
vtkSmartPointer<T> CopyOf(T* data)
{
  auto copy = vtkSmartPointer<T>::New();
  copy->ShallowCopy(data);
  return copy;
}

/// vtkLabelMesher: mesher and decimator block by block; false when it stopped on request.
bool MeshAndDecimate(
  vtkImageData* image, const MeshingSettings& settings, const FilterProgress& progress, MeshingOutcome& out)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetImageToMeshDistance(settings.ImageToMeshDistance);
  mesher->SetMeshToImageDistance(settings.MeshToImageDistance);
  mesher->SetMinimumAngle(settings.MinimumAngle);
  mesher->SetRelocateInteriorVertices(settings.RelocateInteriorVertices);
  mesher->SetBlockCells(static_cast<vtkIdType>(settings.BlockCells));
  mesher->SetIncludeBackground(settings.IncludeBackground);
  mesher->SetMeasureOutput(settings.Measure);
  mesher->SetMemoryLimit(settings.MemoryLimit);
  mesher->SetInputData(image);
  const FilterMessages messages = UpdateFilter(mesher, progress);
  if (!FinishStage(mesher, mesher->GetOutput(), messages, "mesher", OnError::Throw, out))
  {
    return false;
  }
  out.Mesh = CopyOf(mesher->GetOutput());
  out.Interfaces = CopyOf(mesher->GetInterfacesOutput());
  return true;
}

/// vtkLabelOctreeMesher alone (no decimation); false when it stopped on request. The filter is
/// gone on return, so that its output is held once, by `out`.
bool Mesh(vtkImageData* image, const MeshingSettings& settings, const FilterProgress& progress, MeshingOutcome& out)
{
  vtkNew<vtkLabelOctreeMesher> mesher;
  mesher->SetImageToMeshDistance(settings.ImageToMeshDistance);
  mesher->SetMeshToImageDistance(settings.MeshToImageDistance);
  mesher->SetIncludeBackground(settings.IncludeBackground);
  mesher->SetMeasureOutput(settings.Measure);
  mesher->SetMemoryLimit(settings.MemoryLimit);
  mesher->SetInputData(image);
  const FilterMessages messages = UpdateFilter(mesher, progress);
  if (!FinishStage(mesher, mesher->GetOutput(), messages, "mesher", OnError::Throw, out))
  {
    return false;
  }
  out.Initial = CopyOf(mesher->GetOutput());
  out.Mesh = out.Initial;
  out.Interfaces = CopyOf(mesher->GetInterfacesOutput());
  return true;
}

/// vtkBezierCurver on the final mesh. An untangling failure is an error of the filter that still
/// outputs the marked mesh: it is kept with the error, for the front end to show or write.
void Curve(vtkImageData* image, const MeshingSettings& settings, const FilterProgress& progress, MeshingOutcome& out)
{
  vtkNew<vtkBezierCurver> curver;
  curver->SetSmoothness(settings.Smoothness);
  curver->SetTension(settings.Tension);
  curver->SetMaximumUntanglingSteps(settings.MaximumUntanglingSteps);
  curver->SetMaximumShorteningRounds(settings.MaximumShorteningRounds);
  curver->SetQualityIterations(settings.QualityIterations);
  curver->SetInputDataObject(0, out.Mesh);
  curver->SetInputDataObject(1, image);
  const FilterMessages messages = UpdateFilter(curver, progress);
  if (!FinishStage(curver, curver->GetOutput(), messages, "curver", OnError::KeepOutput, out))
  {
    return;
  }
  out.CurveError = messages.Error;
  out.Curved = CopyOf(curver->GetOutput());
}
} // namespace

bool IsTwoDimensional(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  return dims[0] == 1 || dims[1] == 1 || dims[2] == 1;
}

MeshingOutcome RunMeshingPipeline(vtkImageData* image, const MeshingSettings& settings, const FilterProgress& progress)
{
  if (settings.Curve && !IsTwoDimensional(image))
  {
    throw MeshingError("curving needs a 2D image (one extent of a single slice); this image is 3D");
  }
  MeshingOutcome out;
  if (!(settings.Decimate ? MeshAndDecimate(image, settings, progress, out) : Mesh(image, settings, progress, out)))
  {
    return out;
  }
  if (settings.Curve && !out.Aborted)
  {
    Curve(image, settings, progress, out);
  }
  return out;
}

} // namespace labelmesher_cli
