// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MeshChecks_h
#define labelmesher_MeshChecks_h

/**
 * @file MeshChecks.h
 * The measuring component: what the guarantees of the ORD mesh (dissertation
 * section 3.2) mean, computed for a mesh against its label image. Shared by the
 * mesher's own acceptance tests, the CLI report and the test suite.
 *
 * Conventions: both inputs are in the image's index space (LabelImage.h). The
 * *image boundary* of material m is the set of voxel faces (pixel edges in 2D)
 * between a voxel of label m and one of another label (outside the image counts
 * as label 0). The *mesh boundary* of material m is the set of cell faces (edges
 * in 2D) between a cell of material m and a cell of another material or no cell.
 * Overall boundaries are the unions over all non-zero materials.
 */

#include "LabelImage.h"
#include "SimplexMesh.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace labelmesher
{

/// Angles in degrees: dihedral angles of tetrahedra (3D), planar angles of triangles (2D).
struct QualityReport
{
  double MinimumAngle = 0.0;
  double MaximumAngle = 0.0;
  std::size_t InvertedCells = 0; ///< cells with signed volume (area) <= 0
};
QualityReport MeasureQuality(const SimplexMesh& mesh);

struct ConformityReport
{
  /// Faces (3D) / edges (2D) used by more than two cells.
  std::size_t OverSharedFaces = 0;
  /// Vertices lying strictly inside an edge or face of a cell that does not use them.
  std::size_t HangingVertices = 0;
  /// Edges (3D) / vertices (2D) of the mesh boundary (faces used by one cell) not
  /// used by exactly two boundary faces: zero means the boundary is watertight.
  std::size_t NonManifoldBoundaryEdges = 0;
  bool Conforming() const
  {
    return OverSharedFaces == 0 && HangingVertices == 0 && NonManifoldBoundaryEdges == 0;
  }
};
ConformityReport MeasureConformity(const SimplexMesh& mesh);

/// One-sided Hausdorff distances in voxel units. Values are upper bounds on the
/// exact distances, tight to `tolerance`.
struct DistanceReport
{
  double ImageToMesh = 0.0; ///< h(I, M): max over image boundary of distance to mesh boundary
  double MeshToImage = 0.0; ///< h(M, I): max over mesh boundary of distance to image boundary
};
struct HausdorffReport
{
  DistanceReport Overall;
  std::map<std::int32_t, DistanceReport> PerMaterial;
};
HausdorffReport MeasureHausdorff(
  const LabelImage& image, const SimplexMesh& mesh, double tolerance = 1.0 / 64.0);
/// Rigorous yes/no: true only if h(I, M) <= imageToMesh and h(M, I) <= meshToImage
/// hold exactly (up to 1e-9 for round-off), overall and for every material.
bool WithinHausdorff(
  const LabelImage& image, const SimplexMesh& mesh, double imageToMesh, double meshToImage);

struct RegionTopology
{
  std::size_t Components = 0;
  long long EulerCharacteristic = 0;
};
struct TopologyComparison
{
  RegionTopology Image; ///< union of the closed voxels of the material
  RegionTopology Mesh;  ///< union of the closed cells of the material
  bool Matches() const
  {
    return Image.Components == Mesh.Components &&
      Image.EulerCharacteristic == Mesh.EulerCharacteristic;
  }
};
/// Per non-zero material present in the image or the mesh.
std::map<std::int32_t, TopologyComparison> CompareTopology(
  const LabelImage& image, const SimplexMesh& mesh);

} // namespace labelmesher

#endif
