// SPDX-License-Identifier: GPL-2.0-or-later
// The quadratic mesh's part of the run report: gathered from its field data, printed, in JSON.
#include "QuadraticReport.h"

#include "LabelMesherArrayNames.h"
#include "JsonWriter.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>

namespace labelmesher
{
namespace report
{

void AddQuadratic(RunReport& report, vtkUnstructuredGrid* quadratic)
{
  if (!quadratic || quadratic->GetNumberOfCells() == 0)
    return;
  vtkFieldData* fd = quadratic->GetFieldData();
  // Quadratic triangles (a 2D image's Order 2) are the curver's and have its report.
  if (FieldCount(fd, arrays::Order) != 2 || quadratic->GetCellType(0) != VTK_QUADRATIC_TETRA)
    return;
  QuadraticEntry q;
  q.Cells = quadratic->GetNumberOfCells();
  q.Points = quadratic->GetNumberOfPoints();
  q.FittedEdges = FieldCount(fd, arrays::FittedEdges);
  q.CurvedEdges = FieldCount(fd, arrays::CurvedEdges);
  q.PulledBackEdges = FieldCount(fd, arrays::PulledBackEdges);
  q.CellsFailedScaledJacobian = FieldCount(fd, arrays::CellsFailedScaledJacobian);
  q.FacesFailedDistance = FieldCount(fd, arrays::FacesFailedDistance);
  q.Rounds = FieldCount(fd, arrays::CertificationRounds);
  q.UntangledEdges = FieldCount(fd, arrays::UntangledEdges);
  q.PinnedEdges = FieldCount(fd, arrays::PinnedEdges);
  q.ScaledJacobianBound = FieldValue(fd, arrays::MinimumScaledJacobianBound).value_or(0.0);
  q.CertifiedMinimumScaledJacobian = FieldValue(fd, arrays::CertifiedMinimumScaledJacobian).value_or(0.0);
  q.SampledMinimumScaledJacobian = FieldValue(fd, arrays::SampledMinimumScaledJacobian);
  q.CornerAngleBound = FieldValue(fd, arrays::CornerAngleBound).value_or(0.0);
  q.MinimumCornerAngle = FieldValue(fd, arrays::CertifiedMinimumCornerAngle).value_or(0.0);
  q.CellsFailedCornerAngle = FieldCount(fd, arrays::CellsFailedCornerAngle);
  q.MeasuredMinimumCornerAngle = FieldValue(fd, arrays::MeasuredMinimumCornerAngle);
  q.MeasuredImageToMesh = FieldValue(fd, arrays::MeasuredImageToMeshDistance);
  q.MeasuredMeshToImage = FieldValue(fd, arrays::MeasuredMeshToImageDistance);
  q.MeasureResolution = FieldValue(fd, arrays::CurvedMeasureResolution);
  q.Voxels = FieldValue(fd, arrays::Voxels);
  q.MisclassifiedLinear = FieldValue(fd, arrays::MisclassifiedVoxelsLinear);
  q.MisclassifiedQuadratic = FieldValue(fd, arrays::MisclassifiedVoxelsQuadratic);
  if (vtkDataArray* scaled = quadratic->GetCellData()->GetArray(arrays::ScaledJacobian))
    for (vtkIdType c = 0; c < scaled->GetNumberOfTuples(); ++c)
    {
      const double s = scaled->GetComponent(c, 0);
      ++q.ScaledJacobianHistogram[static_cast<std::size_t>(JacobianHistogramBin(s, s > 0.0))];
    }
  report.Quadratic = q;
}

bool QuadraticHolds(const RunReport& report)
{
  if (!report.Quadratic)
    return true;
  const QuadraticEntry& q = *report.Quadratic;
  const bool certified = q.CertifiedMinimumScaledJacobian > 0.0 && q.CertifiedMinimumScaledJacobian >= q.ScaledJacobianBound;
  const bool sampled = !q.SampledMinimumScaledJacobian || *q.SampledMinimumScaledJacobian >= q.ScaledJacobianBound;
  const double slack = q.MeasureResolution.value_or(0.0) + 1e-9;
  const bool distances = !q.MeasuredImageToMesh ||
    (*q.MeasuredImageToMesh <= report.ImageToMeshBound + slack && *q.MeasuredMeshToImage <= report.MeshToImageBound + slack);
  // The measured corners come from differences of points: a little round-off more.
  // The curver's bound itself must be the decimator's angle (or the linear mesh's smallest, if
  // smaller): a curver that lowered it would pass its own test.
  const double asked = std::min(AngleBoundOf(report), report.MinimumAngle.value_or(AngleBoundOf(report)));
  const bool corners = q.CornerAngleBound >= asked - 1e-9 &&
    (q.MinimumCornerAngle >= q.CornerAngleBound - 1e-9 &&
      (!q.MeasuredMinimumCornerAngle || *q.MeasuredMinimumCornerAngle >= q.CornerAngleBound - 1e-6));
  return certified && sampled && distances && corners;
}

void PrintQuadraticSummary(const RunReport& report, std::ostream& out)
{
  if (!report.Quadratic)
    return;
  const QuadraticEntry& q = *report.Quadratic;
  out << "Quadratic mesh: " << q.Cells << " quadratic tetrahedra, " << q.Points << " nodes; " << q.CurvedEdges
      << " curved interface edges (" << q.FittedEdges << " fitted, " << q.PulledBackEdges << " pulled back), "
      << q.UntangledEdges << " interior edges moved by elasticity; " << q.Rounds << " rounds\n";
  out << "  scaled Jacobian (min det J / max det J) >= " << FormatFixed(q.CertifiedMinimumScaledJacobian, 3)
      << " certified over every cell of the box, background included (bound " << FormatFixed(q.ScaledJacobianBound, 3)
      << ")";
  if (q.SampledMinimumScaledJacobian)
    out << ", " << FormatFixed(*q.SampledMinimumScaledJacobian, 3) << " sampled";
  out << "; certified lower bounds of the cells written:\n";
  PrintJacobianHistogram(q.ScaledJacobianHistogram, out);
  if (q.CornerAngleBound > 0.0)
  {
    out << "  corner angles (dihedral, between edge tangents): smallest " << FormatFixed(q.MinimumCornerAngle, 2);
    if (q.MeasuredMinimumCornerAngle)
      out << " (" << FormatFixed(*q.MeasuredMinimumCornerAngle, 2) << " measured)";
    out << " deg, bound " << FormatFixed(q.CornerAngleBound, 2) << "; " << q.CellsFailedCornerAngle
        << " cells had corners pulled back\n";
  }
  if (q.MeasuredImageToMesh)
    out << "  curved interfaces: h(I,M) " << FormatFixed(*q.MeasuredImageToMesh, 3) << ", h(M,I) "
        << FormatFixed(*q.MeasuredMeshToImage, 3) << " voxels measured (bounds " << FormatFixed(report.ImageToMeshBound, 3)
        << " / " << FormatFixed(report.MeshToImageBound, 3) << ", resolution " << FormatFixed(q.MeasureResolution.value_or(0), 4)
        << ")\n";
  if (q.MisclassifiedLinear && q.MisclassifiedQuadratic && q.Voxels)
  {
    out << "  misclassified voxels (of " << static_cast<long long>(*q.Voxels) << "): linear "
        << static_cast<long long>(*q.MisclassifiedLinear) << ", quadratic "
        << static_cast<long long>(*q.MisclassifiedQuadratic);
    if (*q.MisclassifiedLinear > 0)
      out << " (" << FormatFixed(100.0 * (*q.MisclassifiedQuadratic - *q.MisclassifiedLinear) / *q.MisclassifiedLinear, 1)
          << " %)";
    out << "\n";
  }
}

void WriteQuadraticJson(const RunReport& report, JsonWriter& j)
{
  j.Key("quadratic");
  if (!report.Quadratic)
  {
    j.Null();
    return;
  }
  const QuadraticEntry& q = *report.Quadratic;
  auto optional = [&](const char* key, const std::optional<double>& value) {
    j.Key(key);
    if (value)
      j.Number(*value);
    else
      j.Null();
  };
  j.BeginObject();
  j.Key("cells").Integer(q.Cells);
  j.Key("nodes").Integer(q.Points);
  j.Key("fitted_edges").Integer(q.FittedEdges);
  j.Key("curved_edges").Integer(q.CurvedEdges);
  j.Key("pulled_back_edges").Integer(q.PulledBackEdges);
  j.Key("cells_failed_scaled_jacobian").Integer(q.CellsFailedScaledJacobian);
  j.Key("faces_failed_distance").Integer(q.FacesFailedDistance);
  j.Key("certification_rounds").Integer(q.Rounds);
  j.Key("untangled_interior_edges").Integer(q.UntangledEdges);
  j.Key("pinned_interior_edges").Integer(q.PinnedEdges);
  j.Key("scaled_jacobian_bound").Number(q.ScaledJacobianBound);
  j.Key("certified_minimum_scaled_jacobian").Number(q.CertifiedMinimumScaledJacobian);
  j.Key("scaled_jacobian_histogram");
  WriteJacobianHistogramJson(q.ScaledJacobianHistogram, j);
  optional("sampled_minimum_scaled_jacobian", q.SampledMinimumScaledJacobian);
  j.Key("corner_angle_bound_degrees").Number(q.CornerAngleBound);
  j.Key("minimum_corner_angle_degrees").Number(q.MinimumCornerAngle);
  optional("measured_minimum_corner_angle_degrees", q.MeasuredMinimumCornerAngle);
  j.Key("cells_failed_corner_angle").Integer(q.CellsFailedCornerAngle);
  optional("measured_image_to_mesh", q.MeasuredImageToMesh);
  optional("measured_mesh_to_image", q.MeasuredMeshToImage);
  optional("measure_resolution", q.MeasureResolution);
  optional("voxels", q.Voxels);
  optional("misclassified_linear", q.MisclassifiedLinear);
  optional("misclassified_quadratic", q.MisclassifiedQuadratic);
  j.Key("guarantees_hold").Bool(QuadraticHolds(report));
  j.EndObject();
}

} // namespace report
} // namespace labelmesher
