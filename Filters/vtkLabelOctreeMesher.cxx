// SPDX-License-Identifier: GPL-2.0-or-later
#include "vtkLabelOctreeMesher.h"

#include "LabelOctreeMesher.h"
#ifdef LABELMESHER_HAVE_CHECKS
#include "MeshChecks.h"
#endif

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
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
 *   1. gather:  copy the label array into int32 labels, validating every value
 *               (vtkArrayDispatch over the integer value types);
 *   2. place:   choose how the image maps to the core's LabelImage (2D slices
 *               along x or y are permuted into the x-y plane; anisotropic
 *               spacing is resampled nearest-neighbour to the smallest spacing)
 *               and remember the inverse map, index space -> physical space;
 *   3. mesh:    labelmesher::MeshLabelImage with progress and abort forwarded;
 *   4. pack:    points mapped to physical space, cells of the kept materials,
 *               the boundary surface, the field data;
 *   5. measure: the checks of Filters/Core/Checks on the kept cells.
 */

using labelmesher::Point3;

// ---- pass 1: gather -------------------------------------------------------
struct GatherLabels
{
  std::vector<std::int32_t>& Labels;
  std::string Error;
  bool HasForeground = false;

  template <typename ArrayT>
  void operator()(ArrayT* array)
  {
    const auto values = vtk::DataArrayValueRange<1>(array);
    Labels.resize(static_cast<std::size_t>(values.size()));
    std::size_t n = 0;
    for (const auto v : values)
    {
      const long double value = static_cast<long double>(v);
      if (!this->Check(value))
      {
        return;
      }
      Labels[n++] = static_cast<std::int32_t>(v);
    }
  }

  // Values of types the dispatcher does not cover (e.g. implicit arrays).
  void Fallback(vtkDataArray* array)
  {
    Labels.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    {
      const double value = array->GetComponent(t, 0);
      if (!this->Check(value))
      {
        return;
      }
      Labels[static_cast<std::size_t>(t)] = static_cast<std::int32_t>(value);
    }
  }

  bool Check(long double value)
  {
    if (value < 0)
    {
      this->Error = "negative label " + std::to_string(static_cast<long long>(value)) +
        " (labels must be >= 0, 0 = background)";
      return false;
    }
    if (value > std::numeric_limits<std::int32_t>::max())
    {
      this->Error = "label " + std::to_string(static_cast<unsigned long long>(value)) +
        " does not fit a 32-bit signed integer";
      return false;
    }
    this->HasForeground = this->HasForeground || value > 0;
    return true;
  }
};

