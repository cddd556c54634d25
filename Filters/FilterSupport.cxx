// SPDX-License-Identifier: GPL-2.0-or-later
// Plumbing the LabelMesher filters share: progress, requests, cell arrays, field data.
#include "FilterSupport.h"

#include "Checks/MeshChecks.h"
#include "Decimation/MeshDecimator.h"
#include "LabelMesherArrayNames.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

namespace labelmesher
{

ProgressObserver ForwardProgress(vtkAlgorithm* algorithm, double start, double share)
{
  ProgressObserver observer;
  observer.Callback = [algorithm, start, share](const std::string& stage, double fraction) {
    algorithm->SetProgressText(stage.c_str());
    algorithm->UpdateProgress(start + share * std::clamp(fraction, 0.0, 1.0));
    return !algorithm->GetAbortExecute();
  };
  return observer;
}

vtkDataArray* MaterialArray(vtkUnstructuredGrid* mesh, std::string& error)
{
  vtkDataArray* materials = mesh->GetCellData()->GetArray(arrays::Material);
  if (!materials || materials->GetNumberOfComponents() != 1)
  {
    error = "Input mesh has no one-component cell array 'Material'.";
    return nullptr;
  }
  return materials;
}

bool GatherSimplices(vtkUnstructuredGrid* input, vtkDataArray* materials, int dimension, const PointPlacer& place,
  const std::string& why, SimplexMesh& mesh, std::string& error)
{
  mesh.Dimension = dimension;
  mesh.Points.resize(static_cast<std::size_t>(input->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < input->GetNumberOfPoints(); ++p)
  {
    if (!place(input->GetPoint(p), mesh.Points[static_cast<std::size_t>(p)], error))
      return false;
  }
  const int type = dimension == 3 ? VTK_TETRA : VTK_TRIANGLE;
  const int nv = dimension + 1;
  const vtkIdType cells = input->GetNumberOfCells();
  mesh.Connectivity.reserve(static_cast<std::size_t>(cells) * nv);
  mesh.Materials.reserve(static_cast<std::size_t>(cells));
  for (vtkIdType c = 0; c < cells; ++c)
  {
    if (input->GetCellType(c) != type)
    {
      error = "Input cell " + std::to_string(c) + " is not a " + (dimension == 3 ? "tetrahedron" : "triangle") +
        " (VTK type " + std::to_string(input->GetCellType(c)) + ")" + why;
      return false;
    }
    std::int32_t label;
    if (!CellMaterial(materials, c, label, error))
      return false;
    vtkIdType n;
    const vtkIdType* ids;
    input->GetCellPoints(c, n, ids);
    std::int64_t v[4] = { ids[0], ids[1], ids[2], dimension == 3 ? ids[3] : 0 };
    const Point3& a = mesh.Points[v[0]];
    const Point3& b = mesh.Points[v[1]];
    const Point3& d = mesh.Points[v[2]];
    double orientation;
    if (dimension == 2)
    {
      orientation = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
    }
    else
    {
      const Point3& e = mesh.Points[v[3]];
      const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
      const double w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
      const double z[3] = { e[0] - a[0], e[1] - a[1], e[2] - a[2] };
      orientation = u[0] * (w[1] * z[2] - w[2] * z[1]) - u[1] * (w[0] * z[2] - w[2] * z[0]) +
        u[2] * (w[0] * z[1] - w[1] * z[0]);
    }
    if (orientation < 0)
      std::swap(v[1], v[2]);
    mesh.Connectivity.insert(mesh.Connectivity.end(), v, v + nv);
    mesh.Materials.push_back(label);
  }
  return true;
}

bool CellMaterial(vtkDataArray* materials, vtkIdType c, std::int32_t& label, std::string& error)
{
  const double value = materials->GetComponent(c, 0);
  if (!(value >= 0 && value == std::floor(value) && value <= VTK_INT_MAX))
  {
    error = "Input cell " + std::to_string(c) + " has Material " + std::to_string(value) +
      ": expected a non-negative integer label.";
    return false;
  }
  label = static_cast<std::int32_t>(value);
  return true;
}

void RequestWholeImages(vtkInformationVector* port)
{
  for (int c = 0; c < port->GetNumberOfInformationObjects(); ++c)
  {
    vtkInformation* info = port->GetInformationObject(c);
    if (info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
      info->Set(vtkStreamingDemandDrivenPipeline::EXACT_EXTENT(), 1);
      // Under MPI the request is also piece P of N, which the image's producer turns into its
      // own slab of the extent (ParaView): the whole image is piece 0 of 1.
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      info->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    }
  }
}

vtkSmartPointer<vtkCellArray> MakeCellArray(
  const std::vector<std::int64_t>& connectivity, int verticesPerCell, bool swapSecondAndThird)
{
  const std::size_t cells = connectivity.size() / static_cast<std::size_t>(std::max(1, verticesPerCell));
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(cells + 1));
  for (std::size_t c = 0; c <= cells; ++c)
  {
    offsets->SetValue(static_cast<vtkIdType>(c), static_cast<vtkIdType>(c * verticesPerCell));
  }
  vtkNew<vtkIdTypeArray> ids;
  ids->SetNumberOfValues(static_cast<vtkIdType>(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), ids->GetPointer(0));
  if (swapSecondAndThird)
  {
    vtkIdType* id = ids->GetPointer(0);
    for (std::size_t c = 0; c < cells; ++c)
    {
      std::swap(id[c * verticesPerCell + 1], id[c * verticesPerCell + 2]);
    }
  }
  auto array = vtkSmartPointer<vtkCellArray>::New();
  array->SetData(offsets, ids);
  return array;
}

double ResolveBound(double set, vtkDataObject* input, const char* name)
{
  if (set >= 0.0)
    return set;
  vtkDataArray* recorded = input ? input->GetFieldData()->GetArray(name) : nullptr;
  return recorded && recorded->GetNumberOfTuples() > 0 ? recorded->GetComponent(0, 0) : -1.0;
}

double ClampToProvenAngleBounds(double degrees)
{
  return std::clamp(degrees, 0.0, std::max(ProvenAngleBound(2), ProvenAngleBound(3)));
}

void AddScalarField(vtkFieldData* fd, const char* name, double value)
{
  AddField<vtkDoubleArray>(fd, name, std::vector<double>{ value });
}

void PassMaterialTable(vtkFieldData* from, vtkFieldData* to)
{
  // The three arrays are one table: taken together from one source, or not at all.
  if (!from || !to || !from->GetAbstractArray(arrays::MaterialLabel))
  {
    return;
  }
  for (const char* name : { arrays::MaterialLabel, arrays::MaterialName, arrays::MaterialColor })
  {
    to->RemoveArray(name);
    if (vtkAbstractArray* array = from->GetAbstractArray(name))
    {
      to->AddArray(array);
    }
  }
}

void AddStageTimings(vtkFieldData* fd, const std::vector<StageTiming>& timings)
{
  std::vector<std::string> names;
  std::vector<double> seconds;
  for (const StageTiming& timing : timings)
  {
    names.push_back(timing.Stage);
    seconds.push_back(timing.Seconds);
  }
  AddField<vtkStringArray>(fd, arrays::StageName, names);
  AddField<vtkDoubleArray>(fd, arrays::StageSeconds, seconds);
}

void AddMeasurements(vtkFieldData* fd, const LabelImage& image, const SimplexMesh& mesh, double imageToMesh,
  double meshToImage, std::vector<StageTiming>& timings, const std::function<void(int checksDone)>& finished)
{
  // One stage per check, so that users see what the verification costs.
  StageClock clock(timings);
  int checksDone = 0;
  auto done = [&](const char* check) {
    clock.Finish(std::string("measure: ") + check);
    if (finished)
    {
      finished(++checksDone);
    }
  };

  const QualityReport quality = MeasureQuality(mesh);
  AddScalarField(fd, arrays::MinimumAngle, quality.MinimumAngle);
  AddScalarField(fd, arrays::MaximumAngle, quality.MaximumAngle);
  AddScalarField(fd, arrays::InvertedCells, static_cast<double>(quality.InvertedCells));
  done("angles");

  const ConformityReport conformity = MeasureConformity(mesh);
  AddScalarField(fd, arrays::OverSharedFaces, static_cast<double>(conformity.OverSharedFaces));
  AddScalarField(fd, arrays::HangingVertices, static_cast<double>(conformity.HangingVertices));
  AddScalarField(fd, arrays::NonManifoldBoundaryEdges, static_cast<double>(conformity.NonManifoldBoundaryEdges));
  done("conformity");

  HausdorffReport distances = MeasureHausdorff(image, mesh);
  bool above = distances.Overall.ImageToMesh > imageToMesh || distances.Overall.MeshToImage > meshToImage;
  for (const auto& entry : distances.PerMaterial)
    above = above || entry.second.ImageToMesh > imageToMesh || entry.second.MeshToImage > meshToImage;
  const bool certified = !above || WithinHausdorff(image, mesh, imageToMesh, meshToImage);
  if (above && certified)
  {
    distances.Overall.ImageToMesh = std::min(distances.Overall.ImageToMesh, imageToMesh);
    distances.Overall.MeshToImage = std::min(distances.Overall.MeshToImage, meshToImage);
  }
  AddScalarField(fd, arrays::MeasuredImageToMeshDistance, distances.Overall.ImageToMesh);
  AddScalarField(fd, arrays::MeasuredMeshToImageDistance, distances.Overall.MeshToImage);
  AddScalarField(fd, arrays::HausdorffBoundsCertified, certified ? 1.0 : 0.0);
  done("distances");

  std::vector<int> material, imageComponents, imageEuler, meshComponents, meshEuler, matches;
  for (const auto& [label, comparison] : CompareTopology(image, mesh))
  {
    material.push_back(label);
    imageComponents.push_back(static_cast<int>(comparison.Image.Components));
    imageEuler.push_back(static_cast<int>(comparison.Image.EulerCharacteristic));
    meshComponents.push_back(static_cast<int>(comparison.Mesh.Components));
    meshEuler.push_back(static_cast<int>(comparison.Mesh.EulerCharacteristic));
    matches.push_back(comparison.Matches() ? 1 : 0);
  }
  AddField<vtkIntArray>(fd, arrays::TopologyMaterial, material);
  AddField<vtkIntArray>(fd, arrays::ImageComponents, imageComponents);
  AddField<vtkIntArray>(fd, arrays::ImageEulerCharacteristic, imageEuler);
  AddField<vtkIntArray>(fd, arrays::MeshComponents, meshComponents);
  AddField<vtkIntArray>(fd, arrays::MeshEulerCharacteristic, meshEuler);
  AddField<vtkIntArray>(fd, arrays::TopologyMatches, matches);
  done("topology");
}

vtkSmartPointer<vtkPoints> PhysicalPoints(const std::vector<Point3>& points, const ImagePlacement& placement)
{
  auto physical = vtkSmartPointer<vtkPoints>::New();
  physical->SetDataTypeToDouble();
  physical->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    physical->SetPoint(static_cast<vtkIdType>(p), placement.ToPhysical(points[p]).data());
  }
  return physical;
}

