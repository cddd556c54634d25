// SPDX-License-Identifier: GPL-2.0-or-later
// vtkLabelMesher's passes: read the image, run the block-streamed core pipeline, pack and measure.
#include "vtkLabelMesher.h"

#include "FilterSupport.h"
#include "MPIStartup.h"
#include "LabelImageConversion.h"
#include "LabelMesherArrayNames.h"
#include "MemoryBudget.h"
#include "Mesh/MeshSelection.h"
#include "Streaming/StreamedPipeline.h"
#include "Support/MemoryEstimate.h"

#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <exception>
#include <new>
#include <string>
#include <utility>

vtkStandardNewMacro(vtkLabelMesher);

/*
 * Design. RequestData is a sequence of passes, none of which knows the algorithm:
 *   1. convert: the label image as the core's LabelImage (LabelImageConversion.h);
 *   2. check:   the streamed run's memory estimate against the budget;
 *   3. run:     labelmesher::MeshAndDecimate, progress and abort forwarded;
 *   4. pack and measure, as the mesher and the decimator (FilterSupport.h).
 */

namespace arrays = labelmesher::arrays;

//------------------------------------------------------------------------------
vtkLabelMesher::vtkLabelMesher()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLabelMesher::GetInterfacesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkLabelMesher::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLabelMesher::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkLabelMesher::RequestUpdateExtent(
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
int vtkLabelMesher::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
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

  const auto blockCells = static_cast<std::uint64_t>(std::max<vtkIdType>(0, this->BlockCells));
  const labelmesher::MemoryEstimate estimate = labelmesher::EstimateStreamedMemory(image, blockCells);
  const labelmesher::MemoryBudget budget = labelmesher::AvailableMemory(this->MemoryLimit, /*startsMPI=*/true);
  const std::string refusal =
    labelmesher::RefuseIfTooLarge(estimate.RunBytes, labelmesher::DescribeEstimate(estimate), budget);
  if (!refusal.empty())
  {
    vtkErrorMacro(<< refusal << ".");
    return 1;
  }

  labelmesher::MesherParameters mesher;
  mesher.ImageToMeshDistance = this->ImageToMeshDistance;
  mesher.MeshToImageDistance = this->MeshToImageDistance;
  labelmesher::DecimationParameters decimation;
  decimation.MinimumAngle = this->MinimumAngle;
  decimation.ImageToMeshDistance = this->ImageToMeshDistance;
  decimation.MeshToImageDistance = this->MeshToImageDistance;
  decimation.RelocateInteriorVertices = this->RelocateInteriorVertices;
  labelmesher::StreamingParameters streaming;
  streaming.BlockCells = blockCells;

  const double share = this->MeasureOutput ? 0.8 : 1.0;
  labelmesher::StreamedResult result;
  labelmesher::StartMPI(); // p4est's forest needs MPI; starting it is the application's (MPIStartup.h)
  try
  {
    result = labelmesher::MeshAndDecimate(image, mesher, decimation, streaming, labelmesher::ForwardProgress(this, 0.0, share));
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
    vtkErrorMacro("Meshing failed: " << e.what() << ".");
    return 1;
  }

  labelmesher::DecimationResult& decimated = result.Decimated;
  const labelmesher::SimplexMesh kept = labelmesher::SelectMaterials(std::move(decimated.Mesh), this->IncludeBackground);
  labelmesher::PackVolumeMesh(kept, placement, output);
  labelmesher::PackInterfaces(decimated.Interfaces, decimated.InterfaceMaterials, placement, boundary);

  vtkFieldData* fd = output->GetFieldData();
  const std::size_t before =
    this->IncludeBackground ? decimated.Counts.CellsBefore : result.Streaming.ForegroundCellsBefore;
  labelmesher::AddDecimationFields(fd, decimation, decimated.Counts, before, kept.NumberOfCells());
  labelmesher::AddScalarField(fd, arrays::IncludeBackground, this->IncludeBackground ? 1.0 : 0.0);
  labelmesher::AddScalarField(fd, arrays::VoxelSize, placement.VoxelSize);
  labelmesher::AddScalarField(fd, arrays::NumberOfLeaves, static_cast<double>(result.Streaming.Leaves));
  labelmesher::AddScalarField(fd, arrays::EstimatedMemory, static_cast<double>(estimate.RunBytes) / (1 << 20));
  labelmesher::AddScalarField(fd, arrays::InterfaceFaces, static_cast<double>(estimate.InterfaceFaces));
  labelmesher::AddScalarField(fd, arrays::Blocks, static_cast<double>(result.Streaming.Blocks));
  labelmesher::AddScalarField(fd, arrays::LargestBlockCells, static_cast<double>(result.Streaming.LargestBlockCells));
  labelmesher::AddScalarField(fd, arrays::AssembledCells, static_cast<double>(result.Streaming.AssembledCells));
  labelmesher::PassMaterialTable(input->GetFieldData(), fd);
  labelmesher::PassMaterialTable(input->GetFieldData(), boundary->GetFieldData());
  if (this->MeasureOutput)
  {
    this->SetProgressText("measure");
    this->UpdateProgress(share);
    try
    {
      labelmesher::AddMeasurements(fd, image, kept, this->ImageToMeshDistance, this->MeshToImageDistance,
        decimated.Timings, [&](int checksDone) { this->UpdateProgress(share + (1.0 - share) * checksDone / 4.0); });
    }
    catch (const std::exception& e)
    {
      vtkWarningMacro("Measuring the mesh failed: " << e.what());
    }
  }
  labelmesher::AddStageTimings(fd, decimated.Timings);
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLabelMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageToMeshDistance: " << this->ImageToMeshDistance << " voxels\n";
  os << indent << "MeshToImageDistance: " << this->MeshToImageDistance << " voxels\n";
  os << indent << "MinimumAngle: " << this->MinimumAngle << " degrees\n";
  os << indent << "RelocateInteriorVertices: " << (this->RelocateInteriorVertices ? "On" : "Off") << "\n";
  os << indent << "BlockCells: " << this->BlockCells << " initial cells\n";
  os << indent << "IncludeBackground: " << (this->IncludeBackground ? "On" : "Off") << "\n";
  os << indent << "MeasureOutput: " << (this->MeasureOutput ? "On" : "Off") << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << " MiB (0: the available memory)\n";
}
