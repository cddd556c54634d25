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
 *
 * Independence: the checks re-measure what the mesher decided, so on purpose
 * they share no code with its own fidelity test (Criteria/DistanceBound.h)
 * beyond the point distances of Support/Geometry.h: neither calls the other,
 * and a bug in one cannot hide in the other.
 */

#include "Support/LabelImage.h"
#include "Mesh/SimplexMesh.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace labelmesher
{

/// Angles in degrees: all six dihedral angles of every tetrahedron (3D), the three
/// planar angles of every triangle (2D). A degenerate angle (zero-length edge,
/// collinear points) counts as 0. All fields are 0 for an empty mesh.
struct QualityReport
{
  double MinimumAngle = 0.0;
  double MaximumAngle = 0.0;
  std::size_t InvertedCells = 0; ///< cells with signed volume (area) <= 0: det[b-a, c-a, d-a], z of (b-a)x(c-a)
};
QualityReport MeasureQuality(const SimplexMesh& mesh);

/// Facets and edges are identified by point ids. Geometric tests use an absolute
/// tolerance of 1e-9 (index space) and do not assume points on a lattice.
struct ConformityReport
{
  /// Faces (3D) / edges (2D) used by more than two cells.
  std::size_t OverSharedFaces = 0;
  /// Vertices (points used by at least one cell) lying strictly inside an edge or
  /// a triangle face of a cell that does not use them (counted once each).
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

/// One-sided Hausdorff distances in voxel units between the continuous boundaries
/// (voxel faces / mesh boundary triangles; pixel edges / segments in 2D),
/// computed by branch and bound (HausdorffDistance.cxx). Values are upper bounds
/// on the exact distances, tight to `tolerance` (by default 1/1024 voxel: a
/// decimated mesh reaches its bounds, and a coarser figure would read as a
/// violation of a bound that holds; a depth and work limit per
/// direction bounds the refinement; past it a value stays an upper bound but may
/// be less tight). Both values are +infinity when exactly one of the two
/// boundaries is empty; both 0 when both are.
struct DistanceReport
{
  double ImageToMesh = 0.0; ///< h(I, M): max over image boundary of distance to mesh boundary
  double MeshToImage = 0.0; ///< h(M, I): max over mesh boundary of distance to image boundary
};
struct HausdorffReport
{
  DistanceReport Overall;
  std::map<std::int32_t, DistanceReport> PerMaterial; ///< every non-zero label of image or mesh
};
HausdorffReport MeasureHausdorff(
  const LabelImage& image, const SimplexMesh& mesh, double tolerance = 1.0 / 1024.0);
/// A mesh boundary given as triangles with the materials on their two sides
/// (0: background or outside), for meshes whose boundaries are not flat: a
/// curved mesh's boundary measured on its flattening (QuadraticVolume.h). A
/// facet bounds each non-zero material on one side only.
struct BoundaryFacet
{
  Point3 Points[3];
  std::int32_t First = 0, Second = 0;
};
HausdorffReport MeasureHausdorff(
  const LabelImage& image, const std::vector<BoundaryFacet>& facets, double tolerance = 1.0 / 1024.0);
/// Rigorous yes/no: true only if h(I, M) <= imageToMesh and h(M, I) <= meshToImage
/// hold exactly (up to 1e-9 for round-off), overall and for every material.
/// Conservative: an element the branch and bound cannot decide within its depth
/// and work limits makes the answer false, so a bound equal to a distance that
/// is reached at a non-vertex point (e.g. a medial point) may not be
/// certifiable; callers testing a computed value should allow a small margin.
bool WithinHausdorff(
  const LabelImage& image, const SimplexMesh& mesh, double imageToMesh, double meshToImage);

struct RegionTopology
{
  std::size_t Components = 0;          ///< connected components of the closed set
  long long EulerCharacteristic = 0;   ///< V - E + F (- C) of its cell complex
};
struct TopologyComparison
{
  /// Union of the closed voxels of the label: 26-connected (8 in 2D) voxel
  /// components; chi of the cubical complex (streamed, O(voxels)).
  RegionTopology Image;
  /// Union of the closed cells of the material: cells joined through shared
  /// vertex ids; chi of the simplicial complex of the cells and their faces.
  RegionTopology Mesh;
  bool Matches() const
  {
    return Image.Components == Mesh.Components &&
      Image.EulerCharacteristic == Mesh.EulerCharacteristic;
  }
};
/// Per non-zero material present in the image or the mesh (zeros on the side
/// where it is absent).
std::map<std::int32_t, TopologyComparison> CompareTopology(
  const LabelImage& image, const SimplexMesh& mesh);

} // namespace labelmesher

#endif
