// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef LabelMesherArrayNames_h
#define LabelMesherArrayNames_h

/**
 * @file LabelMesherArrayNames.h
 * The names of the arrays the LabelMesher filters write (cell data and field
 * data), in one place: the filters write them and the labelmesher CLI reads
 * them through these constants, so a renamed array cannot silently drop out
 * of a report. Pipelines may use them too (GetFieldData()->GetArray(...)).
 *
 * Field data holds one-tuple arrays for parameters and totals, and
 * equal-length arrays for per-material tables (TopologyMaterial with the
 * Image/Mesh columns; AccuracyMaterial with the pixel columns).
 */

namespace labelmesher
{
namespace arrays
{
// ---- cell data ----
inline constexpr char Material[] = "Material";   ///< int, the image label of a cell
inline constexpr char Materials[] = "Materials"; ///< int x 2, labels on either side of an interface face
inline constexpr char MinimumJacobian[] = "MinimumJacobian";
inline constexpr char ScaledJacobian[] = "ScaledJacobian";
inline constexpr char Valid[] = "Valid";
/// int, on a run shared out over several processes (vtkLabelMesher under mpirun): the rank
/// that meshed the part the cell's centroid lies in; a .pvtu has one piece per rank by it
inline constexpr char Process[] = "Process";
inline constexpr char CornerAngle[] = "CornerAngle"; ///< double, a curved cell's smallest corner angle (tangents), degrees

// ---- field data: the materials' names and colours, one tuple per material ----
// (vtkLabelImageReader fills them from a 3D Slicer segmentation or a colour table; every filter
// passes them from its input to its outputs; vtkLabelMeshWriter names the materials with them)
inline constexpr char MaterialLabel[] = "MaterialLabel"; ///< int, the image label
inline constexpr char MaterialName[] = "MaterialName";   ///< string (UTF-8), may be empty
inline constexpr char MaterialColor[] = "MaterialColor"; ///< double x 3, RGB in [0, 1]; -1: none given

// ---- field data: parameters and run ----
inline constexpr char ImageToMeshDistance[] = "ImageToMeshDistance";
inline constexpr char MeshToImageDistance[] = "MeshToImageDistance";
inline constexpr char IncludeBackground[] = "IncludeBackground";
inline constexpr char VoxelSize[] = "VoxelSize";
inline constexpr char NumberOfLeaves[] = "NumberOfLeaves";
inline constexpr char StageName[] = "StageName";
inline constexpr char StageSeconds[] = "StageSeconds";
/// MiB the run was estimated to need beyond what the process held when it
/// started (Support/MemoryEstimate.h), and the voxel faces the estimate priced.
inline constexpr char EstimatedMemory[] = "EstimatedMemory";
inline constexpr char InterfaceFaces[] = "InterfaceFaces";

// ---- field data: measured output (Filters/Core/Checks) ----
inline constexpr char MinimumAngle[] = "MinimumAngle";
inline constexpr char MaximumAngle[] = "MaximumAngle";
inline constexpr char InvertedCells[] = "InvertedCells";
inline constexpr char OverSharedFaces[] = "OverSharedFaces";
inline constexpr char HangingVertices[] = "HangingVertices";
inline constexpr char NonManifoldBoundaryEdges[] = "NonManifoldBoundaryEdges";
inline constexpr char MeasuredImageToMeshDistance[] = "MeasuredImageToMeshDistance";
inline constexpr char MeasuredMeshToImageDistance[] = "MeasuredMeshToImageDistance";
/// 1 when the checks' exact test certifies both distance bounds, 0 when it does not.
inline constexpr char HausdorffBoundsCertified[] = "HausdorffBoundsCertified";
inline constexpr char TopologyMaterial[] = "TopologyMaterial";
inline constexpr char ImageComponents[] = "ImageComponents";
inline constexpr char ImageEulerCharacteristic[] = "ImageEulerCharacteristic";
inline constexpr char MeshComponents[] = "MeshComponents";
inline constexpr char MeshEulerCharacteristic[] = "MeshEulerCharacteristic";
inline constexpr char TopologyMatches[] = "TopologyMatches";

// ---- field data: vtkMeshDecimator ----
inline constexpr char AngleBound[] = "AngleBound"; ///< the MinimumAngle asked for, degrees
inline constexpr char CellsBefore[] = "CellsBefore"; ///< kept cells of the input (foreground unless IncludeBackground)
inline constexpr char CellsAfter[] = "CellsAfter";
inline constexpr char Merges[] = "Merges";
inline constexpr char MergeOffers[] = "MergeOffers";
inline constexpr char MergesRejectedByQuality[] = "MergesRejectedByQuality";
inline constexpr char MergesRejectedByTopology[] = "MergesRejectedByTopology";
inline constexpr char MergesRejectedByFidelity[] = "MergesRejectedByFidelity";
inline constexpr char VerticesRelocated[] = "VerticesRelocated";
inline constexpr char FrozenVertices[] = "FrozenVertices";
// vtkLabelMesher (block-streamed)
inline constexpr char Blocks[] = "Blocks";                       ///< blocks the run was cut into
inline constexpr char LargestBlockCells[] = "LargestBlockCells"; ///< initial cells of the largest block
inline constexpr char Parts[] = "Parts";                         ///< parts the blocks were grouped into
inline constexpr char Processes[] = "Processes";                 ///< processes the parts were shared out over
inline constexpr char AssembledCells[] = "AssembledCells";       ///< cells entering the last pass (0: one block)
inline constexpr char BorderPasses[] = "BorderPasses";           ///< border passes between blocks
inline constexpr char LargestAssembledCells[] = "LargestAssembledCells"; ///< most cells of the assembled blocks

// ---- field data: vtkBezierCurver ----
inline constexpr char Smoothness[] = "Smoothness";
inline constexpr char Tension[] = "Tension";
inline constexpr char MaximumUntanglingSteps[] = "MaximumUntanglingSteps";
inline constexpr char MaximumShorteningRounds[] = "MaximumShorteningRounds";
inline constexpr char QualityIterations[] = "QualityIterations";
/// The certified scaled Jacobian every curved cell was asked to keep (0: validity alone).
inline constexpr char MinimumScaledJacobianBound[] = "MinimumScaledJacobianBound";
inline constexpr char CellsBelowScaledJacobian[] = "CellsBelowScaledJacobian"; ///< after the rounds, before straightening
inline constexpr char StraightenedForScaledJacobian[] = "StraightenedForScaledJacobian"; ///< 1: every curve made straight
/// The corner angle every curved cell keeps, degrees: the one asked, or the linear mesh's smallest
/// angle when that is smaller (0: measured only).
inline constexpr char CornerAngleBound[] = "CornerAngleBound";
inline constexpr char CellsBelowCornerAngle[] = "CellsBelowCornerAngle"; ///< after the rounds, before straightening
inline constexpr char StraightenedForCornerAngle[] = "StraightenedForCornerAngle"; ///< 1: every curve made straight
inline constexpr char StraightenedForValidity[] = "StraightenedForValidity"; ///< 1: every curve made straight, cells left invalid
inline constexpr char InvalidBeforeUntangling[] = "InvalidBeforeUntangling";
inline constexpr char InvalidCells[] = "InvalidCells";
inline constexpr char UntanglingSteps[] = "UntanglingSteps";
inline constexpr char InterfaceChains[] = "InterfaceChains";
inline constexpr char ClosedInterfaceChains[] = "ClosedInterfaceChains";
inline constexpr char CurvedEdges[] = "CurvedEdges";
inline constexpr char SplitEars[] = "SplitEars";
inline constexpr char EarCorners[] = "EarCorners"; ///< vertices where a chain turns at an ear instead (corner bound on)
inline constexpr char ShortenedPieces[] = "ShortenedPieces";       ///< interface pieces left below scale 1
inline constexpr char StraightenedPieces[] = "StraightenedPieces"; ///< of those, the straight ones
inline constexpr char PiecesShortenedForBounds[] = "PiecesShortenedForBounds";
inline constexpr char PiecesShortenedForValidity[] = "PiecesShortenedForValidity";
inline constexpr char UncertifiedPieces[] = "UncertifiedPieces";
inline constexpr char UntanglingRounds[] = "UntanglingRounds";
inline constexpr char CurvedMeasureResolution[] = "CurvedMeasureResolution"; ///< how far the curves' measured distances may exceed the true ones, voxels
inline constexpr char InterfaceCrossings[] = "InterfaceCrossings";
inline constexpr char Pixels[] = "Pixels";
inline constexpr char MisclassifiedPixelsLinear[] = "MisclassifiedPixelsLinear";
inline constexpr char MisclassifiedPixelsCurved[] = "MisclassifiedPixelsCurved";
inline constexpr char AccuracyMaterial[] = "AccuracyMaterial";
inline constexpr char MissedPixelsLinear[] = "MissedPixelsLinear";
inline constexpr char MissedPixelsCurved[] = "MissedPixelsCurved";
inline constexpr char ClaimedPixelsLinear[] = "ClaimedPixelsLinear";
inline constexpr char ClaimedPixelsCurved[] = "ClaimedPixelsCurved";

// ---- field data of the quadratic 3D mesh (vtkLabelMesher with Order 2) ----
inline constexpr char Order[] = "Order"; ///< 2: quadratic tetrahedra (triangles: vtkBezierCurver's, 2 or 3)
inline constexpr char FittedEdges[] = "FittedEdges";           ///< interface edges given a fitted mid-node
inline constexpr char PulledBackEdges[] = "PulledBackEdges";   ///< of those, pulled back at least once
inline constexpr char CellsFailedScaledJacobian[] = "CellsFailedScaledJacobian"; ///< in some round, before pulling back
inline constexpr char FacesFailedDistance[] = "FacesFailedDistance"; ///< in some round, before pulling back
inline constexpr char CertificationRounds[] = "CertificationRounds"; ///< rounds of certifying and pulling back
inline constexpr char UntangledEdges[] = "UntangledEdges"; ///< interior edges moved by elasticity
inline constexpr char PinnedEdges[] = "PinnedEdges";       ///< interior edges pinned straight
inline constexpr char CertifiedMinimumScaledJacobian[] = "CertifiedMinimumScaledJacobian"; ///< over the cells
inline constexpr char SampledMinimumScaledJacobian[] = "SampledMinimumScaledJacobian"; ///< measured, lattice of step 1/4
inline constexpr char CellsFailedCornerAngle[] = "CellsFailedCornerAngle"; ///< in some round, before pulling back
/// Degrees, over every cell of the box (cell data CornerAngle: each cell's, the curver's exact
/// tangents); the bound is CornerAngleBound.
inline constexpr char CertifiedMinimumCornerAngle[] = "CertifiedMinimumCornerAngle";
inline constexpr char MeasuredMinimumCornerAngle[] = "MeasuredMinimumCornerAngle"; ///< tangents from points of the map
inline constexpr char Voxels[] = "Voxels";
inline constexpr char MisclassifiedVoxelsLinear[] = "MisclassifiedVoxelsLinear";
inline constexpr char MisclassifiedVoxelsQuadratic[] = "MisclassifiedVoxelsQuadratic"; ///< on the cells refined at step 1/4
} // namespace arrays
} // namespace labelmesher

#endif
