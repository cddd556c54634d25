// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_report_RunReport_h
#define labelmesher_report_RunReport_h

/**
 * @file RunReport.h
 * What a run of vtkLabelMesher produced, gathered from its mesh (cell data and
 * field data: the parameters, the measurements, the material table, the
 * timings) and printed as a text summary or written as JSON: the one report of
 * the CLI (`--report`, its summary), the desktop viewer and, through
 * vtkLabelMeshReport, the 3D Slicer module and Python.
 */

#include "MaterialTable.h"

#include "vtkType.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

class vtkFieldData;
class vtkImageData;
class vtkUnstructuredGrid;

namespace labelmesher
{
namespace report
{

class JsonWriter;

struct TopologyEntry
{
  int Material = 0;
  long long ImageComponents = 0, ImageEuler = 0;
  long long MeshComponents = 0, MeshEuler = 0;
  bool Matches = false;
};

/// What the decimation did (vtkLabelMesher's or vtkMeshDecimator's field data).
struct DecimationEntry
{
  double AngleBound = 0.0; ///< degrees
  long long CellsBefore = 0, CellsAfter = 0, Merges = 0, Offers = 0;
  long long RejectedByQuality = 0, RejectedByTopology = 0, RejectedByFidelity = 0, FrozenVertices = 0;
  long long Relocations = 0; ///< interior vertices moved between rounds of merges
  /// Streamed (vtkLabelMesher): blocks, initial cells of the largest, cells entering the last pass,
  /// border passes between blocks, the most cells the assembled blocks held.
  long long Blocks = 0, Parts = 0, Processes = 0, LargestBlockCells = 0, AssembledCells = 0, BorderPasses = 0, LargestAssembledCells = 0;
};

/// Cells by their certified scaled Jacobian: bin 0 for cells not proved valid, bin b (1..10) for
/// ((b − 1)/10, b/10].
using JacobianHistogram = std::array<long long, 11>;
int JacobianHistogramBin(double scaledJacobian, bool provedValid);
void PrintJacobianHistogram(const JacobianHistogram& histogram, std::ostream& out);
void WriteJacobianHistogramJson(const JacobianHistogram& histogram, JsonWriter& json);

/// The quadratic mesh of Order 2 (vtkLabelMesher's port 2 field data, QuadraticOutput.h).
struct QuadraticEntry
{
  JacobianHistogram ScaledJacobianHistogram{}; ///< of the certified lower bounds
  long long Cells = 0, Points = 0;
  long long FittedEdges = 0, CurvedEdges = 0, PulledBackEdges = 0;
  long long CellsFailedScaledJacobian = 0, FacesFailedDistance = 0;
  long long Rounds = 0, UntangledEdges = 0, PinnedEdges = 0;
  double ScaledJacobianBound = 0.0, CertifiedMinimumScaledJacobian = 0.0;
  /// Corner angles (QuadraticCorners.h), degrees: the bound (0: none) and the smallest, exact.
  double CornerAngleBound = 0.0, MinimumCornerAngle = 180.0;
  long long CellsFailedCornerAngle = 0;
  /// Present when measured (independently of the curver's certificates).
  std::optional<double> SampledMinimumScaledJacobian, MeasuredImageToMesh, MeasuredMeshToImage, MeasureResolution;
  std::optional<double> MeasuredMinimumCornerAngle;
  std::optional<double> Voxels, MisclassifiedLinear, MisclassifiedQuadratic;
};

struct RunReport
{
  std::string Input;
  std::vector<std::string> Outputs; ///< every file written, in the order of -o
  MaterialTable Materials; ///< names and colours (names default to label_N)
  std::vector<std::string> Notes;   ///< remarks of the reader (e.g. renumbered segments)
  std::array<int, 3> Dimensions{ 0, 0, 0 };
  std::array<double, 3> Spacing{ 0, 0, 0 };
  int MeshDimension = 3;
  double ImageToMeshBound = 0, MeshToImageBound = 0, VoxelSize = 1;
  bool IncludeBackground = false;
  long long Points = 0, Cells = 0;
  std::map<int, long long> CellsPerMaterial;
  /// Present only when the filter measured its output.
  std::optional<double> MinimumAngle, MaximumAngle, InvertedCells;
  std::optional<double> MeasuredImageToMesh, MeasuredMeshToImage;
  std::optional<double> HausdorffCertified; ///< 1 when the checks' exact test certifies both bounds
  /// Conformity of the written mesh: faces shared by more than two cells,
  /// hanging vertices, boundary edges not shared by exactly two boundary faces
  /// (non-zero also where the image itself is non-manifold, e.g. two voxels of
  /// one label touching along an edge; with the background included the
  /// boundary is the octree's cube and must be 0).
  std::optional<double> OverSharedFaces, HangingVertices, NonManifoldBoundaryEdges;
  std::vector<TopologyEntry> Topology;
  std::optional<DecimationEntry> Decimation; ///< absent with --no-decimate
  std::optional<QuadraticEntry> Quadratic;   ///< present with Order 2 (AddQuadratic)
  std::vector<std::pair<std::string, double>> Timings; ///< stage, seconds
  /// Memory, MiB: the estimate the mesher checked before it started (absent if it did not), the
  /// resident memory when the pipeline started (the image read) and the process's peak.
  std::optional<double> EstimatedMemory;
  long long InterfaceFaces = 0;
  double StartMemory = 0, PeakMemory = 0;

  bool Measured() const { return MinimumAngle.has_value(); }
  bool TopologyMatches() const;
};

/// Value `tuple` of the one-component field-data array `name`, if present.
std::optional<double> FieldValue(vtkFieldData* fd, const char* name, vtkIdType tuple = 0);
/// The same, rounded to an integer (0 when absent): counts stored as doubles.
long long FieldCount(vtkFieldData* fd, const char* name, vtkIdType tuple = 0);
/// `value` with `digits` decimals.
std::string FormatFixed(double value, int digits);

/// The report of the run that made `mesh` (vtkLabelMesher's output port 0: decimated, or the
/// mesher's without decimation) from `image` read from `input`: the parameters, measurements,
/// material table and timings its field data records. Outputs, Notes and the memory figures are
/// the caller's to add.
RunReport MakeReport(const std::string& input, vtkImageData* image, vtkUnstructuredGrid* mesh);
/// Adds the quadratic mesh of port 2 when it is one (field Order 2).
void AddQuadratic(RunReport& report, vtkUnstructuredGrid* quadratic);
/// True when the quadratic mesh keeps its guarantees as recorded: the certified scaled Jacobian
/// at least its bound and, when measured, the sampled one too, and both distances within the
/// bounds up to the measure's resolution. True when there is none.
bool QuadraticHolds(const RunReport& report);
/// The angle bound the mesh keeps, degrees: the decimation's, or without it the initial mesh's
/// proven bound.
double AngleBoundOf(const RunReport& report);
/// True when the mesh was measured and keeps every guarantee as measured: no angle below
/// AngleBoundOf, no inverted cell, both distance bounds certified, every material's topology.
bool GuaranteesHold(const RunReport& report);
void PrintSummary(const RunReport& report, std::ostream& out);
/// "a.vtu, b.msh"
std::string OutputList(const RunReport& report);
/// The report's "material_table": label, name, colour (or null), cells.
void WriteMaterialTableJson(const RunReport& report, JsonWriter& json);
void WriteJson(const RunReport& report, std::ostream& out);
/// The report's "decimation" value: an object, or null with --no-decimate.
void WriteDecimationJson(const std::optional<DecimationEntry>& decimation, JsonWriter& json);

} // namespace report
} // namespace labelmesher

#endif
