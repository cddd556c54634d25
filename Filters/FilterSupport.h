// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef FilterSupport_h
#define FilterSupport_h

/**
 * @file FilterSupport.h
 * Module-private plumbing the LabelMesher filters share, so that each
 * RequestData only unpacks its inputs, calls the core and packs its outputs:
 * the progress/abort bridge to the core's ProgressObserver, VTK cell arrays
 * and points from the core's SimplexMesh, field-data arrays, the measured
 * guarantees (Filters/Core/Checks) and the interface surface of port 1.
 * Not installed.
 */

#include "Decimation/DecimationParameters.h"
#include "LabelImageConversion.h"
#include "Mesh/SimplexMesh.h"
#include "Support/ProgressObserver.h"
#include "Support/StageClock.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkDataObject;

class vtkAlgorithm;
class vtkDataArray;
class vtkInformationVector;
class vtkPoints;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace labelmesher
{

/// A ProgressObserver that forwards the core's stage and fraction to
/// `algorithm` (ProgressText, UpdateProgress mapped onto [start, start +
/// share]) and asks the core to stop when AbortExecute is set.
ProgressObserver ForwardProgress(vtkAlgorithm* algorithm, double start = 0.0, double share = 1.0);

/// Asks for the whole extent of every image on `port`'s connections: the
/// filters mesh whole label images, whatever piece or extent downstream asks for.
void RequestWholeImages(vtkInformationVector* port);

/// The one-component cell array `Material` of `mesh`, or null with a sentence
/// in `error`.
vtkDataArray* MaterialArray(vtkUnstructuredGrid* mesh, std::string& error);
/// The Material of cell `c` as a label (a non-negative integer that fits 32
/// bits), or false with a sentence in `error`.
bool CellMaterial(vtkDataArray* materials, vtkIdType c, std::int32_t& label, std::string& error);

/// Maps an input point to the core's coordinates, or returns false with a sentence in `error`.
using PointPlacer = std::function<bool(const double x[3], Point3& placed, std::string& error)>;

/// The cells of `input` (with their `materials`, MaterialArray's) as the core's SimplexMesh of
/// `dimension`: each point through `place`; each cell checked to be a linear triangle (2D) or
/// tetrahedron (3D) with a valid label, and made positively oriented in the placed coordinates
/// (a placement may reflect). A cell of another type is refused with "Input cell N is not a
/// triangle (VTK type T)" + `why`. Returns false with a sentence in `error`.
bool GatherSimplices(vtkUnstructuredGrid* input, vtkDataArray* materials, int dimension, const PointPlacer& place,
  const std::string& why, SimplexMesh& mesh, std::string& error);

/// Cells of `verticesPerCell` points each, as VTK's offsets + connectivity;
/// `swapSecondAndThird` reverses every cell's orientation on the way.
vtkSmartPointer<vtkCellArray> MakeCellArray(
  const std::vector<std::int64_t>& connectivity, int verticesPerCell, bool swapSecondAndThird = false);

/// One-tuple double array `name` = value.
void AddScalarField(vtkFieldData* fd, const char* name, double value);

/// `degrees` clamped to [0, the larger of the proven angle bounds of 2D and 3D meshes]: what the
/// filters' SetMinimumAngle keep (the image's own bound is checked when they run).
double ClampToProvenAngleBounds(double degrees);

/// Copies the materials' names and colours (MaterialLabel, MaterialName, MaterialColor) from
/// `from` to `to` when `from` has a table (MaterialLabel), replacing any `to` had: the three
/// arrays go together, never mixed from two sources. So a writer at the end of a pipeline still
/// names the materials a segmentation file named (vtkLabelImageReader puts them on the image).
void PassMaterialTable(vtkFieldData* from, vtkFieldData* to);
/// `set` when >= 0, else the first value of `input`'s field array `name`, else -1.
double ResolveBound(double set, vtkDataObject* input, const char* name);
/// Array `name` of `values`, as ArrayT (vtkIntArray, vtkDoubleArray, vtkStringArray).
template <typename ArrayT, typename T>
void AddField(vtkFieldData* fd, const char* name, const std::vector<T>& values)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  fd->AddArray(array);
}
/// StageName (string) and StageSeconds (double), one entry per stage.
void AddStageTimings(vtkFieldData* fd, const std::vector<StageTiming>& timings);

/// Measures `mesh` against `image` with the four checks (angles, conformity,
/// distances, topology) and stores the figures under the names of
/// LabelMesherArrayNames.h; calls `finished(check)` after each check and
/// appends one "measure: <check>" timing per check to `timings`.
///
/// The measured distances are upper bounds tight to 1/1024 voxel; a mesh that
/// reaches its bounds (as a decimated one does) can measure a hair above
/// them. The bounds (`imageToMesh`, `meshToImage`) are then certified by the
/// checks' exact test (WithinHausdorff): certified, a figure above its bound
/// is reported as the bound, a valid and tighter upper bound, and
/// HausdorffBoundsCertified is 1; not certified, the figures stay and it is 0.
void AddMeasurements(vtkFieldData* fd, const LabelImage& image, const SimplexMesh& mesh, double imageToMesh,
  double meshToImage, std::vector<StageTiming>& timings, const std::function<void(int checksDone)>& finished);

/// The decimation's parameters and counts (AngleBound, the distances,
/// CellsBefore/After of the kept materials, merges and refusals, relocations,
/// frozen vertices), as vtkMeshDecimator documents them.
void AddDecimationFields(vtkFieldData* fd, const DecimationParameters& parameters, const DecimationCounts& counts,
  std::size_t keptBefore, std::size_t keptAfter);

/// Port 0: `mesh` (index space) in physical space, tetrahedra or triangles,
/// cell data Material (active scalars). Tetrahedra stay positively oriented
/// when the placement reverses orientation.
void PackVolumeMesh(const SimplexMesh& mesh, const ImagePlacement& placement, vtkUnstructuredGrid* output);

/// Index-space points in physical space (double precision).
vtkSmartPointer<vtkPoints> PhysicalPoints(const std::vector<Point3>& points, const ImagePlacement& placement);

/// Port 1: interface faces (triangles, or segments in 2D) in physical space,
/// only the points they use, cell data Materials (the labels on either side).
void PackInterfaces(const SimplexMesh& faces, const std::vector<std::pair<std::int32_t, std::int32_t>>& sides,
  const ImagePlacement& placement, vtkPolyData* output);

} // namespace labelmesher

#endif
