// SPDX-License-Identifier: GPL-2.0-or-later
// vtkLabelOctreeMesher's passes: read the image, run the core mesher, pack the mesh, interfaces and
// field data.
#include "vtkLabelOctreeMesher.h"

#include "FilterSupport.h"
#include "MPIStartup.h"
#include "LabelImageConversion.h"
#include "LabelMesherArrayNames.h"
#include "LabelOctreeMesher.h"
#include "MemoryBudget.h"
#include "Decimation/MeshDecimator.h"
#include "Mesh/MeshSelection.h"
#include "Support/MemoryEstimate.h"

#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkDataSetAttributes.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <exception>
#include <new>
#include <string>
#include <utility>

vtkStandardNewMacro(vtkLabelOctreeMesher);

double vtkLabelOctreeMesher::GetProvenAngleBound(int dimension)
{
  return labelmesher::ProvenAngleBound(dimension);
}

/*
 * Design. RequestData is a sequence of passes, none of which knows the algorithm:
 *   1. convert: validate the label array, convert it to the core's LabelImage
 *               and remember the map back to physical space (LabelImageConversion.h);
 *   2. mesh:    labelmesher::MeshLabelImage, progress and abort forwarded;
 *   3. pack:    the cells of the kept materials (port 0), the interfaces
 *               (port 1), the parameters and timings (field data);
 *   4. measure: the checks of Filters/Core/Checks on the kept cells.
 * Passes 3 and 4 are shared with the decimator (FilterSupport.h).
 */

//------------------------------------------------------------------------------
vtkLabelOctreeMesher::vtkLabelOctreeMesher()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLabelOctreeMesher::GetInterfacesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkLabelOctreeMesher::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLabelOctreeMesher::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkLabelOctreeMesher::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  labelmesher::RequestWholeImages(inputVector[0]);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLabelOctreeMesher::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
  if (!input || !output || !boundary)
  {
    vtkErrorMacro("Missing input image or outputs.");
    return 0;
  }

  labelmesher::ImagePlacement placement;
  labelmesher::LabelImage image;
  std::string error;
  if (!labelmesher::ConvertLabelImage(input, this->GetInputArrayToProcess(0, inputVector), image, placement, error))
  {
    vtkErrorMacro(<< error << ".");
    return 1;
  }

  const labelmesher::MemoryEstimate estimate = labelmesher::EstimateMemory(image, this->CheckMemoryForDecimation);
  const labelmesher::MemoryBudget budget = labelmesher::AvailableMemory(this->MemoryLimit, /*startsMPI=*/true);
  const std::string refusal =
    labelmesher::RefuseIfTooLarge(estimate.RunBytes, labelmesher::DescribeEstimate(estimate), budget);
  if (!refusal.empty())
  {
    vtkErrorMacro(<< refusal << ".");
    return 1;
  }

  const double meshShare = this->MeasureOutput ? 0.8 : 1.0;
  labelmesher::MesherParameters parameters;
  parameters.ImageToMeshDistance = this->ImageToMeshDistance;
  parameters.MeshToImageDistance = this->MeshToImageDistance;
  labelmesher::MesherResult result;
  labelmesher::StartMPI(); // p4est's forest needs MPI; starting it is the application's (MPIStartup.h)
  try
  {
    result = labelmesher::MeshLabelImage(image, parameters, labelmesher::ForwardProgress(this, 0.0, meshShare));
  }
  catch (const labelmesher::AbortRequested&)
  {
    vtkWarningMacro("Meshing aborted on request: output is empty.");
    return 1;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Meshing failed: out of memory (estimated beforehand to need "
      << labelmesher::FormatMiB(estimate.RunBytes) << " more; " << labelmesher::FormatMiB(budget.Bytes)
      << " were available: " << budget.Source << ").");
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Meshing failed: " << e.what());
    return 1;
  }

  const labelmesher::SimplexMesh kept = labelmesher::SelectMaterials(std::move(result.Mesh), this->IncludeBackground);
  labelmesher::PackVolumeMesh(kept, placement, output);
  labelmesher::PackInterfaces(result.Interfaces, result.InterfaceMaterials, placement, boundary);
  this->AddParameters(output->GetFieldData(), placement.VoxelSize, result.NumberOfLeaves);
  labelmesher::AddScalarField(output->GetFieldData(), labelmesher::arrays::EstimatedMemory, static_cast<double>(estimate.RunBytes) / (1 << 20));
  labelmesher::AddScalarField(output->GetFieldData(), labelmesher::arrays::InterfaceFaces, static_cast<double>(estimate.InterfaceFaces));
  this->Measure(output->GetFieldData(), image, kept, meshShare, result.Timings);
  labelmesher::AddStageTimings(output->GetFieldData(), result.Timings);
  labelmesher::PassMaterialTable(input->GetFieldData(), output->GetFieldData());
  labelmesher::PassMaterialTable(input->GetFieldData(), boundary->GetFieldData());
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLabelOctreeMesher::AddParameters(vtkFieldData* fd, double voxelSize, std::size_t leaves) const
{
  namespace arrays = labelmesher::arrays;
  labelmesher::AddScalarField(fd, arrays::ImageToMeshDistance, this->ImageToMeshDistance);
  labelmesher::AddScalarField(fd, arrays::MeshToImageDistance, this->MeshToImageDistance);
  labelmesher::AddScalarField(fd, arrays::IncludeBackground, this->IncludeBackground ? 1.0 : 0.0);
  labelmesher::AddScalarField(fd, arrays::VoxelSize, voxelSize);
  labelmesher::AddScalarField(fd, arrays::NumberOfLeaves, static_cast<double>(leaves));
}

//------------------------------------------------------------------------------
void vtkLabelOctreeMesher::Measure(vtkFieldData* fd, const labelmesher::LabelImage& image,
  const labelmesher::SimplexMesh& kept, double measureStart, std::vector<labelmesher::StageTiming>& timings)
{
  if (!this->MeasureOutput)
  {
    return;
  }
  this->SetProgressText("measure");
  this->UpdateProgress(measureStart);
  try
  {
    labelmesher::AddMeasurements(fd, image, kept, this->ImageToMeshDistance, this->MeshToImageDistance, timings,
      [&](int checksDone) { this->UpdateProgress(measureStart + (1.0 - measureStart) * checksDone / 4.0); });
  }
  catch (const std::exception& e)
  {
    vtkWarningMacro("Measuring the mesh failed: " << e.what());
  }
}

//------------------------------------------------------------------------------
void vtkLabelOctreeMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageToMeshDistance: " << this->ImageToMeshDistance << " voxels\n";
  os << indent << "MeshToImageDistance: " << this->MeshToImageDistance << " voxels\n";
  os << indent << "IncludeBackground: " << (this->IncludeBackground ? "On" : "Off") << "\n";
  os << indent << "MeasureOutput: " << (this->MeasureOutput ? "On" : "Off") << "\n";
}
