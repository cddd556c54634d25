// SPDX-License-Identifier: GPL-2.0-or-later
#include "vtkBezierCurver.h"

#include "Curving/BezierCurver.h"
#include "Curving/CurvedMeshLocator.h"
#include "LabelImageConversion.h"

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
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <array>
#include <cmath>
#include <exception>
#include <map>
#include <set>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkBezierCurver);

namespace
{
/*
 * Design. RequestData: (1) flatten the input triangles into the core's 2D
 * SimplexMesh, in the two coordinates of the axis plane the mesh lies in, every
 * triangle counter-clockwise there; (2) convert the optional image, keeping the
 * map from its pixels to those coordinates; (3) labelmesher::CurveMesh;
 * (4) pack the Bézier cells back into 3D; (5) measure pixel accuracy.
 */

/// The axis plane a mesh lies in: mesh coordinate a is physical axis Axes[a];
/// physical axis Normal is constant (= Offset).
struct PlaneAxes
{
  int Axes[2] = { 0, 1 };
  int Normal = 2;
  double Offset = 0.0;
};

bool FindAxisPlane(vtkPoints* points, PlaneAxes& plane)
{
  double bounds[6];
  points->GetBounds(bounds);
  double size = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    size = std::max(size, bounds[2 * a + 1] - bounds[2 * a]);
  }
  for (int normal = 2; normal >= 0; --normal)
  {
    if (bounds[2 * normal + 1] - bounds[2 * normal] <= 1e-9 * size)
    {
      plane.Normal = normal;
      plane.Offset = 0.5 * (bounds[2 * normal] + bounds[2 * normal + 1]);
      plane.Axes[0] = normal == 0 ? 1 : 0;
      plane.Axes[1] = normal == 2 ? 1 : 2;
      return true;
    }
  }
  return false;
}

template <typename T>
void AddField(vtkFieldData* fd, const char* name, const std::vector<T>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  for (const T& v : values)
  {
    array->InsertNextValue(static_cast<double>(v));
  }
  fd->AddArray(array);
}

void AddScalarField(vtkFieldData* fd, const char* name, double value)
{
  AddField(fd, name, std::vector<double>{ value });
}

void AddAccuracy(vtkFieldData* fd, const labelmesher::PixelAccuracy& linear,
  const labelmesher::PixelAccuracy& curved, const labelmesher::LabelImage& image)
{
  AddScalarField(fd, "Pixels", static_cast<double>(linear.Pixels));
  AddScalarField(fd, "MisclassifiedPixelsLinear", static_cast<double>(linear.Misclassified));
  AddScalarField(fd, "MisclassifiedPixelsCurved", static_cast<double>(curved.Misclassified));
  std::set<std::int32_t> labels(image.Labels.begin(), image.Labels.end());
  labels.erase(0);
  std::vector<double> material, missedLinear, missedCurved, claimedLinear, claimedCurved;
  auto count = [](const std::map<std::int32_t, std::size_t>& m, std::int32_t label) {
    const auto it = m.find(label);
    return it == m.end() ? 0.0 : static_cast<double>(it->second);
  };
  for (std::int32_t label : labels)
  {
    material.push_back(label);
    missedLinear.push_back(count(linear.Missed, label));
    missedCurved.push_back(count(curved.Missed, label));
    claimedLinear.push_back(count(linear.Claimed, label));
    claimedCurved.push_back(count(curved.Claimed, label));
  }
  AddField(fd, "AccuracyMaterial", material);
  AddField(fd, "MissedPixelsLinear", missedLinear);
  AddField(fd, "MissedPixelsCurved", missedCurved);
  AddField(fd, "ClaimedPixelsLinear", claimedLinear);
  AddField(fd, "ClaimedPixelsCurved", claimedCurved);
}

} // anonymous namespace

