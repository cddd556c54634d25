// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkMeshDecimator
 * @brief   coarsen a vtkLabelOctreeMesher mesh by vertex merges that keep its
 *          angle bound, both Hausdorff distance bounds and the topology of every
 *          material and interface
 *
 * vtkMeshDecimator implements the decimation of section 3.1.3 (Algorithm 4) of
 * J. Xu, "Automatic linear and curvilinear mesh generation driven by validity,
 * fidelity and topological guarantees", PhD dissertation, Old Dominion
 * University, 2020, as a thin adapter over the VTK-free core function
 * labelmesher::DecimateMesh (Filters/Core/Decimation/MeshDecimator.h).
 *
 * Vertices are merged into neighbours along edges, the vertex with the
 * shortest edge first, and a merge is accepted only when
 * 1. (quality) no cell it changes is inverted (exact integer orientation) or
 *    has a dihedral (2D: planar) angle below MinimumAngle;
 * 2. (topology) it keeps the strata: a vertex on an interface moves only
 *    within it, one on a curve where three or more materials meet (or a box
 *    edge) only along it, corners never; and the link condition holds in the
 *    mesh, in every material and every interface around it, with each of them
 *    contracted exactly as the edge: every material region, interface and
 *    curve keeps its homotopy type, so its components and Euler
 *    characteristic (Decimation/TopologyCheck.h states the proof);
 * 3. (fidelity) every face it moves lies within MeshToImageDistance of the
 *    image boundary between its own two materials, and every image boundary
 *    face stays within ImageToMeshDistance of the mesh boundary of each of its
 *    labels, both tested exactly (branch and bound, no sampling).
 * Every cell keeps its material. The mesh must fill its box (background cells
 * included), which keeps the box fixed and the whole mesh free of fold-overs.
 * Between rounds of merges, vertices inside one material move to lattice
 * points that raise the smallest angle around them (RelocateInteriorVertices),
 * which lets further merges pass the angle bound.
 *
 * Input port 0: vtkUnstructuredGrid, the output of vtkLabelOctreeMesher with
 * IncludeBackground on (VTK_TETRA or VTK_TRIANGLE cells, cell array
 * `Material`; field data ImageToMeshDistance and MeshToImageDistance, the
 * bounds it was meshed with). Input port 1: the label image it came from (the
 * same vtkImageData; its point scalars, or the array selected with
 * SetInputArrayToProcess(0, 1, 0, POINTS, name)).
 *
 * Output port 0, vtkUnstructuredGrid: the decimated cells of the kept materials
 * (label 0 dropped unless IncludeBackground), unused points removed, cell
 * array `Material`. Field data (names in LabelMesherArrayNames.h): AngleBound,
 * ImageToMeshDistance, MeshToImageDistance, IncludeBackground, VoxelSize;
 * CellsBefore, CellsAfter (kept cells), Merges, MergeOffers,
 * MergesRejectedByQuality, MergesRejectedByTopology, MergesRejectedByFidelity
 * (each merge refused counts once, under the first check that refused it; they
 * run in that order), VerticesRelocated, FrozenVertices; StageName / StageSeconds; and when
 * MeasureOutput is on the measured MinimumAngle, MaximumAngle, InvertedCells,
 * conformity, both Hausdorff distances and the topology per material, as
 * vtkLabelOctreeMesher writes them. Output port 1, vtkPolyData: the decimated
 * interfaces with `Materials`, as vtkLabelOctreeMesher's port 1.
 *
 * Progress is reported through UpdateProgress; AbortExecute stops the run
 * (the output is then empty).
 *
 * A material table (MaterialLabel, MaterialName, MaterialColor) passes to both
 * outputs: the input mesh's when it has one, else the label image's.
 *
 * @warning Errors (one message, empty output) when port 1 is missing or is not
 * the image of the mesh, when the mesh has no Material array or does not fill
 * its box (the mesher's IncludeBackground was off), when MinimumAngle is not
 * in (0, 30] (3D) or (0, 45] (2D) or the input has a smaller angle, and when
 * the input mesh does not hold the distance bounds asked for (decimation
 * cannot bring a mesh closer to the image).
 *
 * @sa
 * vtkLabelOctreeMesher vtkBezierCurver vtkQuadricDecimation
 */

#ifndef vtkMeshDecimator_h
#define vtkMeshDecimator_h

#include "LabelMesherFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class vtkPolyData;

class LABELMESHERFILTERS_EXPORT vtkMeshDecimator : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkMeshDecimator* New();
  vtkTypeMacro(vtkMeshDecimator, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Smallest dihedral (3D) or planar (2D) angle a merge may create, in
   * degrees: (0, vtkLabelOctreeMesher::GetProvenAngleBound(dimension)], the
   * initial mesh's proven bound; default 15. Smaller angles allow fewer cells.
   * Values are clamped to [0, the larger of the 2D and 3D bounds]; the mesh's
   * own bound is checked when the filter runs.
   */
  virtual void SetMinimumAngle(double degrees);
  vtkGetMacro(MinimumAngle, double);
  ///@}

  ///@{
  /**
   * h(I, M): every point of the image boundary stays within this distance of
   * the mesh boundary (per material). Voxels of the smallest spacing, >= 0; a
   * negative value (the default, -1) takes the bound the input was meshed
   * with (its field data ImageToMeshDistance).
   */
  vtkSetMacro(ImageToMeshDistance, double);
  vtkGetMacro(ImageToMeshDistance, double);
  ///@}

  ///@{
  /**
   * h(M, I): every point of a mesh face between two materials stays within
   * this distance of the image boundary between them. Voxels, >= 0; negative
   * (default -1): the input's MeshToImageDistance.
   */
  vtkSetMacro(MeshToImageDistance, double);
  vtkGetMacro(MeshToImageDistance, double);
  ///@}

  ///@{
  /**
   * Between rounds of merges, move vertices inside one material to lattice
   * points where the smallest angle of their cells is larger, so that more
   * merges pass the angle bound (not in the dissertation; it keeps every
   * guarantee, Decimation/InteriorRelocation.h says why). Default on: 2-3x
   * fewer cells. Off gives the dissertation's merges alone.
   */
  vtkSetMacro(RelocateInteriorVertices, bool);
  vtkGetMacro(RelocateInteriorVertices, bool);
  vtkBooleanMacro(RelocateInteriorVertices, bool);
  ///@}

  ///@{
  /**
   * Keep the background cells (label 0) in the output. Default off.
   */
  vtkSetMacro(IncludeBackground, bool);
  vtkGetMacro(IncludeBackground, bool);
  vtkBooleanMacro(IncludeBackground, bool);
  ///@}

  ///@{
  /**
   * Measure the output (angles, conformity, distances, topology per material)
   * into the field data. Default on.
   */
  vtkSetMacro(MeasureOutput, bool);
  vtkGetMacro(MeasureOutput, bool);
  vtkBooleanMacro(MeasureOutput, bool);
  ///@}

  ///@{
  /**
   * The most memory the whole process may hold, in MiB (mebibytes). Before
   * decimating, the filter estimates what it needs from the input's cell count
   * (Filters/Core/Support/MemoryEstimate.h) and refuses, with an error naming
   * both figures and an empty output, a run that does not fit this limit or
   * A limit set here replaces the machine's available memory (so it may also
   * be raised, counting on swap); the cgroup's memory.max and ulimit -v always
   * count. 0 (the default): the available memory.
   */
  vtkSetClampMacro(MemoryLimit, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  /**
   * The decimated interfaces (output port 1).
   */
  vtkPolyData* GetInterfacesOutput();

protected:
  vtkMeshDecimator();
  ~vtkMeshDecimator() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double MinimumAngle = 15.0;
  double ImageToMeshDistance = -1.0;
  double MeshToImageDistance = -1.0;
  bool RelocateInteriorVertices = true;
  bool IncludeBackground = false;
  bool MeasureOutput = true;
  double MemoryLimit = 0.0;

private:
  vtkMeshDecimator(const vtkMeshDecimator&) = delete;
  void operator=(const vtkMeshDecimator&) = delete;
};

#endif
