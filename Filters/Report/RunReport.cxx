// SPDX-License-Identifier: GPL-2.0-or-later
// Gathers what a run produced from the filters' field data and prints it or writes it as JSON.
#include "RunReport.h"

#include "JsonWriter.h"
#include "QuadraticReport.h"

#include "LabelMesherArrayNames.h"
#include "vtkLabelMesher.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkStringArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>

namespace labelmesher
{
namespace report
{
namespace arrays = labelmesher::arrays;

std::optional<double> FieldValue(vtkFieldData* fd, const char* name, vtkIdType tuple)
{
  vtkDataArray* array = fd ? fd->GetArray(name) : nullptr;
  if (!array || tuple >= array->GetNumberOfTuples())
  {
    return std::nullopt;
  }
  return array->GetComponent(tuple, 0);
}

long long FieldCount(vtkFieldData* fd, const char* name, vtkIdType tuple)
{
  return std::llround(FieldValue(fd, name, tuple).value_or(0.0));
}

std::string FormatFixed(double value, int digits)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, value);
  return buffer;
}

bool RunReport::TopologyMatches() const
{
  for (const auto& entry : this->Topology)
  {
    if (!entry.Matches)
    {
      return false;
    }
  }
  return !this->Topology.empty();
}

namespace
{

void AppendTimings(vtkFieldData* fd, std::vector<std::pair<std::string, double>>& timings)
{
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray(arrays::StageName));
  vtkDataArray* seconds = fd->GetArray(arrays::StageSeconds);
  if (names && seconds)
  {
    for (vtkIdType s = 0; s < names->GetNumberOfValues() && s < seconds->GetNumberOfTuples(); ++s)
    {
      timings.emplace_back(names->GetValue(s), seconds->GetComponent(s, 0));
    }
  }
}

} // namespace

RunReport MakeReport(const std::string& input, vtkImageData* image, vtkUnstructuredGrid* mesh)
{
  RunReport r;
  r.Input = input;
  image->GetDimensions(r.Dimensions.data());
  image->GetSpacing(r.Spacing.data());
  r.MeshDimension = vtkLabelMesher::GetImageDimension(image);

  r.Points = mesh->GetNumberOfPoints();
  r.Cells = mesh->GetNumberOfCells();
  if (vtkDataArray* material = mesh->GetCellData()->GetArray(arrays::Material))
  {
    for (vtkIdType c = 0; c < material->GetNumberOfTuples(); ++c)
    {
      ++r.CellsPerMaterial[static_cast<int>(material->GetComponent(c, 0))];
    }
  }

  vtkFieldData* fd = mesh->GetFieldData();
  r.Materials = ReadMaterialTable(fd);
  r.IncludeBackground = FieldCount(fd, arrays::IncludeBackground) != 0;
  r.ImageToMeshBound = FieldValue(fd, arrays::ImageToMeshDistance).value_or(0.0);
  r.MeshToImageBound = FieldValue(fd, arrays::MeshToImageDistance).value_or(0.0);
  r.VoxelSize = FieldValue(fd, arrays::VoxelSize).value_or(1.0);
  r.MinimumAngle = FieldValue(fd, arrays::MinimumAngle);
  r.MaximumAngle = FieldValue(fd, arrays::MaximumAngle);
  r.InvertedCells = FieldValue(fd, arrays::InvertedCells);
  r.MeasuredImageToMesh = FieldValue(fd, arrays::MeasuredImageToMeshDistance);
  r.MeasuredMeshToImage = FieldValue(fd, arrays::MeasuredMeshToImageDistance);
  r.HausdorffCertified = FieldValue(fd, arrays::HausdorffBoundsCertified);
  r.OverSharedFaces = FieldValue(fd, arrays::OverSharedFaces);
  r.HangingVertices = FieldValue(fd, arrays::HangingVertices);
  r.NonManifoldBoundaryEdges = FieldValue(fd, arrays::NonManifoldBoundaryEdges);
  if (vtkDataArray* materials = fd->GetArray(arrays::TopologyMaterial))
  {
    for (vtkIdType t = 0; t < materials->GetNumberOfTuples(); ++t)
    {
      TopologyEntry e;
      e.Material = static_cast<int>(materials->GetComponent(t, 0));
      e.ImageComponents = FieldCount(fd, arrays::ImageComponents, t);
      e.ImageEuler = FieldCount(fd, arrays::ImageEulerCharacteristic, t);
      e.MeshComponents = FieldCount(fd, arrays::MeshComponents, t);
      e.MeshEuler = FieldCount(fd, arrays::MeshEulerCharacteristic, t);
      e.Matches = FieldCount(fd, arrays::TopologyMatches, t) != 0;
      r.Topology.push_back(e);
    }
  }
  r.EstimatedMemory = FieldValue(fd, arrays::EstimatedMemory);
  r.InterfaceFaces = FieldCount(fd, arrays::InterfaceFaces);
  AppendTimings(fd, r.Timings);
  if (fd->GetArray(arrays::Merges))
  {
    DecimationEntry d;
    d.AngleBound = FieldValue(fd, arrays::AngleBound).value_or(0.0);
    d.CellsBefore = FieldCount(fd, arrays::CellsBefore);
    d.CellsAfter = FieldCount(fd, arrays::CellsAfter);
    d.Merges = FieldCount(fd, arrays::Merges);
    d.Offers = FieldCount(fd, arrays::MergeOffers);
    d.RejectedByQuality = FieldCount(fd, arrays::MergesRejectedByQuality);
    d.RejectedByTopology = FieldCount(fd, arrays::MergesRejectedByTopology);
    d.RejectedByFidelity = FieldCount(fd, arrays::MergesRejectedByFidelity);
    d.FrozenVertices = FieldCount(fd, arrays::FrozenVertices);
    d.Relocations = FieldCount(fd, arrays::VerticesRelocated);
    d.Blocks = FieldCount(fd, arrays::Blocks);
    d.LargestBlockCells = FieldCount(fd, arrays::LargestBlockCells);
    d.Parts = FieldCount(fd, arrays::Parts);
    d.Processes = FieldCount(fd, arrays::Processes);
    d.AssembledCells = FieldCount(fd, arrays::AssembledCells);
    d.BorderPasses = FieldCount(fd, arrays::BorderPasses);
    d.LargestAssembledCells = FieldCount(fd, arrays::LargestAssembledCells);
    r.Decimation = d;
  }
  return r;
}

