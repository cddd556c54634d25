// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkLabelMesher
 * @brief   the whole LabelMesher pipeline in one filter: mesh a multi-label image,
 *          decimate the mesh block by block, and (2D, on request) curve it
 *
 * vtkLabelMesher is what every front end runs (the labelmesher CLI, the
 * desktop viewer, the 3D Slicer module, ParaView's "Label Mesher", the entry
 * of all stages): they set its parameters and show its outputs, nothing more.
 *
 * Decimate on (default): the mesh of vtkLabelOctreeMesher (IncludeBackground
 * on) followed by vtkMeshDecimator, with the same guarantees (angle bound, both
 * Hausdorff distances overall and per material, topology of every material),
 * run as one block-streamed pipeline, the VTK-free core function
 * labelmesher::MeshAndDecimate (Filters/Core/Streaming/StreamedPipeline.h):
 * the octree's leaves in Morton order are cut into blocks of about BlockCells
 * initial cells; each block is filled, decimated with its border frozen, and
 * released; the assembled mesh is then checked whole and decimated once more
 * around the borders. Peak memory follows one block and the output instead of
 * the initial mesh, which on large images is several times the output. The
 * blocks are grouped PartBlocks to a part, the unit one process meshes when the
 * run is Distributed over mpirun's processes. The mesh depends on BlockCells
 * and PartBlocks (the borders lie elsewhere), never on the number of threads
 * or processes. With BlockCells 0 (one block) it is exactly the mesher
 * followed by the decimator.
 *
 * Decimate off: vtkLabelOctreeMesher's mesh, exactly (the initial mesh, angles
 * at least GetProvenAngleBound).
 *
 * Curve on (2D images only): vtkBezierCurver then curves that mesh with the
 * image (its Smoothness, Tension, MaximumUntanglingSteps,
 * MaximumShorteningRounds, QualityIterations, MinimumScaledJacobian), keeping
 * the bounds the linear mesh records and, at every corner of every curved cell,
 * MinimumAngle between the edges' tangents (vtkBezierCurver's
 * MinimumCornerAngle); the cubic Bezier mesh is output port 2.
 *
 * Order 2 of a 2D image (with Decimate): as Curve, with vtkBezierCurver's
 * Order 2: quadratic triangles (VTK_QUADRATIC_TRIANGLE) on port 2, carrying the
 * same certificates as the cubic ones.
 *
 * Order 2 of a 3D image (with Decimate): the decimated mesh becomes quadratic
 * tetrahedra (Quadratic/QuadraticCurver.h), output port 2: the mid-nodes of
 * interface edges fitted to the image, every cell's min det J / max det J
 * certified at least MinimumScaledJacobian by the Bernstein coefficients of
 * det J, every corner's dihedral angles between its edges' tangents at least
 * MinimumAngle (Quadratic/QuadraticCorners.h), both distance bounds certified
 * on the curved interfaces, curves that fail pulled back towards straight;
 * box faces and junction curves stay straight. Cell data Material,
 * ScaledJacobian (the certified lower bound) and CornerAngle (degrees); field
 * data Order, MinimumScaledJacobianBound, CertifiedMinimumScaledJacobian,
 * CornerAngleBound, CertifiedMinimumCornerAngle, FittedEdges, CurvedEdges,
 * PulledBackEdges, CellsFailedScaledJacobian, CellsFailedCornerAngle,
 * FacesFailedDistance and, with MeasureOutput, the independent measurements
 * (QuadraticOutput.h).
 *
 * Input port 0: the label image, as vtkLabelOctreeMesher's (integer point
 * scalars or the array selected with SetInputArrayToProcess(0, 0, 0, POINTS,
 * name); 2D when one extent is a single slice).
 *
 * Output port 0, vtkUnstructuredGrid: the linear mesh (decimated unless
 * Decimate is off) of the kept materials, cell array `Material`. Field data:
 * the decimator's (AngleBound, ImageToMeshDistance, MeshToImageDistance,
 * IncludeBackground, VoxelSize, CellsBefore, CellsAfter, Merges, MergeOffers,
 * MergesRejectedBy*, VerticesRelocated, FrozenVertices, measurements when
 * MeasureOutput is on), the mesher's NumberOfLeaves, EstimatedMemory and
 * InterfaceFaces, and Blocks, LargestBlockCells, AssembledCells (cells that
 * entered the last pass), BorderPasses (passes over the blocks so far, between
 * blocks) and LargestAssembledCells (the most cells those passes or the last
 * one held); StageName / StageSeconds. Without decimation, the
 * mesher's field data. Output port 1, vtkPolyData: the linear mesh's
 * interfaces with `Materials`. Output port 2, vtkUnstructuredGrid: with Curve,
 * vtkBezierCurver's output (VTK_BEZIER_TRIANGLE cells and its field data);
 * empty otherwise. vtkLabelMeshReport turns these into the run's report.
 *
 * A material table in the input's field data (MaterialLabel, MaterialName,
 * MaterialColor: vtkLabelImageReader's from a 3D Slicer segmentation) passes to
 * every output, so that a writer downstream names the materials.
 *
 * Progress is reported through UpdateProgress, over the whole run (the stages'
 * shares are their rough weights on real images); AbortExecute stops the run
 * in whichever stage it is, at that stage's next progress report (the outputs
 * are then empty, and a warning says so). Measuring cannot stop: a request
 * while the mesh or the curves are being measured leaves the complete outputs.
 *
 * @warning Errors (one message) for an image that is not a label image (as
 * vtkLabelOctreeMesher), a MinimumAngle outside (0, GetProvenAngleBound], a
 * run estimated not to fit in memory, Curve on a 3D image, Order 2
 * without Decimate (or with Curve), and a curving that
 * fails: the outputs are then empty. A curving whose untangling fails is an
 * error too, but port 2 then holds the curver's marked mesh (cell data Valid),
 * to inspect, and ports 0 and 1 the linear mesh.
 *
 * @sa
 * vtkLabelOctreeMesher vtkMeshDecimator vtkBezierCurver vtkLabelMeshReport
 */

