// SPDX-License-Identifier: GPL-2.0-or-later
#include "vtkLabelOctreeMesher.h"

#include "LabelImageConversion.h"
#include "LabelOctreeMesher.h"
#include "Mesh/MeshSelection.h"
#include "Checks/MeshChecks.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLabelOctreeMesher);

namespace
{
/*
 * Design. RequestData is a sequence of passes, none of which knows the algorithm:
 *   1-2. gather and place (LabelImageConversion.h): validate the label array,
 *               convert it to the core's LabelImage and remember the inverse
 *               map, index space -> physical space;
 *   3. mesh:    labelmesher::MeshLabelImage with progress and abort forwarded;
 *   4. pack:    points mapped to physical space, cells of the kept materials,
 *               the boundary surface, the field data;
 *   5. measure: the checks of Filters/Core/Checks on the kept cells.
 */

using labelmesher::Point3;

// ---- pass 4: pack -----------------------------------------------------------
vtkSmartPointer<vtkCellArray> MakeCells(const std::vector<std::int64_t>& connectivity,
  int verticesPerCell, std::size_t numberOfCells)
{
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(numberOfCells + 1));
  for (std::size_t c = 0; c <= numberOfCells; ++c)
  {
    offsets->SetValue(static_cast<vtkIdType>(c), static_cast<vtkIdType>(c * verticesPerCell));
  }
  vtkNew<vtkIdTypeArray> ids;
  ids->SetNumberOfValues(static_cast<vtkIdType>(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), ids->GetPointer(0));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, ids);
  return cells;
}

template <typename ArrayT, typename T>
void AddField(vtkFieldData* fd, const char* name, const std::vector<T>& values)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  fd->AddArray(array);
}

void AddScalarField(vtkFieldData* fd, const char* name, double value)
{
  AddField<vtkDoubleArray>(fd, name, std::vector<double>{ value });
}

/// `finished(check)` is called after each check (for its time and progress).
template <typename Finished>
void AddMeasures(vtkFieldData* fd, const labelmesher::LabelImage& image,
  const labelmesher::SimplexMesh& kept, Finished&& finished)
{
  const labelmesher::QualityReport quality = labelmesher::MeasureQuality(kept);
  AddScalarField(fd, "MinimumAngle", quality.MinimumAngle);
  AddScalarField(fd, "MaximumAngle", quality.MaximumAngle);
  AddScalarField(fd, "InvertedCells", static_cast<double>(quality.InvertedCells));
  finished("angles");

  const labelmesher::ConformityReport conformity = labelmesher::MeasureConformity(kept);
  AddScalarField(fd, "OverSharedFaces", static_cast<double>(conformity.OverSharedFaces));
  AddScalarField(fd, "HangingVertices", static_cast<double>(conformity.HangingVertices));
  AddScalarField(fd, "NonManifoldBoundaryEdges", static_cast<double>(conformity.NonManifoldBoundaryEdges));
  finished("conformity");

  const labelmesher::HausdorffReport distances = labelmesher::MeasureHausdorff(image, kept);
  AddScalarField(fd, "MeasuredImageToMeshDistance", distances.Overall.ImageToMesh);
  AddScalarField(fd, "MeasuredMeshToImageDistance", distances.Overall.MeshToImage);
  finished("distances");

  std::vector<int> material, imageComponents, imageEuler, meshComponents, meshEuler, matches;
  for (const auto& entry : labelmesher::CompareTopology(image, kept))
  {
    material.push_back(entry.first);
    imageComponents.push_back(static_cast<int>(entry.second.Image.Components));
    imageEuler.push_back(static_cast<int>(entry.second.Image.EulerCharacteristic));
    meshComponents.push_back(static_cast<int>(entry.second.Mesh.Components));
    meshEuler.push_back(static_cast<int>(entry.second.Mesh.EulerCharacteristic));
    matches.push_back(entry.second.Matches() ? 1 : 0);
  }
  AddField<vtkIntArray>(fd, "TopologyMaterial", material);
  AddField<vtkIntArray>(fd, "ImageComponents", imageComponents);
  AddField<vtkIntArray>(fd, "ImageEulerCharacteristic", imageEuler);
  AddField<vtkIntArray>(fd, "MeshComponents", meshComponents);
  AddField<vtkIntArray>(fd, "MeshEulerCharacteristic", meshEuler);
  AddField<vtkIntArray>(fd, "TopologyMatches", matches);
  finished("topology");
}

} // anonymous namespace

