// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @class   vtkBezierCurver
 * @brief   curve a 2D labelled triangle mesh into a valid cubic Bézier mesh with
 *          C1 or C2 smooth material boundaries
 *
 * vtkBezierCurver implements the curvilinear mesher of chapter 4 of J. Xu,
 * "Automatic linear and curvilinear mesh generation driven by validity,
 * fidelity and topological guarantees", PhD dissertation, Old Dominion
 * University, 2020 (director A. Chernikov), as a thin adapter
 * over the VTK-free core function labelmesher::CurveMesh
 * (Filters/Core/Curving/BezierCurver.h):
 *
 * 1. Every interface between two materials, and between a material and the
 *    outside, becomes a cubic Bézier path through the linear mesh's boundary
 *    vertices (section 4.1). C1 (the default): with the image on port 1, the
 *    handles of Figure 17a's family are fitted by least squares to the
 *    midpoints of the pixel edges between the two materials
 *    (Core/Curving/BoundaryFit.h), so that the curve follows the image between
 *    vertices; without the image, the tangent construction of Figure 17a. C2:
 *    the B-spline system 6 S_i = B_{i-1} + 4 B_i + B_{i+1} (Figure 17c), which
 *    the vertices fix entirely. Closed loops are periodic; chains ending where
 *    three or more materials meet, or on the image border, are open and keep
 *    their end vertices. Edges on the image border stay straight.
 * 2. With the image and distance bounds (ImageToMeshDistance,
 *    MeshToImageDistance, by default the bounds the input records), every piece
 *    of curve that would break a bound is shortened -- both handles scaled by
 *    1/2, 1/4, then straight -- until both bounds hold on the curves, certified
 *    on polylines within 1/256 voxel of them (Core/Curving/CurveFidelity.h).
 * 3. The other control points (interior edges, cell centres) follow by linear
 *    elasticity on the control nets, the boundary displacement applied in
 *    increasing fractions until every cell is valid (section 4.3, Figure 21).
 *    Cells still invalid have their curved edges (or, if none, the curves at
 *    their corners, ring by ring) shortened the same way -- made straight
 *    from a cell's second invalid round -- and untangling runs again, up to 8
 *    rounds; straight pieces make a straight, valid mesh.
 *    A shortened piece keeps its end tangents' directions: the joints stay
 *    tangent continuous (G1); C1 or C2 holds where neither piece was shortened.
 * 4. Every cell's Jacobian determinant, a quartic Bézier triangle (Table 1), is
 *    bounded by subdivision (section 4.2); a cell is valid when that bound or its
 *    control net (with the corrected conditions of JacobianBound.h) proves det J > 0.
 *
 * Input port 0: vtkUnstructuredGrid of VTK_TRIANGLE cells lying in one axis plane
 * (x-y, x-z or y-z; e.g. vtkLabelOctreeMesher's 2D output) with an integer cell
 * array `Material` (0 = background). Input port 1 (optional): the label image the
 * mesh came from (2D vtkImageData of integer labels, as for vtkLabelOctreeMesher:
 * its point scalars, or the array selected with SetInputArrayToProcess(0, 1, 0,
 * POINTS, name));
 * when given, its border box is the border whose edges stay straight, the C1
 * curves are fitted to it, the distance bounds are kept against it, and the
 * accuracy of the linear and of the curved mesh is measured on it. Without it
 * every interface is curved, including any that runs along the image border.
 *
 * Output: vtkUnstructuredGrid of VTK_BEZIER_TRIANGLE cells of degree 3 (10 points
 * each in VTK's order; edge points shared by neighbouring cells), which ParaView
 * renders curved; with Order 2, VTK_QUADRATIC_TRIANGLE cells (6 nodes, mid-nodes
 * shared). Cell data:
 * - `Material` (int): copied from the input;
 * - `MinimumJacobian` (double): proven lower bound of det J over the cell, J the
 *   Jacobian of the map from the reference triangle (0,0), (1,0), (0,1) to the
 *   cell; physical units squared (a straight cell has 2 x its area);
 * - `ScaledJacobian` (double): MinimumJacobian / proven upper bound of det J, a
 *   conservative min|J| / max|J| (1 for straight cells, <= 0 for invalid ones);
 * - `Valid` (unsigned char): 1 where det J > 0 is proven;
 * - `CornerAngle` (double): the smallest angle between the tangents of two
 *   edges at a corner, degrees (kept at MinimumCornerAngle, see below).
 * Field data: `Smoothness`, `Tension`, `MaximumUntanglingSteps`, `MaximumShorteningRounds`,
 * `QualityIterations`; `InvalidBeforeUntangling` (cells made invalid by curving
 * the boundary alone), `InvalidCells`, `UntanglingSteps`, `InterfaceChains`,
 * `ClosedInterfaceChains`, `CurvedEdges`, `SplitEars` (edges split before curving,
 * see below); `StageName` / `StageSeconds`; with an
 * image: `Pixels`, `MisclassifiedPixelsLinear`, `MisclassifiedPixelsCurved`
 * (pixels whose label differs from the mesh material at their centre; cells of
 * material 0 count as outside; an anisotropic image is counted as meshed, i.e.
 * resampled to square pixels of its smallest spacing; a centre exactly on an
 * edge counts for the first cell found) and, one tuple per label, `AccuracyMaterial`,
 * `MissedPixelsLinear`, `MissedPixelsCurved` (its pixels given another material),
 * `ClaimedPixelsLinear`, `ClaimedPixelsCurved` (other pixels given it);
 * `ShortenedPieces`, `StraightenedPieces` (interface pieces left shortened, and
 * of those straight), `PiecesShortenedForBounds`, `PiecesShortenedForValidity`,
 * `UncertifiedPieces` (straight pieces the distance test could not certify,
 * expected 0), `UntanglingRounds`; and measured on the curves
 * (Core/Checks/CurvedBoundary.h, on polylines within 1/1024 voxel of the
 * curves; the figures may exceed the true distances by at most
 * `CurvedMeasureResolution` = 2/1024 voxel): `ImageToMeshDistance`, `MeshToImageDistance` (the bounds kept, -1 for
 * none), `MeasuredImageToMeshDistance`, `MeasuredMeshToImageDistance` (upper
 * bounds, voxels), `InterfaceCrossings` (boundary segments that cross or touch
 * another away from a shared vertex) and `TopologyMatches` (components and
 * Euler characteristic of every material equal the image's).
 *
 * Ears -- cells with two edges on one smooth interface chain -- would have
 * det J = 0 at their corner once curved. With MinimumCornerAngle 0, their third
 * edge is split at its midpoint first (with the cell across it): the output may
 * have a few more cells than the input, over the same region, and the split
 * may halve angles. Otherwise (the default) nothing is split: the interface
 * turns at the ear's vertex (a corner; each side's tangent fitted on its own;
 * field data `EarCorners`), and that corner keeps the angle bound like any other.
 *
 * Quality: every cell's certified scaled Jacobian (cell data `ScaledJacobian`,
 * min det J / max det J bounded by the Bernstein coefficients of det J with
 * subdivision) is at least MinimumScaledJacobian (default 0.1): the curves
 * around a cell below it are shortened as for an invalid cell, straightened at
 * once after MaximumShorteningRounds, for up to 8 more rounds; if cells are
 * still below it then, every curve is made straight (field data
 * `MinimumScaledJacobianBound`, `CellsBelowScaledJacobian`,
 * `StraightenedForScaledJacobian`). In the same way every corner angle (the
 * angle between the tangents of a cell's two edges at a corner, cell data
 * `CornerAngle`) is at least MinimumCornerAngle (default 15 degrees), or the
 * input mesh's smallest angle when that is smaller (a warning says so): field
 * data `CornerAngleBound`, `CellsBelowCornerAngle`, `StraightenedForCornerAngle`.
 *
 * Once untangling has made the mesh valid, a later round that shortened curves
 * for quality may break a cell again: such cells get the curves around them
 * straightened for up to 8 more rounds, and if one is still invalid then,
 * every curve is made straight (field data `StraightenedForValidity`; the
 * linear cells are valid). If untangling never makes the mesh valid within
 * MaximumUntanglingSteps and MaximumShorteningRounds, the filter reports an
 * error naming the count and outputs the mesh with those cells marked
 * (`Valid` = 0) for inspection: an invalid mesh is never passed on silently.
 * Progress is reported by stage; AbortExecute stops the run (empty output).
 *
 * A material table in the input mesh's field data (MaterialLabel, MaterialName,
 * MaterialColor) passes to the output.
 *
 * @sa vtkLabelOctreeMesher vtkBezierTriangle
 */