#ifndef vtkLabelMesher_h
#define vtkLabelMesher_h

#include "LabelMesherFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <string> // For UpdateInputExtent

class vtkDataArray;
class vtkImageData;
class vtkPolyData;
class vtkUnstructuredGrid;

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

  /**
   * True when an image of point dimensions `dims` and `spacing` is meshed as it
   * is (isotropic voxels along its meshed axes; a 2D image across z, neither
   * resampled nor permuted): a process other than rank 0 of a Distributed run
   * then reads only the slab its parts need, from an input that can produce
   * any extent.
   */
  static bool ReadsSlabsOf(const int dims[3], const double spacing[3]);

  /**
   * The smallest dihedral (3D, dimension 3) or planar (2D) angle, in degrees,
   * that the initial mesh is proven to keep (by enumerating every cell the
   * fill can emit): the largest MinimumAngle a decimation may ask for.
   */
  static double GetProvenAngleBound(int dimension);

  /**
   * 2 when one of the image's extents is a single slice (a 2D image: triangles,
   * curving possible), else 3.
   */
  static int GetImageDimension(vtkImageData* image);

  ///@{
  /**
   * The names of the arrays a script needs (LabelMesherArrayNames.h): the
   * cell array of material labels, and the material table's field arrays
   * (label, name, colour) that the filters pass from the image to the mesh.
   */
  static const char* GetMaterialArrayName();
  static const char* GetMaterialLabelArrayName();
  static const char* GetMaterialNameArrayName();
  static const char* GetMaterialColorArrayName();
  ///@}

  ///@{
  /**
   * Decimate the initial mesh (vtkMeshDecimator's merges, streamed by blocks).
   * Off: the initial mesh is the output. Default on.
   */
  vtkSetMacro(Decimate, bool);
  vtkGetMacro(Decimate, bool);
  vtkBooleanMacro(Decimate, bool);
  ///@}

  ///@{
  /**
   * Smallest dihedral (3D) or planar (2D) angle the decimation keeps, in
   * degrees: (0, GetProvenAngleBound(dimension)]; default 15. Also the corner
   * angle the curved cells keep (Curve, Order 2). Values are
   * clamped to [0, the larger of the two bounds]; the image's own bound is
   * checked when the filter runs.
   */
  virtual void SetMinimumAngle(double degrees);
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
   * Blocks per part (a count): a part is the blocks one process meshes when
   * the run is Distributed; rank 0 joins the parts. The mesh depends on it
   * (never on the number of processes). Default 2; 0: one part.
   */
  vtkSetMacro(PartBlocks, vtkIdType);
  vtkGetMacro(PartBlocks, vtkIdType);
  ///@}

  ///@{
  /**
   * Share the run out over MPI's processes when MPI runs with more than one
   * (mpirun, started by the application): every process must be given the
   * same image and parameters; each meshes its parts, and rank 0 joins them
   * into the mesh one process makes. When the pipeline asks each process for
   * its own piece (piece `rank` of as many as there are processes, as
   * ParaView's does), each process's output is the cells of the parts it
   * meshed (cell array Process) with the run's field data, without ghost
   * cells (the interfaces and curved outputs stay whole on rank 0); otherwise
   * rank 0's output is the whole mesh and the others' are empty. A process that fails makes rank 0 fail with its rank and
   * reason; every process's image geometry and parameters are compared with
   * rank 0's first, and the labels of each slab a process meshes with rank 0's.
   * Rank 0 asks its input for the whole image. Another process whose input can
   * produce any extent (vtkLabelImageReader) asks for none at first, then for
   * just the slab of slices its parts need (plus a margin), when the image is
   * meshed as it is (isotropic voxels; a 2D image across z); else for the whole
   * image too. Default off here (a process meshes its input alone); on in the
   * ParaView plugin.
   */
  vtkSetMacro(Distributed, bool);
  vtkGetMacro(Distributed, bool);
  vtkBooleanMacro(Distributed, bool);
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

  ///@{
  /**
   * Curve the linear mesh into cubic Bezier triangles (vtkBezierCurver, 2D
   * images only), output port 2. Default off.
   */
  vtkSetMacro(Curve, bool);
  vtkGetMacro(Curve, bool);
  vtkBooleanMacro(Curve, bool);
  ///@}

  ///@{
  /**
   * The curver's parameters, as vtkBezierCurver's (same defaults): Smoothness
   * 1 (C1, fitted to the image) or 2 (C2); Tension, the C1 handle length
   * factor, dimensionless in [0, 1]; MaximumUntanglingSteps (load steps, >= 1);
   * MaximumShorteningRounds (>= 1); QualityIterations (>= 0).
   */
  vtkSetClampMacro(Smoothness, int, 1, 2);
  vtkGetMacro(Smoothness, int);
  vtkSetClampMacro(Tension, double, 0.0, 1.0);
  vtkGetMacro(Tension, double);
  vtkSetClampMacro(MaximumUntanglingSteps, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumUntanglingSteps, int);
  vtkSetClampMacro(MaximumShorteningRounds, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumShorteningRounds, int);
  vtkSetClampMacro(QualityIterations, int, 0, VTK_INT_MAX);
  vtkGetMacro(QualityIterations, int);
  ///@}

  ///@{
  /**
   * The order of the output on port 2: 1 (default: none) or 2 (quadratic
   * tetrahedra fitted to the image of a 3D image, quadratic triangles of a 2D
   * one; with Decimate, without Curve).
   */
  vtkSetClampMacro(Order, int, 1, 2);
  vtkGetMacro(Order, int);
  ///@}

  ///@{
  /**
   * The smallest certified scaled Jacobian (min det J / max det J) of every
   * curved cell, as vtkBezierCurver's MinimumScaledJacobian: [0, 1), default
   * 0.1. Also the quadratic mesh's (Order 2).
   */
  vtkSetClampMacro(MinimumScaledJacobian, double, 0.0, 0.999);
  vtkGetMacro(MinimumScaledJacobian, double);
  ///@}

  /**
   * The linear mesh's interfaces (output port 1).
   */
  vtkPolyData* GetInterfacesOutput();

  /**
   * The curved mesh (output port 2; empty unless Curve is on or Order is 2).
   */
  vtkUnstructuredGrid* GetCurvedOutput();

