// SPDX-License-Identifier: GPL-2.0-or-later
// vtkBezierCurver's passes: flatten the triangles, run the core curver, pack Bézier cells and field
// data.
#include "vtkBezierCurver.h"

#include "Curving/BezierCurver.h"
#include "Checks/CurvedBoundary.h"
#include "Curving/CurvedMeshLocator.h"
#include "FilterSupport.h"
#include "LabelImageConversion.h"
#include "LabelMesherArrayNames.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
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
namespace arrays = labelmesher::arrays;
using labelmesher::AddField;
using labelmesher::AddScalarField;
using labelmesher::PassMaterialTable;

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

void AddAccuracy(vtkFieldData* fd, const labelmesher::PixelAccuracy& linear,
  const labelmesher::PixelAccuracy& curved, const labelmesher::LabelImage& image)
{
  AddScalarField(fd, arrays::Pixels, static_cast<double>(linear.Pixels));
  AddScalarField(fd, arrays::MisclassifiedPixelsLinear, static_cast<double>(linear.Misclassified));
  AddScalarField(fd, arrays::MisclassifiedPixelsCurved, static_cast<double>(curved.Misclassified));
  std::set<std::int32_t> labels;
  image.WithLabels([&](const auto* values) { labels.insert(values, values + image.NumberOfVoxels()); });
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
  AddField<vtkDoubleArray>(fd, arrays::AccuracyMaterial, material);
  AddField<vtkDoubleArray>(fd, arrays::MissedPixelsLinear, missedLinear);
  AddField<vtkDoubleArray>(fd, arrays::MissedPixelsCurved, missedCurved);
  AddField<vtkDoubleArray>(fd, arrays::ClaimedPixelsLinear, claimedLinear);
  AddField<vtkDoubleArray>(fd, arrays::ClaimedPixelsCurved, claimedCurved);
}


/// Pass 1: the input triangles as the core's 2D SimplexMesh in the two
/// coordinates of the axis plane the mesh lies in, every triangle
/// counter-clockwise there. Returns false with a sentence in `error`.
bool FlattenTriangles(vtkUnstructuredGrid* input, PlaneAxes& plane, labelmesher::SimplexMesh& linear, std::string& error)
{
  const vtkIdType numberOfCells = input->GetNumberOfCells();
  if (numberOfCells == 0 || !input->GetPoints())
  {
    error = "Input mesh has no cells: nothing to curve.";
    return false;
  }
  vtkDataArray* materials = labelmesher::MaterialArray(input, error);
  if (!materials)
  {
    return false;
  }
  if (!FindAxisPlane(input->GetPoints(), plane))
  {
    error = "Input mesh does not lie in an axis plane (x-y, x-z or y-z): the curver needs a 2D mesh.";
    return false;
  }
  // The plane's own orientation is arbitrary: every triangle is made counter-clockwise in it.
  const auto inPlane = [&](const double x[3], labelmesher::Point3& placed, std::string&) {
    placed = { x[plane.Axes[0]], x[plane.Axes[1]], 0.0 };
    return true;
  };
  return labelmesher::GatherSimplices(input, materials, 2, inPlane, ": the curver needs linear triangles.", linear, error);
}

