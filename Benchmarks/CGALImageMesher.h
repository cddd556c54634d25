// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_benchmarks_CGALImageMesher_h
#define labelmesher_benchmarks_CGALImageMesher_h

/**
 * @file CGALImageMesher.h
 * The baseline of labelmesher_compare_cgal: CGAL 5.5 Mesh_3 on a labelled image
 * (CGAL::Labeled_mesh_domain_3::create_labeled_image_mesh_domain), returned as
 * a SimplexMesh in *our* index space so the same checks measure both meshes.
 * All CGAL code is in CGALImageMesher.cxx (one heavy translation unit).
 *
 * Coordinates. CGAL's image domain samples voxel (i, j, k) at
 * (i*vx + tx, j*vy + ty, k*vz + tz) and interpolates labels between those
 * points ("labellized trilinear" interpolation), so with vx = 1, tx = 0 voxel
 * centres sit at integer positions, as in LabelImage.h; an interface between
 * two voxels lands half-way, i.e. on our voxel face. But CGAL returns the
 * outside value (0) for any point beyond the outermost voxel *centres*, which
 * would pull a label touching the border in by half a voxel. We therefore hand
 * CGAL the image padded by one background voxel on every side and shift its
 * output by -1: then the border surface lies near the voxel faces at -0.5 and
 * n - 0.5, like ours.
 */

#include "Support/LabelImage.h"
#include "Mesh/SimplexMesh.h"

#include <string>
#include <utility>
#include <vector>

namespace labelmesher
{
namespace benchmarks
{

struct CGALMeshOptions
{
  // Mesh_criteria_3, in voxels / degrees.
  double FacetAngle = 30.0;
  double FacetSize = 4.0;
  double FacetDistance = 1.0;
  double CellRadiusEdgeRatio = 3.0;
  double CellSize = 8.0;
  /// Run the sliver perturber and exuder after refinement (make_mesh_3's
  /// defaults: no Lloyd, no ODT, perturb, exude). false: no_perturb, no_exude.
  bool Optimise = true;
  /// Seed every 6-connected component of every label with points on its
  /// surface (CGAL's initialize_triangulation_from_labeled_image, as in its
  /// example mesh_3D_image_with_custom_initialization.cpp). false: CGAL's
  /// default random initial points, which can miss whole components.
  bool SeedComponents = true;
  /// Bisection precision of surface intersections, relative to the bounding box diagonal.
  double RelativeErrorBound = 1e-5;
  /// CGAL::get_default_random() is reset to CGAL::Random(Seed) before meshing.
  unsigned int Seed = 0;
};

struct CGALMeshResult
{
  SimplexMesh Mesh; ///< tetrahedra of the complex only (label != 0), our index space
  std::vector<std::pair<std::string, double>> Timings; ///< seconds per stage
  double Seconds = 0.0;                                ///< total (padding/conversion excluded)
  std::size_t InitialPoints = 0;
};

/// Throws std::invalid_argument for labels above 65535 (CGAL's word types used here).
CGALMeshResult MeshWithCGAL(const LabelImage& image, const CGALMeshOptions& options);

} // namespace benchmarks
} // namespace labelmesher

#endif
