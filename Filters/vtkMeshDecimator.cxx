// SPDX-License-Identifier: GPL-2.0-or-later
// vtkMeshDecimator's passes: check the inputs, gather the mesh, run the core decimator, pack and
// measure.
#include "vtkMeshDecimator.h"

#include "Decimation/MeshDecimator.h"
#include "FilterSupport.h"
#include "LabelImageConversion.h"
#include "LabelMesherArrayNames.h"
#include "MemoryBudget.h"
#include "Mesh/MeshSelection.h"
#include "Support/MemoryEstimate.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <exception>
#include <new>
#include <string>
#include <utility>

vtkStandardNewMacro(vtkMeshDecimator);

//------------------------------------------------------------------------------
void vtkMeshDecimator::SetMinimumAngle(double degrees)
{
  const double clamped = labelmesher::ClampToProvenAngleBounds(degrees);
  if (clamped != this->MinimumAngle)
  {
    this->MinimumAngle = clamped;
    this->Modified();
  }
}

/*
 * Design. RequestData is a sequence of passes, none of which knows the algorithm:
 *   1. convert: the label image (port 1) as the core's LabelImage, with its
 *               placement (LabelImageConversion.h);
 *   2. gather:  the mesh (port 0) back in the image's index space, every cell
 *               positively oriented there, with its Material;
 *   3. decimate: labelmesher::DecimateMesh, progress and abort forwarded;
 *   4. pack and measure, as vtkLabelOctreeMesher (FilterSupport.h).
 */