/// Pass 2: the optional image: its pixels as the core's LabelImage, the map
/// from pixel indices to mesh coordinates, and the border (which stays straight).
bool PlaceImage(vtkImageData* imageData, vtkDataArray* labels, const PlaneAxes& plane, labelmesher::LabelImage& image,
  std::array<double, 6>& pixelToMesh, labelmesher::CurvingParameters& parameters, std::string& error)
{
  labelmesher::ImagePlacement placement;
  if (!labelmesher::ConvertLabelImage(imageData, labels, image, placement, error))
  {
    error += ".";
    return false;
  }
  if (image.Dimension() != 2)
  {
    error = "The image on port 1 is 3D: the curver needs the 2D image the mesh came from.";
    return false;
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
  return true;
}

/// Pass 4: the Bézier cells back in 3D (order 3), or as quadratic triangles (order 2, exact), with
/// their proven Jacobian bounds.
void PackBezierCells(
  const labelmesher::CurvingResult& result, const PlaneAxes& plane, int order, vtkUnstructuredGrid* output)
{
  const labelmesher::CurvedMesh& curved = result.Mesh;
  const auto& control = curved.ControlPoints;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto setPoint = [&plane, &points](std::int64_t id, const labelmesher::Point2& p) {
    double x[3];
    x[plane.Axes[0]] = p[0];
    x[plane.Axes[1]] = p[1];
    x[plane.Normal] = plane.Offset;
    points->SetPoint(static_cast<vtkIdType>(id), x);
  };
  std::vector<std::int64_t> connectivity;
  if (order == 2)
  {
    // Six nodes: the vertices (same ids), then one mid-node per edge, its curve's point at t = 1/2.
    points->SetNumberOfPoints(static_cast<vtkIdType>(curved.NumberOfVertices + curved.EdgeControlPoints.size()));
    for (std::int64_t v = 0; v < curved.NumberOfVertices; ++v)
      setPoint(v, control[static_cast<std::size_t>(v)]);
    std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> midNode;
    std::int64_t next = curved.NumberOfVertices;
    for (const auto& [edge, ids] : curved.EdgeControlPoints)
    {
      setPoint(next, labelmesher::CubicMidpoint(control[edge.first], control[ids[0]], control[ids[1]], control[edge.second]));
      midNode[edge] = next++;
    }
    connectivity.reserve(6 * curved.Cells.size());
    for (const auto& cell : curved.Cells)
    {
      connectivity.insert(connectivity.end(), cell.begin(), cell.begin() + 3);
      for (int e = 0; e < 3; ++e)
        connectivity.push_back(midNode.at({ std::min(cell[e], cell[(e + 1) % 3]), std::max(cell[e], cell[(e + 1) % 3]) }));
    }
    output->SetPoints(points);
    output->SetCells(VTK_QUADRATIC_TRIANGLE, labelmesher::MakeCellArray(connectivity, 6));
  }
  else
  {
    points->SetNumberOfPoints(static_cast<vtkIdType>(control.size()));
    for (std::size_t p = 0; p < control.size(); ++p)
      setPoint(static_cast<std::int64_t>(p), control[p]);
    connectivity.reserve(10 * curved.Cells.size());
    for (const auto& cell : curved.Cells)
      connectivity.insert(connectivity.end(), cell.begin(), cell.end());
    output->SetPoints(points);
    output->SetCells(VTK_BEZIER_TRIANGLE, labelmesher::MakeCellArray(connectivity, 10));
  }

  const auto cells = static_cast<vtkIdType>(curved.Cells.size());
  vtkNew<vtkIntArray> material;
  material->SetName(arrays::Material);
  vtkNew<vtkDoubleArray> minimumJacobian;
  minimumJacobian->SetName(arrays::MinimumJacobian);
  vtkNew<vtkDoubleArray> scaledJacobian;
  scaledJacobian->SetName(arrays::ScaledJacobian);
  vtkNew<vtkUnsignedCharArray> valid;
  valid->SetName(arrays::Valid);
  vtkNew<vtkDoubleArray> cornerAngle;
  cornerAngle->SetName(arrays::CornerAngle);
  cornerAngle->SetNumberOfValues(cells);
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
    cornerAngle->SetValue(c, labelmesher::SmallestCornerAngle(curved.Cell(static_cast<std::size_t>(c))));
    valid->SetValue(c, 1);
  }
  for (std::size_t c : result.InvalidCells)
  {
    valid->SetValue(static_cast<vtkIdType>(c), 0);
  }
  output->GetCellData()->SetScalars(material);
  output->GetCellData()->AddArray(minimumJacobian);
  output->GetCellData()->AddArray(scaledJacobian);
  output->GetCellData()->AddArray(cornerAngle);
  output->GetCellData()->AddArray(valid);
}

