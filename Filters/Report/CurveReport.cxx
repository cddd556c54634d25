// SPDX-License-Identifier: GPL-2.0-or-later
// Gathers what a curving run (`labelmesher curve`) produced from vtkBezierCurver's output and prints it or writes it
// as JSON.
#include "CurveReport.h"

#include "JsonWriter.h"

#include "LabelMesherArrayNames.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <string>
#include <cmath>
#include <cstdio>
#include <iomanip>

namespace labelmesher
{
namespace report
{
namespace arrays = labelmesher::arrays;
namespace
{

std::string Percent(long long part, long long whole)
{
  return whole > 0 ? FormatFixed(100.0 * static_cast<double>(part) / static_cast<double>(whole), 3) + " %"
                   : "-";
}

std::optional<double> Bound(vtkFieldData* fd, const char* name)
{
  const auto value = FieldValue(fd, name);
  return value && *value >= 0.0 ? value : std::nullopt;
}

} // namespace

bool CurveReport::CurvesFaithful() const
{
  // The measured figures may exceed the true distances by the measure's resolution. A bound kept
  // (the image was given) must be measured to count as kept, and so must the crossings and the
  // topology: what was not measured is not claimed (as the Slicer module's report does).
  const double resolution = this->CurveResolution.value_or(0.0) + 1e-9;
  auto within = [resolution](const std::optional<double>& measured, const std::optional<double>& bound) {
    return !bound || (measured && *measured <= *bound + resolution);
  };
  return within(this->MeasuredImageToMesh, this->ImageToMeshBound) &&
    within(this->MeasuredMeshToImage, this->MeshToImageBound) && this->InterfaceCrossings &&
    *this->InterfaceCrossings == 0 && this->TopologyMatches && *this->TopologyMatches;
}

CurveReport MakeCurveReport(const RunReport& linear, vtkUnstructuredGrid* curved)
{
  CurveReport r;
  r.Linear = linear;
  r.Cells = curved->GetNumberOfCells();
  r.ControlPoints = curved->GetNumberOfPoints();
  vtkFieldData* fd = curved->GetFieldData();
  r.Order = FieldValue(fd, arrays::Order).value_or(3.0) == 2.0 ? 2 : 3;
  r.Smoothness = static_cast<int>(FieldCount(fd, arrays::Smoothness));
  r.Tension = FieldValue(fd, arrays::Tension).value_or(0.0);
  r.MaximumUntanglingSteps = static_cast<int>(FieldCount(fd, arrays::MaximumUntanglingSteps));
  r.MaximumShorteningRounds = static_cast<int>(FieldCount(fd, arrays::MaximumShorteningRounds));
  r.QualityIterations = static_cast<int>(FieldCount(fd, arrays::QualityIterations));
  r.ScaledJacobianBound = FieldValue(fd, arrays::MinimumScaledJacobianBound).value_or(0.0);
  r.CellsBelowScaledJacobian = FieldCount(fd, arrays::CellsBelowScaledJacobian);
  r.StraightenedForScaledJacobian = FieldCount(fd, arrays::StraightenedForScaledJacobian) != 0;
  r.CornerAngleBound = FieldValue(fd, arrays::CornerAngleBound).value_or(0.0);
  r.CellsBelowCornerAngle = FieldCount(fd, arrays::CellsBelowCornerAngle);
  r.StraightenedForCornerAngle = FieldCount(fd, arrays::StraightenedForCornerAngle) != 0;
  r.StraightenedForValidity = FieldCount(fd, arrays::StraightenedForValidity) != 0;
  r.InvalidBeforeUntangling = FieldCount(fd, arrays::InvalidBeforeUntangling);
  r.InvalidCells = FieldCount(fd, arrays::InvalidCells);
  r.ValidityMeasured = fd->GetArray(arrays::InvalidCells) != nullptr;
  r.UntanglingSteps = FieldCount(fd, arrays::UntanglingSteps);
  r.InterfaceChains = FieldCount(fd, arrays::InterfaceChains);
  r.ClosedInterfaceChains = FieldCount(fd, arrays::ClosedInterfaceChains);
  r.CurvedEdges = FieldCount(fd, arrays::CurvedEdges);
  r.SplitEars = FieldCount(fd, arrays::SplitEars);
  r.EarCorners = FieldCount(fd, arrays::EarCorners);
  r.ShortenedPieces = FieldCount(fd, arrays::ShortenedPieces);
  r.StraightenedPieces = FieldCount(fd, arrays::StraightenedPieces);
  r.PiecesShortenedForBounds = FieldCount(fd, arrays::PiecesShortenedForBounds);
  r.PiecesShortenedForValidity = FieldCount(fd, arrays::PiecesShortenedForValidity);
  r.UncertifiedPieces = FieldCount(fd, arrays::UncertifiedPieces);
  r.UntanglingRounds = FieldCount(fd, arrays::UntanglingRounds);
  r.ImageToMeshBound = Bound(fd, arrays::ImageToMeshDistance);
  r.MeshToImageBound = Bound(fd, arrays::MeshToImageDistance);
  r.CurveResolution = FieldValue(fd, arrays::CurvedMeasureResolution);
  r.MeasuredImageToMesh = FieldValue(fd, arrays::MeasuredImageToMeshDistance);
  r.MeasuredMeshToImage = FieldValue(fd, arrays::MeasuredMeshToImageDistance);
  if (const auto crossings = FieldValue(fd, arrays::InterfaceCrossings))
    r.InterfaceCrossings = static_cast<long long>(*crossings);
  if (const auto topology = FieldValue(fd, arrays::TopologyMatches))
    r.TopologyMatches = *topology != 0.0;

  vtkDataArray* scaled = curved->GetCellData()->GetArray(arrays::ScaledJacobian);
  vtkDataArray* minimum = curved->GetCellData()->GetArray(arrays::MinimumJacobian);
  vtkDataArray* valid = curved->GetCellData()->GetArray(arrays::Valid);
  if (vtkDataArray* corners = curved->GetCellData()->GetArray(arrays::CornerAngle))
  {
    for (vtkIdType c = 0; c < corners->GetNumberOfTuples(); ++c)
      r.MinimumCornerAngle = std::min(r.MinimumCornerAngle.value_or(180.0), corners->GetComponent(c, 0));
  }
  r.MinimumScaledJacobian = r.Cells > 0 ? 1.0 : 0.0;
  r.MinimumJacobian = r.Cells > 0 ? HUGE_VAL : 0.0;
  for (vtkIdType c = 0; scaled && minimum && valid && c < r.Cells; ++c)
  {
    const double s = scaled->GetComponent(c, 0);
    r.MinimumScaledJacobian = std::min(r.MinimumScaledJacobian, s);
    r.MinimumJacobian = std::min(r.MinimumJacobian, minimum->GetComponent(c, 0));
    // A cell proven valid by its control net may have a non-positive subdivided
    // bound; the histogram's first bin is for cells not proven valid.
    ++r.ScaledJacobianHistogram[static_cast<std::size_t>(JacobianHistogramBin(s, valid->GetComponent(c, 0) != 0.0))];
  }

  r.HasAccuracy = fd->GetArray(arrays::MisclassifiedPixelsLinear) != nullptr;
  if (r.HasAccuracy)
  {
    r.Pixels = FieldCount(fd, arrays::Pixels);
    r.MisclassifiedLinear = FieldCount(fd, arrays::MisclassifiedPixelsLinear);
    r.MisclassifiedCurved = FieldCount(fd, arrays::MisclassifiedPixelsCurved);
    if (vtkDataArray* materials = fd->GetArray(arrays::AccuracyMaterial))
    {
      for (vtkIdType t = 0; t < materials->GetNumberOfTuples(); ++t)
      {
        auto& entry = r.AccuracyPerMaterial[static_cast<int>(materials->GetComponent(t, 0))];
        entry.first = { FieldCount(fd, arrays::MissedPixelsLinear, t), FieldCount(fd, arrays::ClaimedPixelsLinear, t) };
        entry.second = { FieldCount(fd, arrays::MissedPixelsCurved, t), FieldCount(fd, arrays::ClaimedPixelsCurved, t) };
      }
    }
  }
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray(arrays::StageName));
  vtkDataArray* seconds = fd->GetArray(arrays::StageSeconds);
  for (vtkIdType s = 0; names && seconds && s < names->GetNumberOfValues(); ++s)
  {
    r.Timings.emplace_back(names->GetValue(s), seconds->GetComponent(s, 0));
  }
  return r;
}

RunReports MakeRunReports(const RunContext& context, vtkImageData* image, vtkUnstructuredGrid* mesh,
  vtkUnstructuredGrid* curved)
{
  RunReports reports;
  RunReport& linear = reports.Linear;
  linear = MakeReport(context.Input, image, mesh);
  linear.Outputs = context.Outputs;
  linear.Notes = context.Notes;
  linear.StartMemory = context.StartMemory;
  linear.PeakMemory = context.PeakMemory;
  linear.Timings.insert(linear.Timings.begin(), context.TimingsBefore.begin(), context.TimingsBefore.end());
  AddQuadratic(linear, curved);
  if (!curved || curved->GetNumberOfCells() == 0 || linear.Quadratic)
  {
    linear.Timings.insert(linear.Timings.end(), context.TimingsAfter.begin(), context.TimingsAfter.end());
    return reports;
  }
  reports.Curved = MakeCurveReport(linear, curved);
  auto& timings = reports.Curved->Timings;
  timings.insert(timings.end(), context.TimingsAfter.begin(), context.TimingsAfter.end());
  return reports;
}

void PrintCurveSummary(const CurveReport& r, std::ostream& out)
{
  PrintSummary(r.Linear, out);
  out << "Curved mesh: " << r.Cells << (r.Order == 2 ? " quadratic triangles, " : " cubic Bezier triangles, ")
      << r.ControlPoints << (r.Order == 2 ? " nodes, " : " control points, C" + std::to_string(r.Smoothness))
      << (r.Order == 2 ? "quadratic boundaries" : " boundaries") << " (" << r.InterfaceChains
      << " chains, " << r.ClosedInterfaceChains << " closed, " << r.CurvedEdges
      << " curved edges, " << r.SplitEars << " ears split, " << r.EarCorners << " corners at ears)\n";
  out << "Validity: " << (r.Valid() ? "every cell proven valid" : "INVALID CELLS REMAIN") << " ("
      << r.InvalidBeforeUntangling << " invalid before untangling, " << r.InvalidCells
      << " after; " << r.UntanglingSteps << " load steps"
      << (r.StraightenedForValidity ? "; every curve made straight after the rounds" : "") << ")\n";
  out << "Pieces shortened: " << r.ShortenedPieces << " of " << r.CurvedEdges << " (" << r.StraightenedPieces
      << " straight; " << r.PiecesShortenedForBounds << " for the distance bounds, " << r.PiecesShortenedForValidity
      << " for validity and the scaled Jacobian; " << r.UntanglingRounds << " untangling rounds)\n";
  if (r.MinimumCornerAngle)
  {
    out << "Corner angles (between edge tangents): ";
    if (r.CornerAngleBound > 0.0)
      out << "every cell " << (r.CornerAnglesHold() ? "at least " : "NOT at least ") << FormatFixed(r.CornerAngleBound, 2)
          << " deg (smallest " << FormatFixed(*r.MinimumCornerAngle, 2) << ")"
          << (r.StraightenedForCornerAngle ? "; every curve made straight to reach it" : "") << "\n";
    else
      out << "smallest " << FormatFixed(*r.MinimumCornerAngle, 2) << " deg (the linear mesh's bound "
          << FormatFixed(AngleBoundOf(r.Linear), 2) << " deg; not kept: no corner bound asked)\n";
  }
  out << "Scaled Jacobian: every cell " << (r.ScaledJacobianHolds() ? "at least " : "NOT at least ")
      << FormatFixed(r.ScaledJacobianBound, 3) << " (certified; smallest " << FormatFixed(r.MinimumScaledJacobian, 4)
      << ")" << (r.StraightenedForScaledJacobian ? "; every curve made straight to reach it" : "") << "\n";
  if (r.MeasuredImageToMesh && r.MeasuredMeshToImage)
  {
    auto bound = [](const std::optional<double>& b) { return b ? FormatFixed(*b, 3) : std::string("none"); };
    out << "Curves: h(I,M) " << FormatFixed(*r.MeasuredImageToMesh, 4) << " (bound " << bound(r.ImageToMeshBound)
        << ", linear " << (r.Linear.MeasuredImageToMesh ? FormatFixed(*r.Linear.MeasuredImageToMesh, 4) : "-")
        << "), h(M,I) " << FormatFixed(*r.MeasuredMeshToImage, 4) << " (bound " << bound(r.MeshToImageBound)
        << ", linear " << (r.Linear.MeasuredMeshToImage ? FormatFixed(*r.Linear.MeasuredMeshToImage, 4) : "-")
        << ") voxels; " << r.InterfaceCrossings.value_or(0) << " crossing segments; topology "
        << (r.TopologyMatches.value_or(false) ? "matches" : "DIFFERS") << "\n";
  }
  out << "Minimum scaled Jacobian " << FormatFixed(r.MinimumScaledJacobian, 4) << ", histogram:\n";
  PrintJacobianHistogram(r.ScaledJacobianHistogram, out);
  if (r.HasAccuracy)
  {
    out << "Misclassified pixels (of " << r.Pixels << "): linear " << r.MisclassifiedLinear << " ("
        << Percent(r.MisclassifiedLinear, r.Pixels) << "), curved " << r.MisclassifiedCurved << " ("
        << Percent(r.MisclassifiedCurved, r.Pixels) << ")\n";
    out << "  material  missed lin/cur  claimed lin/cur\n";
    for (const auto& [material, counts] : r.AccuracyPerMaterial)
    {
      out << "  " << std::setw(8) << material << "  " << std::setw(6) << counts.first.Missed << " / "
          << std::left << std::setw(6) << counts.second.Missed << std::right << "  " << std::setw(6)
          << counts.first.Claimed << " / " << counts.second.Claimed << "\n";
    }
  }
  out << "Curving time per stage:\n";
  for (const auto& t : r.Timings)
  {
    out << "  " << std::left << std::setw(30) << t.first << std::right << FormatFixed(t.second, 3)
        << " s\n";
  }
}

void WriteCurveJson(const CurveReport& r, std::ostream& out)
{
  JsonWriter j(out);
  j.BeginObject();
  j.Key("command").String("curve");
  j.Key("input").String(r.Linear.Input);
  j.Key("output").String(r.Linear.Outputs.empty() ? std::string() : r.Linear.Outputs.front());
  j.Key("outputs").BeginArray();
  for (const std::string& o : r.Linear.Outputs)
  {
    j.String(o);
  }
  j.EndArray();
  WriteMaterialTableJson(r.Linear, j);
  j.Key("parameters").BeginObject();
  j.Key("smoothness").Integer(r.Smoothness);
  j.Key("tension").Number(r.Tension);
  j.Key("maximum_untangling_steps").Integer(r.MaximumUntanglingSteps);
  j.Key("maximum_shortening_rounds").Integer(r.MaximumShorteningRounds);
  j.Key("minimum_scaled_jacobian").Number(r.ScaledJacobianBound);
  j.Key("quality_iterations").Integer(r.QualityIterations);
  j.Key("image_to_mesh").Number(r.Linear.ImageToMeshBound);
  j.Key("mesh_to_image").Number(r.Linear.MeshToImageBound);
  j.EndObject();
  j.Key("decimation");
  WriteDecimationJson(r.Linear.Decimation, j);
  j.Key("linear_mesh").BeginObject();
  j.Key("cells").Integer(r.Linear.Cells);
  j.Key("minimum_angle_degrees");
  if (r.Linear.MinimumAngle)
    j.Number(*r.Linear.MinimumAngle);
  else
    j.Null();
  j.Key("measured_image_to_mesh");
  if (r.Linear.MeasuredImageToMesh)
    j.Number(*r.Linear.MeasuredImageToMesh);
  else
    j.Null();
  j.Key("measured_mesh_to_image");
  if (r.Linear.MeasuredMeshToImage)
    j.Number(*r.Linear.MeasuredMeshToImage);
  else
    j.Null();
  j.Key("topology_matches").Bool(r.Linear.TopologyMatches());
  j.EndObject();
  j.Key("curved_mesh").BeginObject();
  j.Key("cell_type").String(r.Order == 2 ? "quadratic_triangle" : "bezier_triangle_degree_3");
  j.Key("order").Integer(r.Order);
  j.Key("cells").Integer(r.Cells);
  j.Key(r.Order == 2 ? "nodes" : "control_points").Integer(r.ControlPoints);
  j.Key("interface_chains").Integer(r.InterfaceChains);
  j.Key("closed_interface_chains").Integer(r.ClosedInterfaceChains);
  j.Key("curved_edges").Integer(r.CurvedEdges);
  j.Key("split_ears").Integer(r.SplitEars);
  j.Key("ear_corners").Integer(r.EarCorners);
  j.Key("shortened_pieces").Integer(r.ShortenedPieces);
  j.Key("straightened_pieces").Integer(r.StraightenedPieces);
  j.Key("pieces_shortened_for_bounds").Integer(r.PiecesShortenedForBounds);
  j.Key("pieces_shortened_for_validity").Integer(r.PiecesShortenedForValidity);
  j.Key("uncertified_pieces").Integer(r.UncertifiedPieces);
  j.Key("untangling_rounds").Integer(r.UntanglingRounds);
  auto optional = [&j](const char* key, const std::optional<double>& value) {
    j.Key(key);
    if (value)
      j.Number(*value);
    else
      j.Null();
  };
  optional("image_to_mesh_bound", r.ImageToMeshBound);
  optional("mesh_to_image_bound", r.MeshToImageBound);
  optional("measure_resolution", r.CurveResolution);
  optional("measured_image_to_mesh", r.MeasuredImageToMesh);
  optional("measured_mesh_to_image", r.MeasuredMeshToImage);
  j.Key("interface_crossings");
  if (r.InterfaceCrossings)
    j.Integer(*r.InterfaceCrossings);
  else
    j.Null();
  j.Key("topology_matches");
  if (r.TopologyMatches)
    j.Bool(*r.TopologyMatches);
  else
    j.Null();
  j.Key("within_bounds").Bool(r.CurvesFaithful());
  j.EndObject();
  j.Key("validity").BeginObject();
  j.Key("valid").Bool(r.Valid());
  j.Key("invalid_before_untangling").Integer(r.InvalidBeforeUntangling);
  j.Key("invalid_cells").Integer(r.InvalidCells);
  j.Key("untangling_steps").Integer(r.UntanglingSteps);
  j.Key("minimum_scaled_jacobian").Number(r.MinimumScaledJacobian);
  j.Key("scaled_jacobian_bound_holds").Bool(r.ScaledJacobianHolds());
  j.Key("minimum_corner_angle_degrees");
  if (r.MinimumCornerAngle)
    j.Number(*r.MinimumCornerAngle);
  else
    j.Null();
  j.Key("corner_angle_bound_degrees").Number(r.CornerAngleBound);
  j.Key("corner_angle_bound_holds").Bool(r.CornerAnglesHold());
  j.Key("cells_below_corner_angle_bound").Integer(r.CellsBelowCornerAngle);
  j.Key("straightened_for_corner_angle").Bool(r.StraightenedForCornerAngle);
  j.Key("straightened_for_validity").Bool(r.StraightenedForValidity);
  j.Key("cells_below_scaled_jacobian_bound").Integer(r.CellsBelowScaledJacobian);
  j.Key("straightened_for_scaled_jacobian").Bool(r.StraightenedForScaledJacobian);
  j.Key("minimum_jacobian").Number(r.MinimumJacobian);
  j.Key("scaled_jacobian_histogram");
  WriteJacobianHistogramJson(r.ScaledJacobianHistogram, j);
  j.EndObject();
  j.Key("accuracy");
  if (r.HasAccuracy)
  {
    j.BeginObject();
    j.Key("pixels").Integer(r.Pixels);
    j.Key("misclassified_linear").Integer(r.MisclassifiedLinear);
    j.Key("misclassified_curved").Integer(r.MisclassifiedCurved);
    j.Key("materials").BeginArray();
    for (const auto& [material, counts] : r.AccuracyPerMaterial)
    {
      j.BeginObject();
      j.Key("material").Integer(material);
      j.Key("missed_linear").Integer(counts.first.Missed);
      j.Key("missed_curved").Integer(counts.second.Missed);
      j.Key("claimed_linear").Integer(counts.first.Claimed);
      j.Key("claimed_curved").Integer(counts.second.Claimed);
      j.EndObject();
    }
    j.EndArray();
    j.EndObject();
  }
  else
  {
    j.Null();
  }
  j.Key("timings").BeginArray();
  for (const auto& t : r.Linear.Timings)
  {
    j.BeginObject();
    j.Key("stage").String("mesh: " + t.first);
    j.Key("seconds").Number(t.second);
    j.EndObject();
  }
  for (const auto& t : r.Timings)
  {
    j.BeginObject();
    j.Key("stage").String("curve: " + t.first);
    j.Key("seconds").Number(t.second);
    j.EndObject();
  }
  j.EndArray();
  j.EndObject();
}

} // namespace report
} // namespace labelmesher