protected:
  vtkLabelMesher();
  ~vtkLabelMesher() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Distributed and Decimate on, under MPI with more than one process.
  bool SharesOutAcrossProcesses() const;
  /// A process other than rank 0 of a shared-out run whose input can produce any extent and
  /// is meshed as it is (no permutation, no resampling): it asks its input for no voxels at
  /// first, and for the slab its parts need once rank 0 has assigned them.
  bool ReadsItsSlabOnly(vtkInformation* inputInformation) const;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool Decimate = true;
  double ImageToMeshDistance = 2.0;
  double MeshToImageDistance = 2.0;
  double MinimumAngle = 15.0;
  bool RelocateInteriorVertices = true;
  vtkIdType BlockCells = 1000000;
  vtkIdType PartBlocks = 2;
  bool Distributed = false;
  /// Set by MeshAndDecimate when the run stopped on every process at once (a failure they agreed
  /// on): each has said why, and none waits for pieces (RequestData).
  bool StoppedOnEveryProcess = false;
  bool IncludeBackground = false;
  bool MeasureOutput = true;
  double MemoryLimit = 0.0;
  bool Curve = false;
  int Smoothness = 1;
  double Tension = 1.0 / 3.0;
  int MaximumUntanglingSteps = 64;
  int MaximumShorteningRounds = 8;
  int QualityIterations = 0;
  double MinimumScaledJacobian = 0.1;
  int Order = 1;

private:
  // The stages; each returns false when the run ends there (error, abort, no cells).
  /// With Order 2, also the quadratic mesh into `quadratic`.
  /// `slabOnly`: `input` is the image's geometry alone, and the labels are read slab by slab.
  bool MeshAndDecimate(vtkImageData* input, vtkDataArray* labels, bool slabOnly, vtkUnstructuredGrid* output,
    vtkPolyData* interfaces, vtkUnstructuredGrid* quadratic, double share);
  /// On a process that ReadsItsSlabOnly: its input brought up to date with `extent`, the
  /// labels in it (null when there are none), and the producer's first error (empty if none).
  vtkImageData* UpdateInputExtent(const int extent[6], vtkDataArray*& labels, std::string& problem);
  bool MeshOnly(vtkImageData* input, vtkUnstructuredGrid* output, vtkPolyData* interfaces, double share);
  /// Collective, on every process of a shared-out run: "" when every process meshes what rank 0
  /// does (image, parameters) and asks for the same output (`handsOutPieces`: each process its
  /// own piece, as pvbatch does), else the lowest differing process's reason, on every process.
  std::string FirstDifferenceBetweenProcesses(vtkImageData* input, bool slabOnly, bool handsOutPieces);
  /// False when stopped on request before the curver made its mesh.
  bool CurveMesh(vtkImageData* input, vtkUnstructuredGrid* linear, vtkUnstructuredGrid* curved, double start);

  vtkLabelMesher(const vtkLabelMesher&) = delete;
  void operator=(const vtkLabelMesher&) = delete;
};

#endif
