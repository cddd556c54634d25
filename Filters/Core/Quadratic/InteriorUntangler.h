// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_InteriorUntangler_h
#define labelmesher_InteriorUntangler_h

/**
 * @file InteriorUntangler.h
 * Untangling by linear elasticity on the control nets (section 4.3 in 3D; the
 * 2D form is Curving/ElasticUntangler.h). The control net of every cell (its
 * ten Bézier control points: four corner tetrahedra and the inner octahedron
 * split in four) is the undeformed elastic body, taken straight (the linear
 * mesh's net); the control points of interface edges are moved to where their
 * curves put them, corners and the points of box edges stay, and the control
 * points of the free edges (`free`) move to the equilibrium (P1 elements,
 * stiffened by 1 / volume so that small elements resist distortion; Eigen's
 * conjugate gradient). A curved interface bulging into a cell so drags the
 * cell's interior mid-nodes along instead of folding it.
 *
 * Only free edges near a fitted interface edge (sharing a cell with one)
 * move: the displacement decays away from the curves, and the system stays
 * small. It is assembled once and solved again for each new set of curves,
 * starting from the last solution; it changes only when edges are pinned.
 */

#include "Quadratic/QuadraticMesh.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace labelmesher
{

class InteriorUntangler
{
public:
  /// `free[e]`: edge e is on no interface and not on the box. The moving
  /// edges are the free ones sharing a cell with a curved edge of `mesh` now.
  InteriorUntangler(const QuadraticMesh& mesh, const std::vector<char>& free, double poissonRatio = 0.3);
  ~InteriorUntangler();
  InteriorUntangler(const InteriorUntangler&) = delete;
  InteriorUntangler& operator=(const InteriorUntangler&) = delete;

  /// Sets Offset and Scales of the moving edges from the interface curves'
  /// current mid-nodes (the other free edges straight). Returns the edges
  /// moved.
  std::size_t Solve(QuadraticMesh& mesh);
  /// Holds edge e straight from now on (the system is assembled again at the next Solve).
  void Pin(std::size_t e);

private:
  struct System;
  const QuadraticMesh& Mesh;
  std::vector<char> Free;
  double PoissonRatio;
  std::vector<char> Moving;
  std::vector<Point3> Displacement; ///< per edge: its control point's displacement last solved (the next guess)
  std::unique_ptr<System> Factored;
};

} // namespace labelmesher

#endif