void PackVolumeMesh(const SimplexMesh& mesh, const ImagePlacement& placement, vtkUnstructuredGrid* output)
{
  const int nv = mesh.VerticesPerCell();
  output->SetPoints(PhysicalPoints(mesh.Points, placement));
  output->SetCells(mesh.Dimension == 3 ? VTK_TETRA : VTK_TRIANGLE,
    MakeCellArray(mesh.Connectivity, nv, mesh.Dimension == 3 && placement.ReversesOrientation()));
  vtkNew<vtkIntArray> material;
  material->SetName(arrays::Material);
  material->SetNumberOfValues(static_cast<vtkIdType>(mesh.NumberOfCells()));
  std::copy(mesh.Materials.begin(), mesh.Materials.end(), material->GetPointer(0));
  output->GetCellData()->SetScalars(material);
}

void PackInterfaces(const SimplexMesh& faces, const std::vector<std::pair<std::int32_t, std::int32_t>>& sides,
  const ImagePlacement& placement, vtkPolyData* output)
{
  // The faces share the volume mesh's points; keep only those they use, so
  // that the polydata has no stray points (numbered in first-use order).
  std::vector<std::int64_t> renumber(faces.Points.size(), -1);
  std::vector<Point3> used;
  std::vector<std::int64_t> connectivity(faces.Connectivity.size());
  for (std::size_t i = 0; i < faces.Connectivity.size(); ++i)
  {
    std::int64_t& id = renumber[static_cast<std::size_t>(faces.Connectivity[i])];
    if (id < 0)
    {
      id = static_cast<std::int64_t>(used.size());
      used.push_back(faces.Points[static_cast<std::size_t>(faces.Connectivity[i])]);
    }
    connectivity[i] = id;
  }
  output->SetPoints(PhysicalPoints(used, placement));
  // A facet of a d-simplex has d vertices; the faces' mesh has Dimension d - 1.
  const int facetVertices = faces.Dimension + 1;
  auto cells = MakeCellArray(connectivity, facetVertices);
  if (facetVertices == 3)
  {
    output->SetPolys(cells);
  }
  else
  {
    output->SetLines(cells);
  }
  vtkNew<vtkIntArray> materials;
  materials->SetName(arrays::Materials);
  materials->SetNumberOfComponents(2);
  materials->SetNumberOfTuples(cells->GetNumberOfCells());
  for (vtkIdType f = 0; f < cells->GetNumberOfCells() && f < static_cast<vtkIdType>(sides.size()); ++f)
  {
    materials->SetTypedComponent(f, 0, sides[static_cast<std::size_t>(f)].first);
    materials->SetTypedComponent(f, 1, sides[static_cast<std::size_t>(f)].second);
  }
  output->GetCellData()->AddArray(materials);
}