double AngleBoundOf(const RunReport& r)
{
  return r.Decimation ? r.Decimation->AngleBound : vtkLabelMesher::GetProvenAngleBound(r.MeshDimension);
}

bool GuaranteesHold(const RunReport& r)
{
  // The measured angle is computed in floating point from the written coordinates; the bound is
  // an exact predicate's, so the comparison allows rounding only.
  return r.Measured() && *r.MinimumAngle >= AngleBoundOf(r) - 1e-9 && r.InvertedCells.value_or(1.0) == 0.0 &&
    r.HausdorffCertified.value_or(0.0) == 1.0 && r.TopologyMatches();
}

std::string OutputList(const RunReport& r)
{
  std::string list;
  for (const std::string& o : r.Outputs)
  {
    list += (list.empty() ? "" : ", ") + o;
  }
  return list;
}

void WriteMaterialTableJson(const RunReport& r, JsonWriter& j)
{
  j.Key("material_table").BeginArray();
  for (const auto& entry : r.CellsPerMaterial)
  {
    const MaterialInfo* info = r.Materials.Find(entry.first);
    j.BeginObject();
    j.Key("label").Integer(entry.first);
    j.Key("name").String(r.Materials.NameOf(entry.first));
    j.Key("color");
    if (info && info->HasColor())
    {
      j.BeginArray();
      for (double v : info->Color)
      {
        j.Number(v);
      }
      j.EndArray();
    }
    else
    {
      j.Null();
    }
    j.Key("cells").Integer(entry.second);
    j.EndObject();
  }
  j.EndArray();
}

int JacobianHistogramBin(double scaledJacobian, bool provedValid)
{
  return provedValid ? std::clamp(static_cast<int>(std::ceil(std::max(scaledJacobian, 1e-12) * 10.0)), 1, 10) : 0;
}

