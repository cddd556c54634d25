// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkLabelMesher
 * @brief   mesh a multi-label image and decimate the mesh in one pass, block by
 *          block, keeping every guarantee of vtkLabelOctreeMesher and
 *          vtkMeshDecimator without ever holding the whole initial mesh
 *
 * vtkLabelMesher gives the mesh of vtkLabelOctreeMesher (IncludeBackground on)
 * followed by vtkMeshDecimator, with the same guarantees (angle bound, both
 * Hausdorff distances overall and per material, topology of every material),
 * but runs them as one block-streamed pipeline, the VTK-free core function
 * labelmesher::MeshAndDecimate (Filters/Core/Streaming/StreamedPipeline.h):
 * the octree's leaves in Morton order are cut into blocks of about BlockCells
 * initial cells; each block is filled, decimated with its border frozen, and
 * released; the assembled mesh is then checked whole and decimated once more
 * around the borders. Peak memory follows one block and the output instead of
 * the initial mesh, which on large images is several times the output.
 *
 * The mesh depends on BlockCells (the borders lie elsewhere), never on the
 * number of threads. With BlockCells 0 (one block) it is exactly the mesher
 * followed by the decimator.
 *
 * Input port 0: the label image, as vtkLabelOctreeMesher's (integer point
 * scalars or the array selected with SetInputArrayToProcess(0, 0, 0, POINTS,
 * name); 2D when one extent is a single slice).
 *
 * Output port 0, vtkUnstructuredGrid: the decimated cells of the kept
 * materials, cell array `Material`, as vtkMeshDecimator's. Field data: the
 * decimator's (AngleBound, ImageToMeshDistance, MeshToImageDistance,
 * IncludeBackground, VoxelSize, CellsBefore, CellsAfter, Merges, MergeOffers,
 * MergesRejectedBy*, VerticesRelocated, FrozenVertices, measurements when
 * MeasureOutput is on), the mesher's NumberOfLeaves, EstimatedMemory and
 * InterfaceFaces, and Blocks, LargestBlockCells and AssembledCells (cells that
 * entered the last pass); StageName / StageSeconds. Output port 1,
 * vtkPolyData: the decimated interfaces with `Materials`.
 *
 * A material table in the input's field data (MaterialLabel, MaterialName,
 * MaterialColor: vtkLabelImageReader's from a 3D Slicer segmentation) passes to
 * both outputs, so that a writer downstream names the materials.
 *
 * Progress is reported through UpdateProgress; AbortExecute stops the run
 * (the output is then empty).
 *
 * @warning Errors (one message, empty output) for an image that is not a
 * label image (as vtkLabelOctreeMesher), a MinimumAngle outside (0, 30] (3D)
 * or (0, 45] (2D), and a run estimated not to fit in memory.
 *
 * @sa
 * vtkLabelOctreeMesher vtkMeshDecimator vtkBezierCurver
 */

#ifndef vtkLabelMesher_h
#define vtkLabelMesher_h

#include "LabelMesherFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class vtkPolyData;

class LABELMESHERFILTERS_EXPORT vtkLabelMesher : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkLabelMesher* New();
  vtkTypeMacro(vtkLabelMesher, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * h(I, M): every point of the image boundary stays within this distance of
   * the mesh boundary (per material). Voxels of the smallest spacing, >= 0;
   * default 2.
   */
  vtkSetClampMacro(ImageToMeshDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ImageToMeshDistance, double);
  ///@}

  ///@{
  /**
   * h(M, I): every point of a mesh face between two materials stays within
   * this distance of the image boundary between them. Voxels, >= 0; default 2.
   */
  vtkSetClampMacro(MeshToImageDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MeshToImageDistance, double);
  ///@}

  ///@{
  /**
   * Smallest dihedral (3D) or planar (2D) angle of the output, in degrees.
   * Range (0, 30] in 3D and (0, 45] in 2D (the initial mesh's proven bounds);
   * default 15.
   */
  vtkSetClampMacro(MinimumAngle, double, 0.0, 45.0);
  vtkGetMacro(MinimumAngle, double);
  ///@}

  ///@{
  /**
   * Move vertices inside one material between rounds of merges, as
   * vtkMeshDecimator's RelocateInteriorVertices. Default on.
   */
  vtkSetMacro(RelocateInteriorVertices, bool);
  vtkGetMacro(RelocateInteriorVertices, bool);
  vtkBooleanMacro(RelocateInteriorVertices, bool);
  ///@}

  ///@{
  /**
   * Initial cells per block (a count): a block is closed once its leaves made
   * this many. Peak memory grows with it by about 200 bytes a cell; smaller
   * blocks leave more borders for the last pass. Default 1,000,000; 0: one
   * block (the mesher followed by the decimator, exactly).
   */
  vtkSetMacro(BlockCells, vtkIdType);
  vtkGetMacro(BlockCells, vtkIdType);
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
   * The most memory the whole process may hold, in MiB; as vtkLabelOctreeMesher's
   * MemoryLimit (the estimate is the streamed run's). 0 (default): the
   * available memory.
   */
  vtkSetClampMacro(MemoryLimit, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  /**
   * The decimated interfaces (output port 1).
   */
  vtkPolyData* GetInterfacesOutput();

protected:
  vtkLabelMesher();
  ~vtkLabelMesher() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ImageToMeshDistance = 2.0;
  double MeshToImageDistance = 2.0;
  double MinimumAngle = 15.0;
  bool RelocateInteriorVertices = true;
  vtkIdType BlockCells = 1000000;
  bool IncludeBackground = false;
  bool MeasureOutput = true;
  double MemoryLimit = 0.0;

private:
  vtkLabelMesher(const vtkLabelMesher&) = delete;
  void operator=(const vtkLabelMesher&) = delete;
};

#endif
