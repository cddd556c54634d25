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

/// Pass 2. Returns false with a sentence in `error`.
bool GatherMesh(vtkUnstructuredGrid* input, const labelmesher::ImagePlacement& placement, int dimension,
  labelmesher::SimplexMesh& mesh, std::string& error)
{
  const vtkIdType cells = input->GetNumberOfCells();
  if (cells == 0 || !input->GetPoints())
  {
    error = "Input mesh has no cells: nothing to decimate.";
    return false;
  }
  vtkDataArray* materials = labelmesher::MaterialArray(input, error);
  if (!materials)
  {
    return false;
  }
  const int type = dimension == 3 ? VTK_TETRA : VTK_TRIANGLE;
  mesh.Dimension = dimension;
  mesh.Points.resize(static_cast<std::size_t>(input->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    const double* x = input->GetPoint(p);
    labelmesher::Point3 index;
    if (!placement.ToIndex({ x[0], x[1], x[2] }, index))
    {
      error = "The image's direction matrix is singular.";
      return false;
    }
    if (dimension == 2)
    {
      if (std::abs(index[2]) > 1e-6)
      {
        error = "Input mesh does not lie in the plane of the 2D image on port 1: it is not that image's mesh.";
        return false;
      }
      index[2] = 0.0;
    }
    mesh.Points[static_cast<std::size_t>(p)] = index;
  }
  const int nv = dimension + 1;
  mesh.Connectivity.reserve(static_cast<std::size_t>(cells) * nv);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    if (input->GetCellType(c) != type)
    {
      error = "Input cell " + std::to_string(c) + " is not a " + (dimension == 3 ? "tetrahedron" : "triangle") +
        " (VTK type " + std::to_string(input->GetCellType(c)) + "), as the " + (dimension == 3 ? "3D" : "2D") +
        " image on port 1 needs.";
      return false;
    }
    std::int32_t label;
    if (!labelmesher::CellMaterial(materials, c, label, error))
    {
      return false;
    }
    vtkIdType n;
    const vtkIdType* ids;
    input->GetCellPoints(c, n, ids);
    std::int64_t v[4] = { ids[0], ids[1], ids[2], dimension == 3 ? ids[3] : 0 };
    // Positively oriented in index space (a reflecting placement flips them).
    const auto& a = mesh.Points[v[0]];
    const auto& b = mesh.Points[v[1]];
    const auto& d = mesh.Points[v[2]];
    double orientation;
    if (dimension == 2)
    {
      orientation = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    }
    else
    {
      const auto& e = mesh.Points[v[3]];
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
      const double z[3] = { e[0] - a[0], e[1] - a[1], e[2] - a[2] };
      orientation = u[0] * (w[1] * z[2] - w[2] * z[1]) - u[1] * (w[0] * z[2] - w[2] * z[0]) +
        u[2] * (w[0] * z[1] - w[1] * z[0]);
    }
    if (orientation < 0)
    {
      std::swap(v[1], v[2]);
    }
    mesh.Connectivity.insert(mesh.Connectivity.end(), v, v + nv);
    mesh.Materials.push_back(label);
  }
  return true;
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
vtkPolyData* vtkMeshDecimator::GetBoundaryOutput()
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
  labelmesher::PackInterfaces(result.Boundary, result.BoundaryMaterials, placement, boundary);

  vtkFieldData* fd = output->GetFieldData();
  labelmesher::AddDecimationFields(fd, parameters, result.Counts, before, kept.NumberOfCells());
  labelmesher::AddScalarField(fd, arrays::IncludeBackground, this->IncludeBackground ? 1.0 : 0.0);
  labelmesher::AddScalarField(fd, arrays::VoxelSize, placement.VoxelSize);
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