/// Pass 4 (field data): what curving did.
void AddCurvingCounts(vtkFieldData* fd, const labelmesher::CurvingResult& result)
{
  AddScalarField(fd, arrays::InvalidBeforeUntangling, static_cast<double>(result.InvalidBeforeUntangling));
  AddScalarField(fd, arrays::InvalidCells, static_cast<double>(result.InvalidCells.size()));
  AddScalarField(fd, arrays::UntanglingSteps, result.UntanglingSteps);
  AddScalarField(fd, arrays::InterfaceChains, static_cast<double>(result.NumberOfChains));
  AddScalarField(fd, arrays::ClosedInterfaceChains, static_cast<double>(result.NumberOfClosedChains));
  AddScalarField(fd, arrays::CurvedEdges, static_cast<double>(result.NumberOfCurvedEdges));
  AddScalarField(fd, arrays::SplitEars, static_cast<double>(result.SplitEars));
  AddScalarField(fd, arrays::EarCorners, static_cast<double>(result.EarCorners));
  AddScalarField(fd, arrays::ShortenedPieces, static_cast<double>(result.ShortenedPieces));
  AddScalarField(fd, arrays::StraightenedPieces, static_cast<double>(result.StraightenedPieces));
  AddScalarField(fd, arrays::PiecesShortenedForBounds, static_cast<double>(result.PiecesShortenedForBounds));
  AddScalarField(fd, arrays::PiecesShortenedForValidity, static_cast<double>(result.PiecesShortenedForValidity));
  AddScalarField(fd, arrays::UncertifiedPieces, static_cast<double>(result.UncertifiedPieces));
  AddScalarField(fd, arrays::UntanglingRounds, result.UntanglingRounds);
  AddScalarField(fd, arrays::CellsBelowScaledJacobian, static_cast<double>(result.CellsBelowScaledJacobian));
  AddScalarField(fd, arrays::StraightenedForScaledJacobian, result.StraightenedForScaledJacobian ? 1.0 : 0.0);
  AddScalarField(fd, arrays::CornerAngleBound, result.CornerAngleBound);
  AddScalarField(fd, arrays::CellsBelowCornerAngle, static_cast<double>(result.CellsBelowCornerAngle));
  AddScalarField(fd, arrays::StraightenedForCornerAngle, result.StraightenedForCornerAngle ? 1.0 : 0.0);
  AddScalarField(fd, arrays::StraightenedForValidity, result.StraightenedForValidity ? 1.0 : 0.0);
}

/// Pass 5 (field data): the curves' distances, crossings and topology against the image.
void AddCurvedMeasurements(
  vtkFieldData* fd, const labelmesher::CurvedMeshReport& report, const labelmesher::CurveBounds& bounds)
{
  AddScalarField(fd, arrays::ImageToMeshDistance, bounds.ImageToMesh);
  AddScalarField(fd, arrays::MeshToImageDistance, bounds.MeshToImage);
  AddScalarField(fd, arrays::CurvedMeasureResolution, report.Resolution);
  AddScalarField(fd, arrays::MeasuredImageToMeshDistance, report.Curves.ImageToMesh);
  AddScalarField(fd, arrays::MeasuredMeshToImageDistance, report.Curves.MeshToImage);
  AddScalarField(fd, arrays::InterfaceCrossings, static_cast<double>(report.Crossings));
  bool matches = true;
  for (const auto& [material, comparison] : report.Topology)
    matches = matches && comparison.Matches();
  AddScalarField(fd, arrays::TopologyMatches, matches ? 1.0 : 0.0);
}

} // anonymous namespace