void PrintJacobianHistogram(const JacobianHistogram& histogram, std::ostream& out)
{
  for (std::size_t b = 0; b < histogram.size(); ++b)
  {
    const std::string label = b == 0 ? "  not proven valid"
                                     : "  (" + FormatFixed(0.1 * static_cast<double>(b - 1), 1) + ", " +
        FormatFixed(0.1 * static_cast<double>(b), 1) + "]";
    out << std::left << std::setw(20) << label << std::right << histogram[b] << "\n";
  }
}

void WriteJacobianHistogramJson(const JacobianHistogram& histogram, JsonWriter& j)
{
  j.BeginArray();
  for (std::size_t b = 0; b < histogram.size(); ++b)
  {
    j.BeginObject();
    j.Key("from").Number(b == 0 ? -HUGE_VAL : 0.1 * static_cast<double>(b - 1));
    j.Key("to").Number(b == 0 ? 0.0 : 0.1 * static_cast<double>(b));
    j.Key("cells").Integer(histogram[b]);
    j.EndObject();
  }
  j.EndArray();
}

void PrintSummary(const RunReport& r, std::ostream& out)
{
  const char* cellName = r.MeshDimension == 3 ? "tetrahedra" : "triangles";
  out << "Input   " << r.Input << "  (" << r.Dimensions[0] << " x " << r.Dimensions[1] << " x "
      << r.Dimensions[2] << " voxels, spacing " << r.Spacing[0] << " x " << r.Spacing[1] << " x "
      << r.Spacing[2] << ")\n";
  for (const std::string& note : r.Notes)
  {
    out << "Note    " << note << "\n";
  }
  out << "Output  " << OutputList(r) << "  (" << r.Cells << " " << cellName << ", " << r.Points
      << " points)\n";
  out << "Cells per material:\n";
  for (const auto& entry : r.CellsPerMaterial)
  {
    out << "  " << std::setw(6) << entry.first << "  " << std::setw(9) << entry.second << "  "
        << r.Materials.NameOf(entry.first) << "\n";
  }
  if (r.Decimation)
  {
    const DecimationEntry& d = *r.Decimation;
    out << "Decimated: " << d.CellsBefore << " -> " << d.CellsAfter << " " << cellName << " (angle bound "
        << FormatFixed(d.AngleBound, 2) << " deg; " << d.Merges << " merges, refused by quality "
        << d.RejectedByQuality << ", topology " << d.RejectedByTopology << ", fidelity " << d.RejectedByFidelity
        << "; " << d.Relocations << " interior vertices relocated)\n";
    if (d.Blocks > 1)
    {
      out << "Streamed in " << d.Blocks << " blocks (largest " << d.LargestBlockCells << " initial " << cellName
          << ") in " << d.Parts << (d.Parts == 1 ? " part" : " parts");
      if (d.Processes > 1)
      {
        out << " over " << d.Processes << " processes";
      }
      out << "; " << d.BorderPasses << " border passes, at most " << d.LargestAssembledCells << " " << cellName
          << " assembled; last pass over " << d.AssembledCells << " " << cellName << "\n";
    }
  }
  else
  {
    out << "Not decimated (--no-decimate): the initial mesh\n";
  }
  const std::string unit = " voxels (1 voxel = " + FormatFixed(r.VoxelSize, 4) + ")";
  if (r.Measured())
  {
    out << "Minimum " << (r.MeshDimension == 3 ? "dihedral" : "planar")
        << " angle: " << FormatFixed(*r.MinimumAngle, 2) << " deg  (maximum "
        << FormatFixed(r.MaximumAngle.value_or(0.0), 2) << " deg, inverted cells "
        << static_cast<long long>(r.InvertedCells.value_or(0.0)) << ")\n";
    out << "Hausdorff h(I,M): " << FormatFixed(r.MeasuredImageToMesh.value_or(0.0), 3) << " (bound "
        << FormatFixed(r.ImageToMeshBound, 3) << ")" << unit << "\n";
    out << "Hausdorff h(M,I): " << FormatFixed(r.MeasuredMeshToImage.value_or(0.0), 3) << " (bound "
        << FormatFixed(r.MeshToImageBound, 3) << ")" << unit << "\n";
    out << "Both bounds " << (r.HausdorffCertified.value_or(0.0) == 1.0 ? "certified" : "NOT certified")
        << " by the checks' exact test\n";
    out << "Conformity: " << static_cast<long long>(r.OverSharedFaces.value_or(0.0))
        << " over-shared faces, " << static_cast<long long>(r.HangingVertices.value_or(0.0))
        << " hanging vertices, " << static_cast<long long>(r.NonManifoldBoundaryEdges.value_or(0.0))
        << " non-manifold boundary edges\n";
    out << "Topology (components, Euler characteristic; image vs mesh):\n";
    for (const auto& e : r.Topology)
    {
      out << "  " << std::setw(6) << e.Material << "  (" << e.ImageComponents << ", "
          << e.ImageEuler << ") vs (" << e.MeshComponents << ", " << e.MeshEuler << ")  "
          << (e.Matches ? "match" : "MISMATCH") << "\n";
    }
  }
  else
  {
    out << "Quality, distances and topology: not measured (--no-measure, or the checks were not built)\n";
  }
  out << "Time per stage:\n";
  double total = 0.0;
  for (const auto& t : r.Timings)
  {
    out << "  " << std::left << std::setw(20) << t.first << std::right << FormatFixed(t.second, 3)
        << " s\n";
    total += t.second;
  }
  out << "  " << std::left << std::setw(20) << "total" << std::right << FormatFixed(total, 3) << " s\n";
  if (r.PeakMemory > 0)
  {
    out << "Memory: peak " << FormatFixed(r.PeakMemory, 0) << " MiB resident; the run added "
        << FormatFixed(std::max(0.0, r.PeakMemory - r.StartMemory), 0) << " MiB to the "
        << FormatFixed(r.StartMemory, 0) << " MiB held after reading";
    if (r.EstimatedMemory)
    {
      out << " (estimated beforehand: " << FormatFixed(*r.EstimatedMemory, 0) << " MiB)";
    }
    out << "\n";
  }
  PrintQuadraticSummary(r, out);
}

