// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_QualityCheck_h
#define labelmesher_QualityCheck_h

/**
 * @file QualityCheck.h
 * Requirement 1 of section 3.1.3: a merge may not invert a cell nor create an
 * angle (dihedral in 3D, planar in 2D) below the user's bound. Orientation is
 * decided exactly on the integer lattice (EditableMesh::Orientation), never
 * with a tolerance: a flat cell is refused like an inverted one. Angles are
 * compared through their cosines (no acos per angle), in double precision.
 */

#include "Decimation/EdgeCollapse.h"

#include <array>
#include <vector>

namespace labelmesher
{

class QualityCheck
{
public:
  /// `minimumAngle` in degrees.
  QualityCheck(int dimension, double minimumAngle);

  /// Prepares the orientation test of merges of `from`: the plane of each
  /// cell's face opposite `from` (a vertex is offered once and tried against
  /// each neighbour, so this is done once per offer).
  void Prepare(const EditableMesh& mesh, VertexId from);
  /// Every cell around `from` that does not hold `to` stays positively
  /// oriented when `from` moves to `to`: `to` lies strictly on `from`'s side of
  /// the opposite face. Exact (integers). Cheap: most refused merges stop here.
  bool OrientationsHold(const EditableMesh& mesh, VertexId to) const;
  /// Every moved cell of the planned merge has no angle below the bound (the
  /// cells that stay are unchanged); call after OrientationsHold.
  bool AnglesHold(const EditableMesh& mesh, const EdgeCollapse& merge) const;

  /// The smallest angle (degrees) of the cell with these lattice points.
  static double SmallestAngle(int dimension, const Lattice* points);
  /// The largest cosine of the cell's angles (dihedral in 3D, planar in 2D):
  /// the cosine of its smallest angle, without trigonometry.
  static double LargestCosine(int dimension, const Lattice* points);
  /// The angle (degrees) of a cosine, clamped to [-1, 1].
  static double AngleOfCosine(double cosine);

private:
  struct OppositeFace
  {
    CellId Cell;
    Lattice Point;               ///< a vertex of the face
    std::array<long long, 3> Normal; ///< towards `from`'s side
  };
  std::vector<OppositeFace> Faces;
  int Dimension;
  double CosineBound; ///< cos(minimumAngle): an angle is too small when its cosine is larger
};

} // namespace labelmesher

#endif
