// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_report_CurveReport_h
#define labelmesher_report_CurveReport_h

/**
 * @file CurveReport.h
 * What a curving run (`labelmesher curve`) produced, gathered from vtkBezierCurver's output
 * (cell data and field data) next to the linear mesh's report, printed as a
 * text summary or written as JSON.
 */

#include "RunReport.h"

#include <array>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

class vtkImageData;
class vtkUnstructuredGrid;

namespace labelmesher
{
namespace report
{

struct PixelCounts
{
  long long Missed = 0;  ///< pixels of the label given another material
  long long Claimed = 0; ///< pixels of other labels given this material
};

struct CurveReport
{
  RunReport Linear; ///< the mesher's run (its Output is the curved file)
  int Smoothness = 2;
  double Tension = 0.0;
  int MaximumUntanglingSteps = 0, MaximumShorteningRounds = 0, QualityIterations = 0;
  /// 3: cubic Bézier triangles (ControlPoints counts their control points); 2: quadratic
  /// triangles (ControlPoints counts their nodes).
  int Order = 3;
  long long Cells = 0, ControlPoints = 0;
  long long InvalidBeforeUntangling = 0, InvalidCells = 0, UntanglingSteps = 0;
  long long InterfaceChains = 0, ClosedInterfaceChains = 0, CurvedEdges = 0, SplitEars = 0, EarCorners = 0;
  double MinimumScaledJacobian = 0.0, MinimumJacobian = 0.0;
  /// The smallest corner angle of the curved cells (cell data CornerAngle), degrees; none when
  /// the curver did not record it.
  std::optional<double> MinimumCornerAngle;
  /// Scaled Jacobian histogram: bin 0 is <= 0 (not proven valid), bins 1..10
  /// are (0, 0.1], (0.1, 0.2], ..., (0.9, 1].
  JacobianHistogram ScaledJacobianHistogram{};
  long long ShortenedPieces = 0, StraightenedPieces = 0, PiecesShortenedForBounds = 0,
            PiecesShortenedForValidity = 0, UncertifiedPieces = 0, UntanglingRounds = 0;
  /// Measured on the curves (upper bounds, voxels), with the image only.
  std::optional<double> ImageToMeshBound, MeshToImageBound; ///< kept by the curver; none when < 0
  std::optional<double> CurveResolution, MeasuredImageToMesh, MeasuredMeshToImage;
  std::optional<long long> InterfaceCrossings;
  std::optional<bool> TopologyMatches;
  /// The curves keep the bounds they were given, do not cross and keep the topology.
  bool CurvesFaithful() const;
  bool HasAccuracy = false;
  long long Pixels = 0, MisclassifiedLinear = 0, MisclassifiedCurved = 0;
  std::map<int, std::pair<PixelCounts, PixelCounts>> AccuracyPerMaterial; ///< linear, curved
  std::vector<std::pair<std::string, double>> Timings; ///< stage, seconds

  /// The certified scaled Jacobian every cell was asked to keep (0: validity alone); the cells
  /// still below it after the shortening rounds, and whether every curve was then made straight.
  double ScaledJacobianBound = 0.0;
  long long CellsBelowScaledJacobian = 0;
  bool StraightenedForScaledJacobian = false;
  /// Every cell's certified scaled Jacobian is at least the bound.
  bool ScaledJacobianHolds() const { return this->MinimumScaledJacobian >= this->ScaledJacobianBound; }
  /// The corner angle every cell was asked to keep, degrees (field data CornerAngleBound: the one
  /// asked, or the linear mesh's smallest angle when smaller; 0: measured only); the cells still
  /// below it after the rounds, and whether every curve was then made straight.
  double CornerAngleBound = 0.0;
  long long CellsBelowCornerAngle = 0;
  bool StraightenedForCornerAngle = false;
  bool StraightenedForValidity = false; ///< every curve made straight: the rounds left cells invalid
  /// Every corner angle is at least the bound (to within rounding: a straight cell's corners are
  /// its angles, recomputed from the control points).
  bool CornerAnglesHold() const
  {
    return this->CornerAngleBound <= 0.0 || this->MinimumCornerAngle.value_or(0.0) >= this->CornerAngleBound - 1e-9;
  }
  bool ValidityMeasured = false; ///< the curver recorded InvalidCells
  bool Valid() const { return this->ValidityMeasured && this->InvalidCells == 0; }
};

/// The report of `curved` (vtkLabelMesher's output port 2, vtkBezierCurver's output) beside that of
/// the linear mesh it was curved from; the curver's parameters are those its field data records.
CurveReport MakeCurveReport(const RunReport& linear, vtkUnstructuredGrid* curved);

/// What only the caller of a run knows: the input's and the written files' names, the reader's
/// notes, the stages it timed itself (reading before the filters, writing after) and the
/// process's resident memory (MiB; a peak of 0: not measured).
struct RunContext
{
  std::string Input;
  std::vector<std::string> Outputs, Notes;
  std::vector<std::pair<std::string, double>> TimingsBefore, TimingsAfter;
  double StartMemory = 0.0, PeakMemory = 0.0;
};

/// A run's reports: the linear mesh's, and with curves theirs.
struct RunReports
{
  RunReport Linear;
  std::optional<CurveReport> Curved;
};

/// The one assembly of a run's report, for the CLI, the viewer and vtkLabelMeshReport: `mesh` and
/// `curved` are vtkLabelMesher's ports 0 and 2 (`curved` null or without cells: no curves). The
/// caller's later stages go last in the curve report's timings when there are curves, else in the
/// linear report's.
RunReports MakeRunReports(const RunContext& context, vtkImageData* image, vtkUnstructuredGrid* mesh,
  vtkUnstructuredGrid* curved);
void PrintCurveSummary(const CurveReport& report, std::ostream& out);
void WriteCurveJson(const CurveReport& report, std::ostream& out);

} // namespace report
} // namespace labelmesher

#endif