//------------------------------------------------------------------------------
vtkLabelOctreeMesher::vtkLabelOctreeMesher()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLabelOctreeMesher::GetBoundaryOutput()
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

  // ---- validate, gather, place ----
  labelmesher::ImagePlacement placement;
  labelmesher::LabelImage image;
  {
    std::string error;
    vtkDataArray* scalars = this->GetInputArrayToProcess(0, inputVector);
    if (!labelmesher::ConvertLabelImage(input, scalars, image, placement, error))
    {
      vtkErrorMacro(<< error << ".");
      return 1;
    }
  }

  // ---- mesh ----
  labelmesher::MesherParameters parameters;
  parameters.ImageToMeshDistance = this->ImageToMeshDistance;
  parameters.MeshToImageDistance = this->MeshToImageDistance;
  const bool measure = this->MeasureOutput;
  const double meshShare = measure ? 0.8 : 1.0;
  labelmesher::ProgressObserver observer;
  observer.Callback = [this, meshShare](const std::string& stage, double fraction) {
    this->SetProgressText(stage.c_str());
    this->UpdateProgress(meshShare * std::clamp(fraction, 0.0, 1.0));
    return !this->GetAbortExecute();
  };

  labelmesher::MesherResult result;
  try
  {
    result = labelmesher::MeshLabelImage(image, parameters, observer);
  }
  catch (const labelmesher::AbortRequested&)
  {
    vtkWarningMacro("Meshing aborted on request: output is empty.");
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Meshing failed: " << e.what());
    return 1;
  }

  // ---- pack: volume cells of the kept materials, compacted points ----
  const labelmesher::SimplexMesh& mesh = result.Mesh;
  const int nv = mesh.VerticesPerCell();
  const bool reverse = mesh.Dimension == 3 && placement.ReversesOrientation();
  // kept cells, compacted points, index space
  const labelmesher::SimplexMesh kept = labelmesher::SelectMaterials(mesh, this->IncludeBackground);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(kept.Points.size()));
  for (std::size_t p = 0; p < kept.Points.size(); ++p)
  {
    points->SetPoint(static_cast<vtkIdType>(p), placement.ToPhysical(kept.Points[p]).data());
  }
  std::vector<std::int64_t> connectivity = kept.Connectivity;
  if (reverse)
  {
    for (std::size_t c = 0; c < kept.NumberOfCells(); ++c)
    {
      std::swap(connectivity[c * nv + 1], connectivity[c * nv + 2]);
    }
  }
  output->SetPoints(points);
  output->SetCells(mesh.Dimension == 3 ? VTK_TETRA : VTK_TRIANGLE,
    MakeCells(connectivity, nv, kept.NumberOfCells()));
  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  material->SetNumberOfValues(static_cast<vtkIdType>(kept.NumberOfCells()));
  std::copy(kept.Materials.begin(), kept.Materials.end(), material->GetPointer(0));
  output->GetCellData()->SetScalars(material);

  // ---- pack: boundary surface ----
  const labelmesher::SimplexMesh& surface = result.Boundary;
  vtkNew<vtkPoints> surfacePoints;
  surfacePoints->SetDataTypeToDouble();
  surfacePoints->SetNumberOfPoints(static_cast<vtkIdType>(surface.Points.size()));
  for (std::size_t p = 0; p < surface.Points.size(); ++p)
  {
    surfacePoints->SetPoint(
      static_cast<vtkIdType>(p), placement.ToPhysical(surface.Points[p]).data());
  }
  boundary->SetPoints(surfacePoints);
  const int facetVertices = mesh.Dimension; // a facet of a d-simplex has d vertices
  const std::size_t facets = surface.Connectivity.size() / std::max(1, facetVertices);
  auto facetCells = MakeCells(surface.Connectivity, facetVertices, facets);
  if (facetVertices == 3)
  {
    boundary->SetPolys(facetCells);
  }
  else
  {
    boundary->SetLines(facetCells);
  }
  vtkNew<vtkIntArray> materials;
  materials->SetName("Materials");
  materials->SetNumberOfComponents(2);
  materials->SetNumberOfTuples(static_cast<vtkIdType>(facets));
  for (std::size_t f = 0; f < facets && f < result.BoundaryMaterials.size(); ++f)
  {
    materials->SetTypedComponent(static_cast<vtkIdType>(f), 0, result.BoundaryMaterials[f].first);
    materials->SetTypedComponent(static_cast<vtkIdType>(f), 1, result.BoundaryMaterials[f].second);
  }
  boundary->GetCellData()->AddArray(materials);

  // ---- field data ----
  vtkFieldData* fd = output->GetFieldData();
  AddScalarField(fd, "ImageToMeshDistance", this->ImageToMeshDistance);
  AddScalarField(fd, "MeshToImageDistance", this->MeshToImageDistance);
  AddScalarField(fd, "IncludeBackground", this->IncludeBackground ? 1.0 : 0.0);
  AddScalarField(fd, "VoxelSize", placement.VoxelSize);
  AddScalarField(fd, "NumberOfLeaves", static_cast<double>(result.NumberOfLeaves));
  std::vector<std::string> stageNames;
  std::vector<double> stageSeconds;
  for (const auto& timing : result.Timings)
  {
    stageNames.push_back(timing.Stage);
    stageSeconds.push_back(timing.Seconds);
  }

  if (measure)
  {
    this->SetProgressText("measure");
    this->UpdateProgress(meshShare);
    // One stage per check, so that users see what the verification costs.
    auto start = std::chrono::steady_clock::now();
    int checksDone = 0;
    auto finished = [&](const char* check) {
      const auto now = std::chrono::steady_clock::now();
      stageNames.push_back(std::string("measure: ") + check);
      stageSeconds.push_back(std::chrono::duration<double>(now - start).count());
      start = now;
      this->UpdateProgress(meshShare + (1.0 - meshShare) * ++checksDone / 4.0);
    };
    try
    {
      AddMeasures(fd, image, kept, finished);
    }
    catch (const std::exception& e)
    {
      vtkWarningMacro("Measuring the mesh failed: " << e.what());
    }
  }
  AddField<vtkStringArray>(fd, "StageName", stageNames);
  AddField<vtkDoubleArray>(fd, "StageSeconds", stageSeconds);
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);
  return 1;
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
