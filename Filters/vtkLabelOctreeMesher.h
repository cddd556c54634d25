// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkLabelOctreeMesher
 * @brief   mesh a multi-label image into labelled tetrahedra (3D) or triangles (2D)
 *          with bounded angles and bounded two-sided Hausdorff distance
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
 * the initial mesh of the ORD method (F. Drakopoulos, "Automatic linear and
 * curvilinear mesh generation driven by validity, fidelity and topological
 * guarantees", PhD dissertation, Old Dominion University; referred to below by
 * section):
 *
 * 1. An octree (quadtree in 2D) over the padded image is refined until every leaf
 *    that touches the image boundary (section 2.1) lies within the fidelity
 *    distance of it, holds at most two labels and satisfies the single manifold
 *    condition (section 2.4); the tree is then balanced by the 2-to-1 rule across
 *    faces and edges (section 2.2; Algorithm 2 of section 3.1.1).
 * 2. A waterproof surface is extracted leaf by leaf from the signs of the leaf
 *    corners (section 3.1.1, "Waterproof surface mesh").
 * 3. Every leaf is filled with tetrahedra (triangles) coned from its centre to a
 *    triangulation of its faces that contains the surface (section 3.1.2).
 *
 * Section 3.2 states the guarantees: a minimum dihedral (2D: planar) angle of
 * 19.47 degrees (3.2.1), two-sided Hausdorff distance between the image boundary
 * and the mesh boundary within ImageToMeshDistance and MeshToImageDistance (3.2.2)
 * and, for each material, the same topology as the image region (3.2.3). The
 * figures this implementation actually achieves are measured by the checks in
 * Filters/Core/Checks and written into the output's field data (see below), so a
 * pipeline can verify them rather than trust them.
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
 * the active scalars). Cells of label 0 are dropped unless IncludeBackground is on.
 * Field data:
 * - `ImageToMeshDistance`, `MeshToImageDistance`, `IncludeBackground`: the
 *   parameters used; `VoxelSize`: physical length of one distance unit;
 *   `NumberOfLeaves`: octree leaves;
 * - `StageName` (string) and `StageSeconds` (double): wall time per stage of the
 *   core (and `measure` for the checks);
 * - when the checks are built and MeasureOutput is on: `MinimumAngle`,
 *   `MaximumAngle` (degrees, dihedral in 3D, planar in 2D, over the output
 *   cells), `InvertedCells`, `MeasuredImageToMeshDistance`,
 *   `MeasuredMeshToImageDistance` (upper bounds on the one-sided Hausdorff
 *   distances, distance units) and, one tuple per non-zero material,
 *   `TopologyMaterial`, `ImageComponents`, `ImageEulerCharacteristic`,
 *   `MeshComponents`, `MeshEulerCharacteristic`, `TopologyMatches` (1 or 0).
 *
 * Output port 1, vtkPolyData: the boundary between different materials (the
 * background included): triangles in 3D, lines in 2D, with the 2-component int
 * cell array `Materials` holding the labels on either side.
 *
 * Progress is reported through UpdateProgress (with the stage as ProgressText) and
 * AbortExecute stops the run (the output is then empty).
 *
 * @warning Input must be a single-component integer image (any integer type) with
 * non-negative labels that fit in 32-bit signed integers and at least one
 * non-zero voxel; otherwise the filter reports an error and produces empty output.
 * Only the point scalars (or the array selected with SetInputArrayToProcess on
 * points) are used. The distances are in voxel units of the smallest spacing, not
 * physical units. The 19.47 degree bound is the dissertation's claim; the
 * project's issue notes record which configurations have been verified.
 *
 * @sa
 * vtkSurfaceNets3D vtkDiscreteFlyingEdges3D vtkImageToPoints vtkDelaunay3D
 */

#ifndef vtkLabelOctreeMesher_h
#define vtkLabelOctreeMesher_h

#include "LabelMesherFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class vtkPolyData;

class LABELMESHERFILTERS_EXPORT vtkLabelOctreeMesher : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkLabelOctreeMesher* New();
  vtkTypeMacro(vtkLabelOctreeMesher, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
   * Measure the output (angles, Hausdorff distances, topology per material) and
   * store the figures in the field data. Costs roughly as much as meshing.
   * Default on; has no effect when the checks are not built.
   */
  vtkSetMacro(MeasureOutput, bool);
  vtkGetMacro(MeasureOutput, bool);
  vtkBooleanMacro(MeasureOutput, bool);
  ///@}

  /**
   * The boundary surface (output port 1).
   */
  vtkPolyData* GetBoundaryOutput();

protected:
  vtkLabelOctreeMesher();
  ~vtkLabelOctreeMesher() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ImageToMeshDistance = 2.0;
  double MeshToImageDistance = 2.0;
  bool IncludeBackground = false;
  bool MeasureOutput = true;

private:
  vtkLabelOctreeMesher(const vtkLabelOctreeMesher&) = delete;
  void operator=(const vtkLabelOctreeMesher&) = delete;
};

#endif