void AddDecimationFields(vtkFieldData* fd, const DecimationParameters& parameters, const DecimationCounts& counts,
  std::size_t keptBefore, std::size_t keptAfter)
{
  AddScalarField(fd, arrays::AngleBound, parameters.MinimumAngle);
  AddScalarField(fd, arrays::ImageToMeshDistance, parameters.ImageToMeshDistance);
  AddScalarField(fd, arrays::MeshToImageDistance, parameters.MeshToImageDistance);
  AddScalarField(fd, arrays::CellsBefore, static_cast<double>(keptBefore));
  AddScalarField(fd, arrays::CellsAfter, static_cast<double>(keptAfter));
  AddScalarField(fd, arrays::Merges, static_cast<double>(counts.Merges));
  AddScalarField(fd, arrays::MergeOffers, static_cast<double>(counts.Offers));
  AddScalarField(fd, arrays::MergesRejectedByQuality, static_cast<double>(counts.RejectedByQuality));
  AddScalarField(fd, arrays::MergesRejectedByTopology, static_cast<double>(counts.RejectedByTopology));
  AddScalarField(fd, arrays::MergesRejectedByFidelity, static_cast<double>(counts.RejectedByFidelity));
  AddScalarField(fd, arrays::VerticesRelocated, static_cast<double>(counts.Relocations));
  AddScalarField(fd, arrays::FrozenVertices, static_cast<double>(counts.FrozenVertices));
}

} // namespace labelmesher