//------------------------------------------------------------------------------
vtkBezierCurver::vtkBezierCurver()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
int vtkBezierCurver::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkBezierCurver::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkImageData* imageData = vtkImageData::GetData(inputVector[1], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Missing input mesh or output.");
    return 0;
  }

  // ---- (1) flatten ----
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  if (numberOfCells == 0 || !input->GetPoints())
  {
    vtkErrorMacro("Input mesh has no cells: nothing to curve.");
    return 1;
  }
  vtkDataArray* materials = input->GetCellData()->GetArray("Material");
  if (!materials || materials->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("Input mesh has no one-component cell array 'Material'.");
    return 1;
  }
  PlaneAxes plane;
  if (!FindAxisPlane(input->GetPoints(), plane))
  {
    vtkErrorMacro("Input mesh does not lie in an axis plane (x-y, x-z or y-z): "
                  "the curver needs a 2D mesh.");
    return 1;
  }
  labelmesher::SimplexMesh linear;
  linear.Dimension = 2;
  linear.Points.resize(static_cast<std::size_t>(input->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    const double* x = input->GetPoint(p);
    linear.Points[static_cast<std::size_t>(p)] = { x[plane.Axes[0]], x[plane.Axes[1]], 0.0 };
  }
  linear.Connectivity.reserve(static_cast<std::size_t>(3 * numberOfCells));
  for (vtkIdType c = 0; c < numberOfCells; ++c)
  {
    if (input->GetCellType(c) != VTK_TRIANGLE)
    {
      vtkErrorMacro("Input cell " << c << " is not a linear triangle (VTK type "
                                  << input->GetCellType(c) << "): the curver needs triangles.");
      return 1;
    }
    const double value = materials->GetComponent(c, 0);
    if (!(value >= 0 && value == std::floor(value) && value <= VTK_INT_MAX))
    {
      vtkErrorMacro("Input cell " << c << " has Material " << value
                                  << ": expected a non-negative integer label.");
      return 1;
    }
    vtkIdType n;
    const vtkIdType* ids;
    input->GetCellPoints(c, n, ids);
    std::array<std::int64_t, 3> v{ ids[0], ids[1], ids[2] };
    const auto& a = linear.Points[v[0]];
    const auto& b = linear.Points[v[1]];
    const auto& d = linear.Points[v[2]];
    // The plane's own orientation is arbitrary: make every triangle counter-clockwise.
    if ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]) < 0.0)
    {
      std::swap(v[1], v[2]);
    }
    linear.Connectivity.insert(linear.Connectivity.end(), v.begin(), v.end());
    linear.Materials.push_back(static_cast<std::int32_t>(value));
  }

  // ---- (2) image: border and pixel placement ----
  labelmesher::CurvingParameters parameters;
  parameters.Smoothing.Continuity =
    this->Smoothness == 1 ? labelmesher::Smoothness::C1 : labelmesher::Smoothness::C2;
  parameters.Smoothing.Tension = this->Tension;
  parameters.Untangling.MaximumSteps = this->MaximumUntanglingSteps;
  parameters.Untangling.QualityIterations = this->QualityIterations;
  labelmesher::LabelImage image;
  std::array<double, 6> pixelToMesh{ 0, 1, 0, 0, 0, 1 };
  if (imageData)
  {
    labelmesher::ImagePlacement placement;
    std::string error;
    vtkDataArray* scalars = imageData->GetPointData()->GetScalars();
    if (!labelmesher::ConvertLabelImage(imageData, scalars, image, placement, error))
    {
      vtkErrorMacro(<< error << ".");
      return 1;
    }
    if (image.Dimension() != 2)
    {
      vtkErrorMacro("The image on port 1 is 3D: the curver needs the 2D image the mesh came from.");
      return 1;
    }
    auto project = [&](double i, double j) {
      const labelmesher::Point3 x = placement.ToPhysical({ i, j, 0.0 });
      return labelmesher::Point2{ x[plane.Axes[0]], x[plane.Axes[1]] };
    };
    const labelmesher::Point2 o = project(0, 0), di = project(1, 0), dj = project(0, 1);
    pixelToMesh = { o[0], di[0] - o[0], dj[0] - o[0], o[1], di[1] - o[1], dj[1] - o[1] };
    // The border is the outer side of the border pixels.
    parameters.HasBorder = true;
    parameters.Border = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    for (double i : { -0.5, image.Dimensions[0] - 0.5 })
    {
      for (double j : { -0.5, image.Dimensions[1] - 0.5 })
      {
        const labelmesher::Point2 corner = project(i, j);
        parameters.Border[0] = std::min(parameters.Border[0], corner[0]);
        parameters.Border[1] = std::max(parameters.Border[1], corner[0]);
        parameters.Border[2] = std::min(parameters.Border[2], corner[1]);
        parameters.Border[3] = std::max(parameters.Border[3], corner[1]);
      }
    }
  }

  // ---- (3) curve ----
  labelmesher::ProgressObserver observer;
  const double curveShare = imageData ? 0.8 : 1.0;
  observer.Callback = [this, curveShare](const std::string& stage, double fraction) {
    this->SetProgressText(stage.c_str());
    this->UpdateProgress(curveShare * std::clamp(fraction, 0.0, 1.0));
    return !this->GetAbortExecute();
  };
  labelmesher::CurvingResult result;
  try
  {
    result = labelmesher::CurveMesh(linear, parameters, observer);
  }
  catch (const labelmesher::AbortRequested&)
  {
    vtkWarningMacro("Curving aborted on request: output is empty.");
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Curving failed: " << e.what());
    return 1;
  }

  // ---- (4) pack ----
  const labelmesher::CurvedMesh& curved = result.Mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(curved.ControlPoints.size()));
  for (std::size_t p = 0; p < curved.ControlPoints.size(); ++p)
  {
    double x[3];
    x[plane.Axes[0]] = curved.ControlPoints[p][0];
    x[plane.Axes[1]] = curved.ControlPoints[p][1];
    x[plane.Normal] = plane.Offset;
    points->SetPoint(static_cast<vtkIdType>(p), x);
  }
  const auto cells = static_cast<vtkIdType>(curved.Cells.size());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(cells + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(10 * cells);
  for (vtkIdType c = 0; c <= cells; ++c)
  {
    offsets->SetValue(c, 10 * c);
  }
  for (vtkIdType c = 0; c < cells; ++c)
  {
    for (int k = 0; k < 10; ++k)
    {
      connectivity->SetValue(10 * c + k, curved.Cells[static_cast<std::size_t>(c)][k]);
    }
  }
  vtkNew<vtkCellArray> cellArray;
  cellArray->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetCells(VTK_BEZIER_TRIANGLE, cellArray);

  vtkNew<vtkIntArray> material;
  material->SetName("Material");
  vtkNew<vtkDoubleArray> minimumJacobian;
  minimumJacobian->SetName("MinimumJacobian");
  vtkNew<vtkDoubleArray> scaledJacobian;
  scaledJacobian->SetName("ScaledJacobian");
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName("Valid");
  material->SetNumberOfValues(cells);
  minimumJacobian->SetNumberOfValues(cells);
  scaledJacobian->SetNumberOfValues(cells);
  valid->SetNumberOfValues(cells);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const auto& bounds = result.CellBounds[static_cast<std::size_t>(c)];
    material->SetValue(c, curved.Materials[static_cast<std::size_t>(c)]);
    minimumJacobian->SetValue(c, bounds.Lower);
    scaledJacobian->SetValue(c, bounds.ScaledJacobian());
    valid->SetValue(c, 1);
  }
  for (std::size_t c : result.InvalidCells)
  {
    valid->SetValue(static_cast<vtkIdType>(c), 0);
  }
  output->GetCellData()->SetScalars(material);
  output->GetCellData()->AddArray(minimumJacobian);
  output->GetCellData()->AddArray(scaledJacobian);
  output->GetCellData()->AddArray(valid);

  vtkFieldData* fd = output->GetFieldData();
  AddScalarField(fd, "Smoothness", this->Smoothness);
  AddScalarField(fd, "Tension", this->Tension);
  AddScalarField(fd, "MaximumUntanglingSteps", this->MaximumUntanglingSteps);
  AddScalarField(fd, "QualityIterations", this->QualityIterations);
  AddScalarField(fd, "InvalidBeforeUntangling", static_cast<double>(result.InvalidBeforeUntangling));
  AddScalarField(fd, "InvalidCells", static_cast<double>(result.InvalidCells.size()));
  AddScalarField(fd, "UntanglingSteps", result.UntanglingSteps);
  AddScalarField(fd, "InterfaceChains", static_cast<double>(result.NumberOfChains));
  AddScalarField(fd, "ClosedInterfaceChains", static_cast<double>(result.NumberOfClosedChains));
  AddScalarField(fd, "CurvedEdges", static_cast<double>(result.NumberOfCurvedEdges));
  AddScalarField(fd, "SplitEars", static_cast<double>(result.SplitEars));

  // ---- (5) accuracy ----
  if (imageData)
  {
    const auto start = std::chrono::steady_clock::now();
    this->SetProgressText("Measuring pixel accuracy");
    this->UpdateProgress(0.85);
    const labelmesher::PixelAccuracy linearAccuracy = labelmesher::MeasurePixelAccuracy(
      labelmesher::MakeStraightCurvedMesh(linear), image, pixelToMesh);
    const labelmesher::PixelAccuracy curvedAccuracy =
      labelmesher::MeasurePixelAccuracy(curved, image, pixelToMesh);
    AddAccuracy(fd, linearAccuracy, curvedAccuracy, image);
    result.Timings.emplace_back("pixel accuracy",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  vtkNew<vtkStringArray> stageName;
  stageName->SetName("StageName");
  std::vector<double> seconds;
  for (const auto& [stage, s] : result.Timings)
  {
    stageName->InsertNextValue(stage);
    seconds.push_back(s);
  }
  fd->AddArray(stageName);
  AddField(fd, "StageSeconds", seconds);
  this->UpdateProgress(1.0);

  if (!result.Valid)
  {
    vtkErrorMacro(<< result.InvalidCells.size() << " of " << cells
                  << " cells could not be proven valid after untangling with up to "
                  << this->MaximumUntanglingSteps
                  << " steps; they are marked Valid = 0 in the output.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkBezierCurver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Smoothness: C" << this->Smoothness << "\n";
  os << indent << "Tension: " << this->Tension << "\n";
  os << indent << "MaximumUntanglingSteps: " << this->MaximumUntanglingSteps << "\n";
  os << indent << "QualityIterations: " << this->QualityIterations << "\n";
}
