// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkLabelOctreeMesher
 * @brief   mesh a multi-label image into labelled tetrahedra (3D) or triangles (2D)
 *          with proven angle bounds, bounded two-sided Hausdorff distance and the
 *          image's topology per material
 *
 * vtkLabelOctreeMesher takes a label image -- a vtkImageData whose point scalars
 * are integer labels, 0 meaning background -- and produces a conforming simplicial
 * mesh of the labelled regions: tetrahedra when the image is 3D, triangles when one
 * of its extents has a single slice. Every cell carries the label of the material
 * it belongs to, and the faces (edges in 2D) between cells of different labels
 * form a watertight surface that follows the image boundary within the requested
 * distances.
 *
 * The filter is a thin adapter over the VTK-free core function
 * labelmesher::MeshLabelImage (Filters/Core/LabelOctreeMesher.h), which implements
 * the initial mesh of the octree refinement and decimation (ORD) method of
 * J. Xu, "Automatic linear and curvilinear mesh generation driven by validity,
 * fidelity and topological guarantees", PhD dissertation, Old Dominion
 * University, 2020 (and J. Xu, A. Chernikov, "Homeomorphic tetrahedralization of
 * multimaterial images with quality and fidelity guarantees", 26th International
 * Meshing Roundtable, 2017); sections below are the dissertation's:
 *
 * 1. An octree (quadtree in 2D) over the padded image is refined until every leaf
 *    holds one label, or two labels whose image boundary satisfies the single
 *    manifold condition (section 2.4) and lies within both distances of the
 *    leaf's surface patch (tested exactly, not through a distance transform);
 *    2:1 balance across faces and edges, and a neighbour rule that keeps the
 *    configurations the angle proof covers (Filters/Core/Criteria/RefinementCriteria.h).
 * 2. A waterproof surface is extracted leaf by leaf from the labels at the leaf
 *    corners (section 3.1.1, "Waterproof surface mesh").
 * 3. Every leaf is filled with tetrahedra (triangles) coned from its centre to a
 *    triangulation of its faces that contains the surface (section 3.1.2).
 *
 * Guarantees. Minimum dihedral angle 30 degrees (3D), minimum planar angle 45
 * degrees (2D): proved by exhaustive enumeration of the face configurations the
 * octree rules allow (Testing/Cxx/Fill/TestAngleBoundEnumeration.cxx); the
 * dissertation's 19.47 degree claim does not hold for its own rules on graded
 * faces, which the neighbour rule excludes. Two-sided Hausdorff distance between
 * the image boundary and the mesh boundary within ImageToMeshDistance and
 * MeshToImageDistance, overall and per material (section 3.2.2). For each
 * material, the same number of components and Euler characteristic as its image
 * region (section 3.2.3). The figures the output actually has are measured by the
 * independent checks in Filters/Core/Checks and written into the field data (see
 * below), so a pipeline can verify them rather than trust them.
 *
 * Geometry. Voxel (i, j, k) is centred at its VTK point; the image boundary runs
 * along the voxel faces half way between points. Output points are in physical
 * coordinates, physical = origin + direction * (index * spacing), honouring the
 * input's direction matrix. Anisotropic images are first resampled
 * (nearest neighbour) to isotropic voxels of the smallest spacing, keeping the
 * physical extent of the voxels; all distances (parameters and measurements) are
 * then in units of that smallest spacing (the field data array VoxelSize gives it
 * in physical units). A 2D image may lie in any axis plane (a single slice along
 * x, y or z); its triangles lie in that plane.
 *
 * Output port 0, vtkUnstructuredGrid: VTK_TETRA (3D, positively oriented) or
 * VTK_TRIANGLE (2D) cells. Cell data: int array `Material` (the image label, also
 * the active scalars). Cells of label 0 are dropped unless IncludeBackground is on
 * (vtkMeshDecimator needs them). Field data (names in LabelMesherArrayNames.h):
 * - `ImageToMeshDistance`, `MeshToImageDistance`, `IncludeBackground`: the
 *   parameters used; `VoxelSize`: physical length of one distance unit;
 *   `NumberOfLeaves`: octree leaves; `EstimatedMemory` (MiB) and
 *   `InterfaceFaces`: the memory check's estimate and what it was priced from;
 * - `StageName` (string) and `StageSeconds` (double): wall time per stage of the
 *   core, and one `measure: ...` stage per check;
 * - when MeasureOutput is on: `MinimumAngle`, `MaximumAngle` (degrees, dihedral
 *   in 3D, planar in 2D, over the output cells), `InvertedCells`;
 *   `OverSharedFaces`, `HangingVertices`, `NonManifoldBoundaryEdges`
 *   (conformity); `MeasuredImageToMeshDistance`, `MeasuredMeshToImageDistance`
 *   (upper bounds on the one-sided Hausdorff distances, distance units, tight to
 *   1/1024; a figure above its bound that the checks' exact test certifies
 *   is reported as the bound) and `HausdorffBoundsCertified` (1: both bounds
 *   certified by that test); and, one
 *   tuple per non-zero material, `TopologyMaterial`, `ImageComponents`,
 *   `ImageEulerCharacteristic`, `MeshComponents`, `MeshEulerCharacteristic`,
 *   `TopologyMatches` (1 or 0).
 *
 * Output port 1, vtkPolyData (GetInterfacesOutput(), "Interfaces" in ParaView):
 * the interfaces, faces between different materials (the background included):
 * triangles in 3D, lines in 2D, with the 2-component int cell array `Materials`
 * holding the labels on either side.
 *
 * A material table in the input's field data (MaterialLabel, MaterialName,
 * MaterialColor: vtkLabelImageReader's from a 3D Slicer segmentation) passes to
 * both outputs, so that a writer downstream names the materials.
 *
 * Progress is reported through UpdateProgress (with the stage as ProgressText) and
 * AbortExecute stops the run (the output is then empty).
 *
 * @warning Input must be a single-component integer image (any integer type) with
 * non-negative labels that fit in 32-bit signed integers and at least one
 * non-zero voxel; otherwise the filter reports an error and produces empty output.
 * Only the point scalars (or the array selected with SetInputArrayToProcess on
 * points) are used. The distances are in voxel units of the smallest spacing, not
 * physical units. On 3D voxel data the boundary leaves end up one voxel in size
 * (the README's "Limitation"), so the mesh is large: vtkMeshDecimator coarsens it
 * within the same guarantees.
 *
 * @sa
 * vtkMeshDecimator vtkBezierCurver vtkSurfaceNets3D vtkDiscreteFlyingEdges3D
 */

#ifndef vtkLabelOctreeMesher_h
#define vtkLabelOctreeMesher_h

#include "LabelMesherFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <cstddef> // For std::size_t
#include <vector>  // For the timings

class vtkFieldData;
class vtkPolyData;
namespace labelmesher
{
class LabelImage;
struct SimplexMesh;
struct StageTiming;
}

class LABELMESHERFILTERS_EXPORT vtkLabelOctreeMesher : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkLabelOctreeMesher* New();
  vtkTypeMacro(vtkLabelOctreeMesher, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The smallest angle of every mesh this filter makes, in degrees: dihedral in 3D (30), planar
   * in 2D (45), proven by enumerating every cell the fill can emit
   * (Testing/Cxx/Fill/TestAngleBoundEnumeration.cxx). The largest MinimumAngle the decimator
   * (and vtkLabelMesher) accepts for an image of that dimension. The one place front ends take
   * these figures from.
   */
  static double GetProvenAngleBound(int dimension);

  ///@{
  /**
   * h(I, M): every point of the image boundary lies within this distance of the
   * mesh boundary. Units: voxels of the smallest spacing. Range [0, inf), default 2.
   */
  vtkSetClampMacro(ImageToMeshDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ImageToMeshDistance, double);
  ///@}

  ///@{
  /**
   * h(M, I): every point of the mesh boundary lies within this distance of the
   * image boundary. Units: voxels of the smallest spacing. Range [0, inf), default 2.
   */
  vtkSetClampMacro(MeshToImageDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MeshToImageDistance, double);
  ///@}

  ///@{
  /**
   * Keep the cells of label 0 (the background around and between the labelled
   * regions, up to the padded octree domain). Default off.
   */
  vtkSetMacro(IncludeBackground, bool);
  vtkGetMacro(IncludeBackground, bool);
  vtkBooleanMacro(IncludeBackground, bool);
  ///@}

  ///@{
  /**
   * Measure the output (angles, conformity, Hausdorff distances, topology per
   * material) and store the figures in the field data. Costs one to two times
   * the meshing. Default on.
   */
  vtkSetMacro(MeasureOutput, bool);
  vtkGetMacro(MeasureOutput, bool);
  vtkBooleanMacro(MeasureOutput, bool);
  ///@}

  ///@{
  /**
   * The most memory the whole process may hold, in MiB (mebibytes). Before
   * meshing, the filter estimates what the run needs from the image (its size
   * and the voxel faces between labels, Filters/Core/Support/MemoryEstimate.h)
   * and refuses, with an error naming both figures and an empty output, a run
   * that does not fit. A limit set here replaces the machine's available
   * memory (so it may also be raised, counting on swap); the cgroup's
   * memory.max and ulimit -v always count. 0 (the default): the available memory.
   */
  vtkSetClampMacro(MemoryLimit, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  ///@{
  /**
   * Count a vtkMeshDecimator run on this output in the memory check, so that a
   * mesh that could not be decimated is refused before it is built. Default off.
   */
  vtkSetMacro(CheckMemoryForDecimation, bool);
  vtkGetMacro(CheckMemoryForDecimation, bool);
  vtkBooleanMacro(CheckMemoryForDecimation, bool);
  ///@}

  /**
   * The interfaces: faces between different materials, cell array `Materials` (output port 1).
   */
  vtkPolyData* GetInterfacesOutput();

protected:
  vtkLabelOctreeMesher();
  ~vtkLabelOctreeMesher() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Pass 3 of RequestData: the parameters and octree size in the field data.
  void AddParameters(vtkFieldData* fd, double voxelSize, std::size_t leaves) const;
  /// Pass 4: the checks on the kept cells, when MeasureOutput is on.
  void Measure(vtkFieldData* fd, const labelmesher::LabelImage& image, const labelmesher::SimplexMesh& kept,
    double measureStart, std::vector<labelmesher::StageTiming>& timings);

  double ImageToMeshDistance = 2.0;
  double MeshToImageDistance = 2.0;
  bool IncludeBackground = false;
  bool MeasureOutput = true;
  double MemoryLimit = 0.0;
  bool CheckMemoryForDecimation = false;

private:
  vtkLabelOctreeMesher(const vtkLabelOctreeMesher&) = delete;
  void operator=(const vtkLabelOctreeMesher&) = delete;
};

#endif