void WriteDecimationJson(const std::optional<DecimationEntry>& decimation, JsonWriter& j)
{
  if (!decimation)
  {
    j.Null();
    return;
  }
  const DecimationEntry& d = *decimation;
  j.BeginObject();
  j.Key("minimum_angle_bound_degrees").Number(d.AngleBound);
  j.Key("cells_before").Integer(d.CellsBefore);
  j.Key("cells_after").Integer(d.CellsAfter);
  j.Key("merges").Integer(d.Merges);
  j.Key("merge_offers").Integer(d.Offers);
  j.Key("rejected_by_quality").Integer(d.RejectedByQuality);
  j.Key("rejected_by_topology").Integer(d.RejectedByTopology);
  j.Key("rejected_by_fidelity").Integer(d.RejectedByFidelity);
  j.Key("frozen_vertices").Integer(d.FrozenVertices);
  j.Key("vertices_relocated").Integer(d.Relocations);
  j.Key("blocks").Integer(d.Blocks);
  j.Key("largest_block_cells").Integer(d.LargestBlockCells);
  j.Key("parts").Integer(d.Parts);
  j.Key("processes").Integer(d.Processes);
  j.Key("assembled_cells").Integer(d.AssembledCells);
  j.Key("border_passes").Integer(d.BorderPasses);
  j.Key("largest_assembled_cells").Integer(d.LargestAssembledCells);
  j.EndObject();
}