#ifndef vtkBezierCurver_h
#define vtkBezierCurver_h

#include "LabelMesherFiltersModule.h" // For export macro
#include "vtkUnstructuredGridAlgorithm.h"

class LABELMESHERFILTERS_EXPORT vtkBezierCurver : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkBezierCurver* New();
  vtkTypeMacro(vtkBezierCurver, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Continuity of the curved material boundaries: 1 (C1, fitted to the image
   * when there is one, else the tangent construction) or 2 (C2, B-spline
   * interpolation). Default 1: only C1 curves can follow the image between
   * vertices, and on decimated meshes only they are more accurate than the
   * linear mesh (README, "Curved meshes").
   */
  vtkSetClampMacro(Smoothness, int, 1, 2);
  vtkGetMacro(Smoothness, int);
  ///@}

  ///@{
  /**
   * C1 only: length of the tangent handles as a fraction of the translated chord
   * of Figure 17a (dimensionless, [0, 1]); 1/3 on evenly spaced vertices gives
   * the Catmull-Rom spline, 0 straight edges. With an image, the handles the
   * fit is pulled towards where the image says little. Default 1/3.
   */
  vtkSetClampMacro(Tension, double, 0.0, 1.0);
  vtkGetMacro(Tension, double);
  ///@}

  ///@{
  /**
   * Most fractions the boundary displacement is split into while untangling
   * (tried 1, 2, 4, ... up to this). Default 64.
   */
  vtkSetClampMacro(MaximumUntanglingSteps, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumUntanglingSteps, int);
  ///@}

  ///@{
  /**
   * Most untangling rounds: after each that leaves cells invalid, the curves
   * of those cells are shortened (see the class description) and untangling
   * runs again. Default 8 (three shortenings make a curve straight).
   */
  vtkSetClampMacro(MaximumShorteningRounds, int, 1, VTK_INT_MAX);
  vtkGetMacro(MaximumShorteningRounds, int);
  ///@}

  ///@{
  /**
   * Further doublings of the fractions after the mesh is valid, each kept when
   * the worst scaled Jacobian improves. Default 0.
   */
  vtkSetClampMacro(QualityIterations, int, 0, VTK_INT_MAX);
  vtkGetMacro(QualityIterations, int);
  ///@}

  ///@{
  /**
   * The smallest scaled Jacobian every cell keeps, certified (min det J / max
   * det J bounded by the Bernstein coefficients of det J with subdivision;
   * cell data `ScaledJacobian`): dimensionless, [0, 1). Cells below it get the
   * curves around them shortened, as invalid cells do; if the rounds run out
   * first, every curve is made straight (the linear cells have 1). Default
   * 0.1 (what Gmsh's high-order optimiser aims at, Mesh.HighOrderThresholdMin);
   * 0: validity alone.
   */
  vtkSetClampMacro(MinimumScaledJacobian, double, 0.0, 0.999);
  vtkGetMacro(MinimumScaledJacobian, double);
  ///@}

  ///@{
  /**
   * The smallest corner angle every cell keeps: the angle between the
   * tangents of two edges at a cell corner, degrees, [0, 179]. Curving turns
   * the edges at a vertex away from their chords, so without it corners fall
   * below the linear mesh's angle bound. Cells below it get the curves around
   * them shortened, as invalid cells do; if the rounds run out first, every
   * curve is made straight (a straight cell's corners are its angles). Bounded
   * by the input mesh's smallest angle (the bound kept is the smaller of the
   * two, field data `CornerAngleBound`). Default 15, vtkMeshDecimator's
   * default; 0: measured only, and ears are split instead of straightened.
   */
  vtkSetClampMacro(MinimumCornerAngle, double, 0.0, 179.0);
  vtkGetMacro(MinimumCornerAngle, double);
  ///@}

  ///@{
  /**
   * The distance bounds the curved interfaces keep against the image on port
   * 1, h(I, M) and h(M, I) in voxels; pieces that would break one are
   * shortened (see the class description). Negative (the default): the bounds
   * recorded in the input's field data (ImageToMeshDistance and
   * MeshToImageDistance, as vtkLabelOctreeMesher and vtkMeshDecimator write
   * them); none are enforced when the input records none or there is no image.
   */
  vtkSetMacro(ImageToMeshDistance, double);
  vtkGetMacro(ImageToMeshDistance, double);
  vtkSetMacro(MeshToImageDistance, double);
  vtkGetMacro(MeshToImageDistance, double);
  ///@}

  ///@{
  /**
   * Order of the output cells: 3 (default), cubic Bézier triangles
   * (VTK_BEZIER_TRIANGLE, 10 points); 2, quadratic triangles
   * (VTK_QUADRATIC_TRIANGLE, 6 points: corners, then the mid-nodes of edges
   * 0-1, 1-2, 2-0, on the curves at their middle), as finite-element solvers
   * take them (Abaqus CPS6, Gmsh's 6-node triangle). Every curve is then a
   * quadratic (one control point per edge: with the image, C1, fitted to it
   * on its own; otherwise the one nearest to the smoothed cubic), shortened
   * towards its chord's midpoint, and the cells carry the same proofs: they
   * are certified in their exact cubic form (degree elevation). Field data
   * `Order`.
   */
  vtkSetClampMacro(Order, int, 2, 3);
  vtkGetMacro(Order, int);
  ///@}

  /**
   * The optional label image (port 1): the border, the fit, the bounds and accuracy.
   */
  void SetImageConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

protected:
  vtkBezierCurver();
  ~vtkBezierCurver() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Smoothness = 1;
  double Tension = 1.0 / 3.0;
  int MaximumUntanglingSteps = 64;
  int MaximumShorteningRounds = 8;
  int QualityIterations = 0;
  double MinimumScaledJacobian = 0.1;
  double MinimumCornerAngle = 15.0;
  double ImageToMeshDistance = -1.0;
  double MeshToImageDistance = -1.0;
  int Order = 3;

private:
  vtkBezierCurver(const vtkBezierCurver&) = delete;
  void operator=(const vtkBezierCurver&) = delete;
};

#endif