// ---- pass 2: place ----------------------------------------------------------
// LabelImage axis a corresponds to image axis ImageAxis[a]; its index p maps to
// the image's local (pre-direction) coordinate Start[a] + p * Step[a].
struct Placement
{
  int ImageAxis[3] = { 0, 1, 2 };
  double Start[3] = { 0, 0, 0 };
  double Step[3] = { 1, 1, 1 };
  double Origin[3] = { 0, 0, 0 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double VoxelSize = 1.0;

  Point3 ToPhysical(const Point3& p) const
  {
    double local[3];
    for (int a = 0; a < 3; ++a)
    {
      local[this->ImageAxis[a]] = this->Start[a] + p[a] * this->Step[a];
    }
    Point3 x;
    for (int r = 0; r < 3; ++r)
    {
      x[r] = this->Origin[r] + this->Direction[3 * r] * local[0] +
        this->Direction[3 * r + 1] * local[1] + this->Direction[3 * r + 2] * local[2];
    }
    return x;
  }

  /// True when the index -> physical map reverses orientation (tetrahedra must
  /// then swap two vertices to stay positively oriented).
  bool ReversesOrientation() const
  {
    double m[9]; // columns: physical image of each LabelImage axis
    for (int a = 0; a < 3; ++a)
    {
      for (int r = 0; r < 3; ++r)
      {
        m[3 * r + a] = this->Direction[3 * r + this->ImageAxis[a]] * this->Step[a];
      }
    }
    const double det = m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
      m[2] * (m[3] * m[7] - m[4] * m[6]);
    return det < 0;
  }
};

/// Builds the LabelImage (x fastest) from the gathered labels of an image with
/// point dimensions `dims`, permuting a single-slice image into the x-y plane and
/// resampling to isotropic voxels of the smallest (in-plane) spacing.
labelmesher::LabelImage PlaceLabels(const std::vector<std::int32_t>& labels, const int dims[3],
  const int extent[6], const double spacing[3], Placement& placement)
{
  // 2D when one axis has a single slice; the last such axis is the normal.
  int normal = -1;
  for (int a = 2; a >= 0 && normal < 0; --a)
  {
    if (dims[a] == 1)
    {
      normal = a;
    }
  }
  if (normal >= 0)
  {
    int next = 0;
    for (int a = 0; a < 3; ++a)
    {
      if (a != normal)
      {
        placement.ImageAxis[next++] = a;
      }
    }
    placement.ImageAxis[2] = normal;
  }
  const int meshedAxes = normal >= 0 ? 2 : 3;

  double h = std::numeric_limits<double>::max();
  for (int a = 0; a < meshedAxes; ++a)
  {
    h = std::min(h, std::abs(spacing[placement.ImageAxis[a]]));
  }
  placement.VoxelSize = h;

  int newDims[3];
  std::vector<std::vector<int>> source(3); // source index along each LabelImage axis
  for (int a = 0; a < 3; ++a)
  {
    const int axis = placement.ImageAxis[a];
    const int n = dims[axis];
    const double s = spacing[axis];
    const double sign = s < 0 ? -1.0 : 1.0;
    const bool resample = a < meshedAxes && std::abs(std::abs(s) - h) > 1e-9 * h;
    if (!resample)
    {
      newDims[a] = n;
      placement.Start[a] = extent[2 * axis] * s;
      placement.Step[a] = s;
      source[a].resize(n);
      for (int i = 0; i < n; ++i)
      {
        source[a][i] = i;
      }
      continue;
    }
    // Keep the physical span of the voxels, [-s/2, (n - 1/2) s], and tile it
    // with voxels of size h; voxel j samples the old voxel under its centre.
    const double ratio = std::abs(s) / h;
    newDims[a] = std::max(1, static_cast<int>(std::lround(n * ratio)));
    placement.Start[a] = extent[2 * axis] * s + sign * 0.5 * (h - std::abs(s));
    placement.Step[a] = sign * h;
    source[a].resize(newDims[a]);
    for (int j = 0; j < newDims[a]; ++j)
    {
      source[a][j] = std::min(n - 1, static_cast<int>(std::floor((j + 0.5) / ratio)));
    }
  }

  labelmesher::LabelImage image(newDims[0], newDims[1], newDims[2]);
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(dims[0]),
    static_cast<std::size_t>(dims[0]) * dims[1] };
  const std::size_t sx = stride[placement.ImageAxis[0]];
  const std::size_t sy = stride[placement.ImageAxis[1]];
  const std::size_t sz = stride[placement.ImageAxis[2]];
  std::size_t out = 0;
  for (int k = 0; k < newDims[2]; ++k)
  {
    for (int j = 0; j < newDims[1]; ++j)
    {
      const std::size_t row = source[2][k] * sz + source[1][j] * sy;
      for (int i = 0; i < newDims[0]; ++i)
      {
        image.Labels[out++] = labels[row + source[0][i] * sx];
      }
    }
  }
  return image;
}

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

