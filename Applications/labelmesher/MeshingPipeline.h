// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_cli_MeshingPipeline_h
#define labelmesher_cli_MeshingPipeline_h

/**
 * @file MeshingPipeline.h
 * The CLI's and the viewer's binding of vtkLabelMesher, the one pipeline of
 * every front end (mesher and decimator block by block; with --no-decimate the
 * mesher alone; then, 2D images on request, the curver): settings in, the
 * filter's outputs and one-line messages out.
 */

#include "FilterRun.h"

#include "vtkLabelMesher.h"      // the defaults
#include "vtkPolyData.h"         // complete types: the outcome is copied by value
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <stdexcept>
#include <string>

class vtkAlgorithm;
class vtkImageData;

namespace labelmesher_cli
{

/// A filter failed or made no cells; the message is one line.
struct MeshingError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// A vtkLabelMesher as constructed: where MeshingSettings' defaults come from, so that the front
/// ends' defaults are the filter's.
vtkLabelMesher* FilterDefaults();

struct MeshingSettings
{
  double ImageToMeshDistance = FilterDefaults()->GetImageToMeshDistance(); ///< voxels of the smallest spacing
  double MeshToImageDistance = FilterDefaults()->GetMeshToImageDistance(); ///< voxels of the smallest spacing
  bool Decimate = FilterDefaults()->GetDecimate(); ///< decimate the mesher's mesh (streamed by blocks)
  long long BlockCells = FilterDefaults()->GetBlockCells(); ///< initial cells per streamed block; 0: one block
  long long PartBlocks = FilterDefaults()->GetPartBlocks(); ///< blocks per part (a process's unit); 0: one part
  /// Share the run out over mpirun's processes (vtkLabelMesher::Distributed): on ranks other
  /// than 0 the outcome holds no mesh.
  bool Distributed = false;
  /// Degrees, the decimator's bound: (0, vtkLabelMesher::GetProvenAngleBound(dimension)].
  double MinimumAngle = FilterDefaults()->GetMinimumAngle();
  bool RelocateInteriorVertices = FilterDefaults()->GetRelocateInteriorVertices(); ///< move interior vertices between rounds
  bool IncludeBackground = FilterDefaults()->GetIncludeBackground(); ///< keep background cells in the final mesh
  bool Measure = FilterDefaults()->GetMeasureOutput(); ///< measure the final mesh (angles, distances, topology)
  double MemoryLimit = FilterDefaults()->GetMemoryLimit(); ///< MiB the process may hold at most; 0: the machine's limits only
  // Curving (`labelmesher curve`): 2D images only
  bool Curve = FilterDefaults()->GetCurve();
  int Smoothness = FilterDefaults()->GetSmoothness(); ///< 1 (C1, fitted to the image) or 2 (C2)
  double Tension = FilterDefaults()->GetTension();    ///< C1 handle length factor, dimensionless, [0, 1]
  int MaximumUntanglingSteps = FilterDefaults()->GetMaximumUntanglingSteps();
  int MaximumShorteningRounds = FilterDefaults()->GetMaximumShorteningRounds();
  int QualityIterations = FilterDefaults()->GetQualityIterations();
  /// Every curved cell's certified min det J / max det J at least this, [0, 1) (curve, and mesh
  /// with Order 2).
  double MinimumScaledJacobian = FilterDefaults()->GetMinimumScaledJacobian();
  /// `mesh`: 1 linear tetrahedra, 2 also quadratic ones fitted to the image (3D, decimated).
  int Order = FilterDefaults()->GetOrder();
};

struct MeshingOutcome
{
  vtkSmartPointer<vtkUnstructuredGrid> Mesh;    ///< the linear mesh (decimated unless Decimate is off)
  vtkSmartPointer<vtkPolyData> Interfaces;      ///< faces between materials, on Mesh's points
  /// With Curve: the cubic Bezier mesh curved from Mesh. When CurveError is set (untangling
  /// failed) it is the curver's marked mesh (cell data Valid), to inspect, not to use. With
  /// Order 2: the quadratic tetrahedra made from Mesh.
  vtkSmartPointer<vtkUnstructuredGrid> Curved;
  std::string CurveError;
  std::string Warning;                          ///< the filters' first warning, empty if none
  bool Aborted = false; ///< a filter stopped on request (AbortExecute); the meshes are then null
};

/// True when one of the image's extents is a single slice (what the curver needs).
bool IsTwoDimensional(vtkImageData* image);

/// Runs vtkLabelMesher on `image`; `progress` sees its progress over the whole run (setting
/// AbortExecute there stops it). Throws MeshingError with the filter's error (also for Curve on a
/// 3D image) or when it produced no cells. With a `source` (a vtkLabelImageReader that has
/// read the image's header) the filter reads from it what it needs instead, and `image` holds
/// only the image's geometry: a process other than rank 0 that reads its slab alone.
MeshingOutcome RunMeshingPipeline(vtkImageData* image, const MeshingSettings& settings, const FilterProgress& progress,
  vtkAlgorithm* source = nullptr);

} // namespace labelmesher_cli

#endif