//------------------------------------------------------------------------------
vtkBezierCurver::vtkBezierCurver()
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(
    0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
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
int vtkBezierCurver::RequestUpdateExtent(
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

  std::string error;
  PlaneAxes plane;
  labelmesher::SimplexMesh linear;
  if (!FlattenTriangles(input, plane, linear, error))
  {
    vtkErrorMacro(<< error);
    return 1;
  }
  labelmesher::CurvingParameters parameters;
  parameters.Smoothing.Continuity =
    this->Smoothness == 1 ? labelmesher::Smoothness::C1 : labelmesher::Smoothness::C2;
  parameters.Smoothing.Tension = this->Tension;
  parameters.Untangling.MaximumSteps = this->MaximumUntanglingSteps;
  parameters.MaximumShorteningRounds = this->MaximumShorteningRounds;
  parameters.Untangling.QualityIterations = this->QualityIterations;
  parameters.MinimumScaledJacobian = this->MinimumScaledJacobian;
  parameters.MinimumCornerAngle = this->MinimumCornerAngle;
  parameters.Order = this->Order;
  labelmesher::LabelImage image;
  std::array<double, 6> pixelToMesh{ 0, 1, 0, 0, 0, 1 };
  if (imageData &&
    !PlaceImage(imageData, this->GetInputArrayToProcess(0, inputVector), plane, image, pixelToMesh, parameters, error))
  {
    vtkErrorMacro(<< error);
    return 1;
  }

  if (imageData)
  {
    parameters.Image = { &image, pixelToMesh };
    parameters.Bounds.ImageToMesh = labelmesher::ResolveBound(this->ImageToMeshDistance, input, arrays::ImageToMeshDistance);
    parameters.Bounds.MeshToImage = labelmesher::ResolveBound(this->MeshToImageDistance, input, arrays::MeshToImageDistance);
  }

  // ---- (3) curve ----
  const double curveShare = imageData ? 0.8 : 1.0;
  labelmesher::CurvingResult result;
  try
  {
    result = labelmesher::CurveMesh(linear, parameters, labelmesher::ForwardProgress(this, 0.0, curveShare));
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

  if (this->MinimumCornerAngle > 0.0 && result.CornerAngleBound < this->MinimumCornerAngle)
  {
    vtkWarningMacro("The input mesh has an angle of " << result.CornerAngleBound << " degrees, below the corner angle "
                    << this->MinimumCornerAngle << " asked for: the curved cells keep " << result.CornerAngleBound
                    << " (field data CornerAngleBound).");
  }
  PackBezierCells(result, plane, this->Order, output);
  vtkFieldData* fd = output->GetFieldData();
  PassMaterialTable(input->GetFieldData(), fd);
  AddScalarField(fd, arrays::Smoothness, this->Smoothness);
  AddScalarField(fd, arrays::Tension, this->Tension);
  AddScalarField(fd, arrays::MaximumUntanglingSteps, this->MaximumUntanglingSteps);
  AddScalarField(fd, arrays::MaximumShorteningRounds, this->MaximumShorteningRounds);
  AddScalarField(fd, arrays::QualityIterations, this->QualityIterations);
  AddScalarField(fd, arrays::MinimumScaledJacobianBound, this->MinimumScaledJacobian);
  AddScalarField(fd, arrays::Order, this->Order);
  AddCurvingCounts(fd, result);

  // ---- (5) accuracy against the image ----
  if (imageData)
  {
    labelmesher::StageClock clock(result.Timings);
    this->SetProgressText("Measuring pixel accuracy");
    this->UpdateProgress(0.85);
    const labelmesher::PixelAccuracy linearAccuracy = labelmesher::MeasurePixelAccuracy(
      labelmesher::MakeStraightCurvedMesh(linear), image, pixelToMesh);
    const labelmesher::PixelAccuracy curvedAccuracy =
      labelmesher::MeasurePixelAccuracy(result.Mesh, image, pixelToMesh);
    AddAccuracy(fd, linearAccuracy, curvedAccuracy, image);
    clock.Finish("pixel accuracy");
    AddCurvedMeasurements(fd, labelmesher::MeasureCurvedMesh(image, result.Mesh, parameters.Image), parameters.Bounds);
    clock.Finish("curved distances");
  }
  labelmesher::AddStageTimings(fd, result.Timings);
  this->UpdateProgress(1.0);

  if (!result.Valid)
  {
    vtkErrorMacro(<< result.InvalidCells.size() << " of " << result.Mesh.Cells.size()
                  << " cells could not be proven valid after untangling with up to "
                  << this->MaximumUntanglingSteps
                  << " steps in " << result.UntanglingRounds
                  << " rounds of shortening; they are marked Valid = 0 in the output.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkBezierCurver::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Smoothness: C" << this->Smoothness << "\n";
  os << indent << "Order: " << this->Order << "\n";
  os << indent << "Tension: " << this->Tension << "\n";
  os << indent << "MaximumUntanglingSteps: " << this->MaximumUntanglingSteps << "\n";
  os << indent << "MaximumShorteningRounds: " << this->MaximumShorteningRounds << "\n";
  os << indent << "MinimumScaledJacobian: " << this->MinimumScaledJacobian << "\n";
  os << indent << "MinimumCornerAngle: " << this->MinimumCornerAngle << " degrees\n";
  os << indent << "QualityIterations: " << this->QualityIterations << "\n";
  os << indent << "ImageToMeshDistance: " << this->ImageToMeshDistance << " voxels (negative: the input's)\n";
  os << indent << "MeshToImageDistance: " << this->MeshToImageDistance << " voxels (negative: the input's)\n";
}