void WriteJson(const RunReport& r, std::ostream& out)
{
  JsonWriter j(out);
  auto optional = [&j](const std::optional<double>& v) {
    if (v)
    {
      j.Number(*v);
    }
    else
    {
      j.Null();
    }
  };
  j.BeginObject();
  j.Key("input").String(r.Input);
  j.Key("output").String(r.Outputs.empty() ? std::string() : r.Outputs.front());
  j.Key("outputs").BeginArray();
  for (const std::string& o : r.Outputs)
  {
    j.String(o);
  }
  j.EndArray();
  j.Key("notes").BeginArray();
  for (const std::string& n : r.Notes)
  {
    j.String(n);
  }
  j.EndArray();
  WriteMaterialTableJson(r, j);
  j.Key("image").BeginObject();
  j.Key("dimensions").BeginArray();
  for (int d : r.Dimensions)
  {
    j.Integer(d);
  }
  j.EndArray();
  j.Key("spacing").BeginArray();
  for (double s : r.Spacing)
  {
    j.Number(s);
  }
  j.EndArray();
  j.EndObject();
  j.Key("parameters").BeginObject();
  j.Key("image_to_mesh").Number(r.ImageToMeshBound);
  j.Key("mesh_to_image").Number(r.MeshToImageBound);
  j.Key("include_background").Bool(r.IncludeBackground);
  j.Key("distance_unit").Number(r.VoxelSize);
  j.EndObject();
  j.Key("mesh").BeginObject();
  j.Key("dimension").Integer(r.MeshDimension);
  j.Key("cell_type").String(r.MeshDimension == 3 ? "tetra" : "triangle");
  j.Key("points").Integer(r.Points);
  j.Key("cells").Integer(r.Cells);
  j.Key("cells_per_material").BeginObject();
  for (const auto& entry : r.CellsPerMaterial)
  {
    j.Key(std::to_string(entry.first)).Integer(entry.second);
  }
  j.EndObject();
  j.EndObject();
  j.Key("decimation");
  WriteDecimationJson(r.Decimation, j);
  j.Key("measured").Bool(r.Measured());
  j.Key("quality").BeginObject();
  j.Key("angle_kind").String(r.MeshDimension == 3 ? "dihedral" : "planar");
  j.Key("angle_bound_degrees")
    .Number(AngleBoundOf(r));
  j.Key("minimum_angle_degrees");
  optional(r.MinimumAngle);
  j.Key("maximum_angle_degrees");
  optional(r.MaximumAngle);
  j.Key("inverted_cells");
  optional(r.InvertedCells);
  j.EndObject();
  j.Key("conformity").BeginObject();
  j.Key("over_shared_faces");
  optional(r.OverSharedFaces);
  j.Key("hanging_vertices");
  optional(r.HangingVertices);
  j.Key("non_manifold_boundary_edges");
  optional(r.NonManifoldBoundaryEdges);
  j.EndObject();
  j.Key("fidelity").BeginObject();
  j.Key("unit").String("voxels of the smallest spacing");
  j.Key("image_to_mesh");
  optional(r.MeasuredImageToMesh);
  j.Key("mesh_to_image");
  optional(r.MeasuredMeshToImage);
  j.Key("bounds_certified");
  if (r.HausdorffCertified)
  {
    j.Bool(*r.HausdorffCertified == 1.0);
  }
  else
  {
    j.Null();
  }
  j.Key("image_to_mesh_bound").Number(r.ImageToMeshBound);
  j.Key("mesh_to_image_bound").Number(r.MeshToImageBound);
  j.EndObject();
  j.Key("topology").BeginObject();
  j.Key("all_match");
  if (r.Measured())
  {
    j.Bool(r.TopologyMatches());
  }
  else
  {
    j.Null();
  }
  j.Key("materials").BeginArray();
  for (const auto& e : r.Topology)
  {
    j.BeginObject();
    j.Key("material").Integer(e.Material);
    j.Key("image_components").Integer(e.ImageComponents);
    j.Key("image_euler_characteristic").Integer(e.ImageEuler);
    j.Key("mesh_components").Integer(e.MeshComponents);
    j.Key("mesh_euler_characteristic").Integer(e.MeshEuler);
    j.Key("matches").Bool(e.Matches);
    j.EndObject();
  }
  j.EndArray();
  j.EndObject();
  j.Key("timings").BeginArray();
  double total = 0.0;
  for (const auto& t : r.Timings)
  {
    j.BeginObject();
    j.Key("stage").String(t.first);
    j.Key("seconds").Number(t.second);
    j.EndObject();
    total += t.second;
  }
  j.EndArray();
  j.Key("total_seconds").Number(total);
  j.Key("memory").BeginObject();
  j.Key("peak_mib").Number(r.PeakMemory);
  j.Key("after_reading_mib").Number(r.StartMemory);
  j.Key("estimated_run_mib");
  if (r.EstimatedMemory)
  {
    j.Number(*r.EstimatedMemory);
  }
  else
  {
    j.Null();
  }
  j.Key("interface_faces").Integer(r.InterfaceFaces);
  j.EndObject();
  WriteQuadraticJson(r, j);
  j.EndObject();
}

} // namespace report
} // namespace labelmesher
