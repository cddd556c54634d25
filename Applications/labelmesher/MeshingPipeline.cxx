// SPDX-License-Identifier: GPL-2.0-or-later
#include "MeshingPipeline.h"

#include "MPIPartExchange.h"

#include "vtkImageData.h"
#include "vtkLabelMesher.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

namespace labelmesher_cli
{
namespace
{
template <typename T>
vtkSmartPointer<T> CopyOf(T* data)
{
  auto copy = vtkSmartPointer<T>::New();
  copy->ShallowCopy(data);
  return copy;
}
} // namespace

vtkLabelMesher* FilterDefaults()
{
  static const vtkNew<vtkLabelMesher> defaults;
  return defaults.GetPointer();
}

bool IsTwoDimensional(vtkImageData* image)
{
  return vtkLabelMesher::GetImageDimension(image) == 2;
}

MeshingOutcome RunMeshingPipeline(
  vtkImageData* image, const MeshingSettings& settings, const FilterProgress& progress, vtkAlgorithm* source)
{
  vtkNew<vtkLabelMesher> mesher;
  mesher->SetDecimate(settings.Decimate);
  mesher->SetImageToMeshDistance(settings.ImageToMeshDistance);
  mesher->SetMeshToImageDistance(settings.MeshToImageDistance);
  mesher->SetMinimumAngle(settings.MinimumAngle);
  mesher->SetRelocateInteriorVertices(settings.RelocateInteriorVertices);
  mesher->SetBlockCells(static_cast<vtkIdType>(settings.BlockCells));
  mesher->SetPartBlocks(static_cast<vtkIdType>(settings.PartBlocks));
  mesher->SetDistributed(settings.Distributed);
  mesher->SetIncludeBackground(settings.IncludeBackground);
  mesher->SetMeasureOutput(settings.Measure);
  mesher->SetMemoryLimit(settings.MemoryLimit);
  mesher->SetCurve(settings.Curve);
  mesher->SetOrder(settings.Order);
  mesher->SetSmoothness(settings.Smoothness);
  mesher->SetTension(settings.Tension);
  mesher->SetMaximumUntanglingSteps(settings.MaximumUntanglingSteps);
  mesher->SetMaximumShorteningRounds(settings.MaximumShorteningRounds);
  mesher->SetQualityIterations(settings.QualityIterations);
  mesher->SetMinimumScaledJacobian(settings.MinimumScaledJacobian);
  if (source)
  {
    mesher->SetInputConnection(source->GetOutputPort());
  }
  else
  {
    mesher->SetInputData(image);
  }
  const FilterMessages messages = UpdateFilter(mesher, progress);

  MeshingOutcome out;
  out.Warning = messages.Warning;
  if (settings.Distributed && labelmesher::WorldRank() != 0)
  {
    if (!messages.Error.empty())
    {
      throw MeshingError(messages.Error); // rank 0 names this process in its own line
    }
    return out; // its parts went to rank 0
  }
  vtkUnstructuredGrid* mesh = mesher->GetOutput();
  vtkUnstructuredGrid* curved = mesher->GetCurvedOutput();
  // A curving whose untangling failed is an error that still outputs the marked mesh: kept with
  // the error, for the front end to show or write.
  // (A 2D image's Order 2 is a curving too, into quadratic triangles.)
  const bool curving = settings.Curve || (settings.Order == 2 && IsTwoDimensional(image));
  const bool markedCurves = curving && curved->GetNumberOfCells() > 0 && mesh->GetNumberOfCells() > 0;
  if (!messages.Error.empty() && !markedCurves)
  {
    throw MeshingError(messages.Error);
  }
  // A stop requested while measuring (which cannot stop) leaves complete outputs, kept.
  if (mesher->GetAbortExecute() != 0 && mesh->GetNumberOfCells() == 0)
  {
    out.Aborted = true;
    return out;
  }
  if (mesh->GetNumberOfCells() == 0)
  {
    throw MeshingError(!messages.Warning.empty() ? messages.Warning : std::string("the mesher produced no cells"));
  }
  out.Mesh = CopyOf(mesh);
  out.Interfaces = CopyOf(mesher->GetInterfacesOutput());
  if (curving)
  {
    out.Curved = CopyOf(curved);
    out.CurveError = messages.Error;
  }
  else if (settings.Order == 2)
  {
    out.Curved = CopyOf(curved);
  }
  return out;
}

} // namespace labelmesher_cli