#ifdef LABELMESHER_HAVE_CHECKS
void AddMeasures(vtkFieldData* fd, const labelmesher::LabelImage& image,
  const labelmesher::SimplexMesh& kept)
{
  const labelmesher::QualityReport quality = labelmesher::MeasureQuality(kept);
  AddScalarField(fd, "MinimumAngle", quality.MinimumAngle);
  AddScalarField(fd, "MaximumAngle", quality.MaximumAngle);
  AddScalarField(fd, "InvertedCells", static_cast<double>(quality.InvertedCells));

  const labelmesher::ConformityReport conformity = labelmesher::MeasureConformity(kept);
  AddScalarField(fd, "OverSharedFaces", static_cast<double>(conformity.OverSharedFaces));
  AddScalarField(fd, "HangingVertices", static_cast<double>(conformity.HangingVertices));
  AddScalarField(fd, "NonManifoldBoundaryEdges", static_cast<double>(conformity.NonManifoldBoundaryEdges));

  const labelmesher::HausdorffReport distances = labelmesher::MeasureHausdorff(image, kept);
  AddScalarField(fd, "MeasuredImageToMeshDistance", distances.Overall.ImageToMesh);
  AddScalarField(fd, "MeasuredMeshToImageDistance", distances.Overall.MeshToImage);

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
}
#endif

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

  // ---- validate and gather ----
  int extent[6];
  input->GetExtent(extent);
  int dims[3];
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
  }
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0)
  {
    vtkErrorMacro("Input image has an empty extent: nothing to mesh.");
    return 1;
  }
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, inputVector);
  if (!scalars)
  {
    vtkErrorMacro("Input image has no point scalars: expected integer labels.");
    return 1;
  }
  if (scalars->GetDataType() == VTK_FLOAT || scalars->GetDataType() == VTK_DOUBLE)
  {
    vtkErrorMacro("Input scalars '" << (scalars->GetName() ? scalars->GetName() : "")
                                    << "' are of type " << scalars->GetDataTypeAsString()
                                    << ": expected integer labels.");
    return 1;
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("Input scalars have " << scalars->GetNumberOfComponents()
                                        << " components: expected one label per voxel.");
    return 1;
  }
  if (scalars->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro("Input scalars have " << scalars->GetNumberOfTuples() << " values for "
                                        << input->GetNumberOfPoints()
                                        << " points: expected point-associated labels.");
    return 1;
  }
  const double* spacing = input->GetSpacing();
  for (int a = 0; a < 3; ++a)
  {
    if (!(std::isfinite(spacing[a]) && spacing[a] != 0.0))
    {
      vtkErrorMacro("Input spacing along axis " << a << " is " << spacing[a]
                                                << ": expected a finite, non-zero value.");
      return 1;
    }
  }

  std::vector<std::int32_t> labels;
  GatherLabels gather{ labels, {} };
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Integrals>::Execute(
        scalars, gather))
  {
    gather.Fallback(scalars);
  }
  if (!gather.Error.empty())
  {
    vtkErrorMacro("Invalid label image: " << gather.Error << ".");
    return 1;
  }
  if (!gather.HasForeground)
  {
    vtkErrorMacro("Input image has no foreground (every label is 0): nothing to mesh.");
    return 1;
  }

  // ---- place ----
  Placement placement;
  input->GetOrigin(placement.Origin);
  std::copy(input->GetDirectionMatrix()->GetData(), input->GetDirectionMatrix()->GetData() + 9,
    placement.Direction);
  const labelmesher::LabelImage image = PlaceLabels(labels, dims, extent, spacing, placement);
  labels = std::vector<std::int32_t>();

  // ---- mesh ----
  labelmesher::MesherParameters parameters;
  parameters.ImageToMeshDistance = this->ImageToMeshDistance;
  parameters.MeshToImageDistance = this->MeshToImageDistance;
#ifdef LABELMESHER_HAVE_CHECKS
  const bool measure = this->MeasureOutput;
#else
  const bool measure = false;
#endif
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
  labelmesher::SimplexMesh kept; // kept cells, compacted points, index space
  kept.Dimension = mesh.Dimension;
  std::vector<std::int64_t> newId(mesh.Points.size(), -1);
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    if (mesh.Materials[c] == 0 && !this->IncludeBackground)
    {
      continue;
    }
    const std::int64_t* cell = mesh.Cell(c);
    for (int v = 0; v < nv; ++v)
    {
      std::int64_t& id = newId[static_cast<std::size_t>(cell[v])];
      if (id < 0)
      {
        id = static_cast<std::int64_t>(kept.Points.size());
        kept.Points.push_back(mesh.Points[static_cast<std::size_t>(cell[v])]);
      }
      kept.Connectivity.push_back(id);
    }
    kept.Materials.push_back(mesh.Materials[c]);
  }

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

#ifdef LABELMESHER_HAVE_CHECKS
  if (measure)
  {
    this->SetProgressText("measure");
    this->UpdateProgress(meshShare);
    const auto start = std::chrono::steady_clock::now();
    try
    {
      AddMeasures(fd, image, kept);
    }
    catch (const std::exception& e)
    {
      vtkWarningMacro("Measuring the mesh failed: " << e.what());
    }
    stageNames.push_back("measure");
    stageSeconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
#endif
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
