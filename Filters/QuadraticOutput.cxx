// SPDX-License-Identifier: GPL-2.0-or-later
// The quadratic mesh as a vtkUnstructuredGrid, its counts and its measurements.
#include "QuadraticOutput.h"

#include "Checks/QuadraticVolume.h"
#include "FilterSupport.h"
#include "LabelMesherArrayNames.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <limits>

namespace labelmesher
{
void PackQuadraticMesh(
  const QuadraticResult& result, bool includeBackground, const ImagePlacement& placement, vtkUnstructuredGrid* output)
{
  const QuadraticMesh& mesh = result.Mesh;
  const SimplexMesh& linear = mesh.Linear;
  // Points: the kept cells' corners, then their edges' mid-nodes, numbered in first-use order.
  std::vector<std::int64_t> cornerId(linear.Points.size(), -1), edgeId(mesh.Edges.size(), -1);
  std::vector<Point3> points;
  std::vector<std::int64_t> connectivity;
  std::vector<std::size_t> kept;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    if (!includeBackground && linear.Materials[c] == 0)
      continue;
    kept.push_back(c);
    const std::int64_t* v = linear.Cell(c);
    for (int k = 0; k < 4; ++k)
    {
      std::int64_t& id = cornerId[static_cast<std::size_t>(v[k])];
      if (id < 0)
      {
        id = static_cast<std::int64_t>(points.size());
        points.push_back(linear.Points[static_cast<std::size_t>(v[k])]);
      }
      connectivity.push_back(id);
    }
    for (int e = 0; e < 6; ++e)
    {
      const auto edge = static_cast<std::size_t>(mesh.CellEdges[c * 6 + e]);
      if (edgeId[edge] < 0)
      {
        edgeId[edge] = static_cast<std::int64_t>(points.size());
        points.push_back(mesh.MidNode(edge));
      }
      connectivity.push_back(edgeId[edge]);
    }
  }
  if (placement.ReversesOrientation())
  {
    // Corners 1 and 2 swap; so do edges 0-1 and 2-0, and 1-3 and 2-3 (VTK's edge order).
    for (std::size_t c = 0; c < kept.size(); ++c)
    {
      std::int64_t* n = connectivity.data() + c * 10;
      std::swap(n[1], n[2]);
      std::swap(n[4], n[6]);
      std::swap(n[8], n[9]);
    }
  }
  output->SetPoints(PhysicalPoints(points, placement));
  vtkNew<vtkIdTypeArray> offsets, ids;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(kept.size() + 1));
  for (std::size_t c = 0; c <= kept.size(); ++c)
    offsets->SetValue(static_cast<vtkIdType>(c), static_cast<vtkIdType>(c * 10));
  ids->SetNumberOfValues(static_cast<vtkIdType>(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), ids->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, ids);
  output->SetCells(VTK_QUADRATIC_TETRA, cells);
  vtkNew<vtkIntArray> material;
  material->SetName(arrays::Material);
  vtkNew<vtkDoubleArray> jacobian, corner;
  jacobian->SetName(arrays::ScaledJacobian);
  corner->SetName(arrays::CornerAngle);
  for (std::size_t c : kept)
  {
    material->InsertNextValue(linear.Materials[c]);
    jacobian->InsertNextValue(result.ScaledJacobian[c]);
    corner->InsertNextValue(result.CornerAngle.empty() ? 180.0 : result.CornerAngle[c]);
  }
  output->GetCellData()->SetScalars(material);
  output->GetCellData()->AddArray(jacobian);
  output->GetCellData()->AddArray(corner);
}

void AddQuadraticFields(vtkFieldData* fd, const QuadraticResult& result, double minimumScaledJacobian)
{
  AddScalarField(fd, arrays::Order, 2.0);
  AddScalarField(fd, arrays::MinimumScaledJacobianBound, minimumScaledJacobian);
  const double certified = result.ScaledJacobian.empty()
    ? 1.0
    : *std::min_element(result.ScaledJacobian.begin(), result.ScaledJacobian.end());
  AddScalarField(fd, arrays::CertifiedMinimumScaledJacobian, certified);
  AddScalarField(fd, arrays::FittedEdges, static_cast<double>(result.FittedEdges));
  AddScalarField(fd, arrays::CurvedEdges, static_cast<double>(result.CurvedEdges));
  AddScalarField(fd, arrays::PulledBackEdges, static_cast<double>(result.ShortenedEdges));
  AddScalarField(fd, arrays::CellsFailedScaledJacobian, static_cast<double>(result.CellsFailedQuality));
  AddScalarField(fd, arrays::FacesFailedDistance, static_cast<double>(result.FacesFailedDistance));
  AddScalarField(fd, arrays::CornerAngleBound, result.CornerAngleBound);
  AddScalarField(fd, arrays::CertifiedMinimumCornerAngle,
    result.CornerAngle.empty() ? 180.0 : *std::min_element(result.CornerAngle.begin(), result.CornerAngle.end()));
  AddScalarField(fd, arrays::CellsFailedCornerAngle, static_cast<double>(result.CellsFailedCornerAngle));
  AddScalarField(fd, arrays::CertificationRounds, static_cast<double>(result.Rounds));
  AddScalarField(fd, arrays::UntangledEdges, static_cast<double>(result.UntangledEdges));
  AddScalarField(fd, arrays::PinnedEdges, static_cast<double>(result.PinnedEdges));
}

void AddQuadraticMeasurements(vtkFieldData* fd, const LabelImage& image, const QuadraticResult& result)
{
  constexpr int kFacetSteps = 8, kAccuracySteps = 4, kJacobianSteps = 4;
  const QuadraticMesh& mesh = result.Mesh;
  const HausdorffReport distances = MeasureHausdorff(image, CurvedBoundaryFacets(mesh, kFacetSteps));
  AddScalarField(fd, arrays::MeasuredImageToMeshDistance, distances.Overall.ImageToMesh);
  AddScalarField(fd, arrays::MeasuredMeshToImageDistance, distances.Overall.MeshToImage);
  AddScalarField(fd, arrays::CurvedMeasureResolution, RefinementTolerance(mesh, kFacetSteps) + 1.0 / 1024.0);
  double sampled = 1.0, corner = 180.0;
  for (std::size_t c = 0; c < mesh.NumberOfCells(); ++c)
  {
    const std::array<Point3, 10> nodes = mesh.Nodes(c);
    corner = std::min(corner, MeasuredCornerAngle(nodes));
    if (mesh.CellIsCurved(c))
    {
      double smallest = 0.0;
      sampled = std::min(sampled, SampledScaledJacobian(nodes, kJacobianSteps, smallest));
    }
  }
  AddScalarField(fd, arrays::SampledMinimumScaledJacobian, sampled);
  AddScalarField(fd, arrays::MeasuredMinimumCornerAngle, corner);
  AddScalarField(fd, arrays::Voxels, static_cast<double>(image.NumberOfVoxels()));
  AddScalarField(fd, arrays::MisclassifiedVoxelsLinear,
    static_cast<double>(MeasureVoxelAccuracy(image, mesh.Linear).Misclassified));
  AddScalarField(fd, arrays::MisclassifiedVoxelsQuadratic,
    static_cast<double>(MeasureVoxelAccuracy(image, mesh, kAccuracySteps).Misclassified));
}

} // namespace labelmesher