namespace
{
namespace arrays = labelmesher::arrays;

/// Pass 2: the input cells in the image's index space, positively oriented there. Returns false
/// with a sentence in `error`.
bool GatherMesh(vtkUnstructuredGrid* input, const labelmesher::ImagePlacement& placement, int dimension,
  labelmesher::SimplexMesh& mesh, std::string& error)
{
  if (input->GetNumberOfCells() == 0 || !input->GetPoints())
  {
    error = "Input mesh has no cells: nothing to decimate.";
    return false;
  }
  vtkDataArray* materials = labelmesher::MaterialArray(input, error);
  if (!materials)
  {
    return false;
  }
  const auto toIndex = [&](const double x[3], labelmesher::Point3& index, std::string& why) {
    if (!placement.ToIndex({ x[0], x[1], x[2] }, index))
    {
      why = "The image's direction matrix is singular.";
      return false;
    }
    if (dimension == 2)
    {
      if (std::abs(index[2]) > 1e-6)
      {
        why = "Input mesh does not lie in the plane of the 2D image on port 1: it is not that image's mesh.";
        return false;
      }
      index[2] = 0.0;
    }
    return true;
  };
  return labelmesher::GatherSimplices(input, materials, dimension, toIndex,
    std::string(", as the ") + (dimension == 3 ? "3D" : "2D") + " image on port 1 needs.", mesh, error);
}

/// A bound the user set (>= 0), or the one the mesher recorded.
bool ResolveDistance(double set, vtkUnstructuredGrid* input, const char* name, double& value, std::string& error)
{
  value = labelmesher::ResolveBound(set, input, name);
  if (value < 0.0)
  {
    error = std::string("Set ") + name + ": the input mesh does not record the bound it was meshed with.";
    return false;
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
vtkMeshDecimator::vtkMeshDecimator()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkMeshDecimator::GetInterfacesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkMeshDecimator::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkUnstructuredGrid" : "vtkImageData");
  if (port == 1)
  {
    // Required in fact; optional to the pipeline so that RequestData can say
    // plainly what is missing instead of the executive's generic message.
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkMeshDecimator::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkMeshDecimator::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  labelmesher::RequestWholeImages(inputVector[1]);
  return 1;
}

//------------------------------------------------------------------------------
int vtkMeshDecimator::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkImageData* imageData = vtkImageData::GetData(inputVector[1], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkPolyData* boundary = vtkPolyData::GetData(outputVector, 1);
  if (!input || !output || !boundary)
  {
    vtkErrorMacro("Missing input mesh or outputs.");
    return 0;
  }
  if (!imageData)
  {
    vtkErrorMacro("No label image on port 1: the decimator measures the mesh against the image it came from.");
    return 1;
  }

  std::string error;
  labelmesher::ImagePlacement placement;
  labelmesher::LabelImage image;
  if (!labelmesher::ConvertLabelImage(imageData, this->GetInputArrayToProcess(0, inputVector), image, placement, error))
  {
    vtkErrorMacro("Label image on port 1: " << error << ".");
    return 1;
  }
  const std::uint64_t needed = labelmesher::EstimateDecimationMemory(static_cast<std::uint64_t>(input->GetNumberOfCells()));
  const labelmesher::MemoryBudget budget = labelmesher::AvailableMemory(this->MemoryLimit);
  const std::string refusal =
    labelmesher::RefuseIfTooLarge(needed, labelmesher::WithThousandsSeparators(static_cast<std::uint64_t>(input->GetNumberOfCells())) + " input cells", budget);
  if (!refusal.empty())
  {
    vtkErrorMacro(<< refusal << ".");
    return 1;
  }
  labelmesher::SimplexMesh mesh;
  labelmesher::DecimationParameters parameters;
  parameters.MinimumAngle = this->MinimumAngle;
  parameters.RelocateInteriorVertices = this->RelocateInteriorVertices;
  if (!GatherMesh(input, placement, image.Dimension(), mesh, error) ||
    !ResolveDistance(this->ImageToMeshDistance, input, arrays::ImageToMeshDistance, parameters.ImageToMeshDistance, error) ||
    !ResolveDistance(this->MeshToImageDistance, input, arrays::MeshToImageDistance, parameters.MeshToImageDistance, error))
  {
    vtkErrorMacro(<< error);
    return 1;
  }

  std::size_t before = 0;
  for (std::int32_t m : mesh.Materials)
  {
    before += this->IncludeBackground || m != 0;
  }
  const double share = this->MeasureOutput ? 0.8 : 1.0;
  labelmesher::DecimationResult result;
  try
  {
    // Handed over: the decimator frees the copy once it holds its own.
    result = labelmesher::DecimateMesh(image, std::move(mesh), parameters, labelmesher::ForwardProgress(this, 0.0, share));
  }
  catch (const labelmesher::AbortRequested&)
  {
    vtkWarningMacro("Decimation aborted on request: output is empty.");
    return 1;
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Decimation failed: out of memory (estimated beforehand to need "
      << labelmesher::FormatMiB(needed) << " more; " << labelmesher::FormatMiB(budget.Bytes)
      << " were available: " << budget.Source << ").");
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Decimation failed: " << e.what() << ".");
    return 1;
  }

  const labelmesher::SimplexMesh kept = labelmesher::SelectMaterials(std::move(result.Mesh), this->IncludeBackground);
  labelmesher::PackVolumeMesh(kept, placement, output);
  labelmesher::PackInterfaces(result.Interfaces, result.InterfaceMaterials, placement, boundary);

  vtkFieldData* fd = output->GetFieldData();
  labelmesher::AddDecimationFields(fd, parameters, result.Counts, before, kept.NumberOfCells());
  labelmesher::AddScalarField(fd, arrays::IncludeBackground, this->IncludeBackground ? 1.0 : 0.0);
  labelmesher::AddScalarField(fd, arrays::VoxelSize, placement.VoxelSize);
  // The mesh's table where it has one (it came through the mesher), else the image's.
  labelmesher::PassMaterialTable(
    input->GetFieldData()->GetAbstractArray(arrays::MaterialLabel) ? input->GetFieldData() : imageData->GetFieldData(), fd);
  labelmesher::PassMaterialTable(fd, boundary->GetFieldData());
  if (this->MeasureOutput)
  {
    this->SetProgressText("measure");
    this->UpdateProgress(share);
    try
    {
      labelmesher::AddMeasurements(fd, image, kept, parameters.ImageToMeshDistance, parameters.MeshToImageDistance,
        result.Timings,
        [&](int checksDone) { this->UpdateProgress(share + (1.0 - share) * checksDone / 4.0); });
    }
    catch (const std::exception& e)
    {
      vtkWarningMacro("Measuring the mesh failed: " << e.what());
    }
  }
  labelmesher::AddStageTimings(fd, result.Timings);
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkMeshDecimator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumAngle: " << this->MinimumAngle << " degrees\n";
  os << indent << "ImageToMeshDistance: " << this->ImageToMeshDistance << " voxels (negative: the input's)\n";
  os << indent << "MeshToImageDistance: " << this->MeshToImageDistance << " voxels (negative: the input's)\n";
  os << indent << "RelocateInteriorVertices: " << (this->RelocateInteriorVertices ? "On" : "Off") << "\n";
  os << indent << "IncludeBackground: " << (this->IncludeBackground ? "On" : "Off") << "\n";
  os << indent << "MeasureOutput: " << (this->MeasureOutput ? "On" : "Off") << "\n";
}
