// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QuadraticFidelity_h
#define labelmesher_QuadraticFidelity_h

/**
 * @file QuadraticFidelity.h
 * The two distance bounds of section 3.1.1 on curved interfaces, certified
 * (the 3D form of Curving/CurveFidelity.h). A quadratic face is replaced by
 * its 4^L sub-triangles through its points at the lattice of step 2^-L; the
 * face and that flattening are within
 *   (2/3) max_e |a + b − 2 m_e| / 4^L
 * of each other both ways (the map minus its interpolant on a sub-triangle is
 * −½ Σ l_i l_j D²x(v_i − v_j), Σ l_i l_j ≤ 1/3, and along a sub-edge D²x is
 * 4 (a + b − 2 m) / 4^L for the parallel edge of the face), and L is the
 * smallest giving at most `Tolerance`. Then, with the mesher's exact test
 * (Criteria/DistanceBound.h):
 *   - mesh to image: every sub-triangle of a face within h(M, I) − Tolerance
 *     of the image boundary of each non-zero material on its sides;
 *   - image to mesh: every voxel face of material m near a curved face of m
 *     within h(I, M) of m's straight faces, or within h(I, M) − Tolerance of
 *     them and the curved faces' sub-triangles. Voxel faces with no curved
 *     face in reach are the linear mesh's, which the decimator certified.
 * Everything is in index space: voxels.
 */

#include "Quadratic/InterfaceFaces.h"
#include "Support/LabelImage.h"
#include "Support/ProgressObserver.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace labelmesher
{

struct QuadraticBounds
{
  double ImageToMesh = 0.0; ///< h(I, M), voxels
  double MeshToImage = 0.0; ///< h(M, I), voxels
  double Tolerance = 1.0 / 64.0; ///< flattening tolerance, voxels
};

/// The faces whose curves break a bound (or cannot be flattened to the
/// tolerance within 4^5 sub-triangles): indices into `faces`. Precondition:
/// the straight faces keep the same bounds (the linear mesh was certified for
/// them: the decimator's h(I, M) and h(M, I), at most these). With `changed`
/// (per face), only what changed faces can affect is tested again: the
/// changed faces themselves and the voxel faces within reach of them; the
/// rest passed an earlier call on the same curves. Curves may only have been
/// pulled back (Scales lowered) since: the voxel faces near any shape a face
/// has had are those near its full-scale hull. `keepGoing`, if given, is asked now and then from
/// the calling thread; when it says no, AbortRequested is thrown.
std::vector<std::size_t> FacesBreakingDistances(const QuadraticMesh& mesh, const std::vector<MaterialFace>& faces,
  const LabelImage& image, const QuadraticBounds& bounds, const std::vector<char>* changed = nullptr,
  const std::function<bool()>& keepGoing = {});

/// The face's six nodes: corners a, b, c, then the mid-nodes of the edges
/// opposite a, b and c.
std::array<Point3, 6> FaceNodes(const QuadraticMesh& mesh, const MaterialFace& face);

/// Its flattening into 4^level triangles (three points each).
std::vector<std::array<Point3, 3>> FlattenFace(const std::array<Point3, 6>& nodes, int level);

/// The smallest level whose flattening is within `tolerance` of the face, or
/// -1 if more than 5 would be needed.
int FlatteningLevel(const std::array<Point3, 6>& nodes, double tolerance);

} // namespace labelmesher

#endif
