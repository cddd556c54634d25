// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_InteriorRelocation_h
#define labelmesher_InteriorRelocation_h

/**
 * @file InteriorRelocation.h
 * Moves a vertex inside one material to a better place, so that merges the
 * angle bound refused become possible. An addition to section 3.1.3, whose
 * merges only ever move a vertex onto a neighbour: the vertices they leave
 * are mostly where the angle bound stopped them (Cassini 100 at 15 degrees:
 * 6,126 foreground tetrahedra without relocation, 1,796 with it).
 *
 * Only interior vertices move (every cell around them has one label and they
 * are off the box), and only to points of the doubled lattice, so that
 * orientation stays exact. Why each guarantee survives a move:
 *  - distances and topology: no cell changes its vertices or its label and
 *    no interface face contains the vertex, so no interface face moves;
 *  - embedding: every cell around the vertex stays positively oriented
 *    (exact test), so the vertex stays inside the polyhedron its link bounds
 *    and the cells around it still tile that polyhedron;
 *  - angles: the smallest angle of the cells around the vertex must grow, so
 *    it stays above the bound it was above.
 * Candidates: the lattice points nearest the centroid of the neighbours, the
 * 26 (8 in 2D) lattice points around it, and the point halfway to it; the one
 * with the largest smallest angle wins.
 */

#include "Decimation/EditableMesh.h"

#include <vector>

namespace labelmesher
{

class InteriorRelocation
{
public:
  /// Moves v if it is interior and a candidate raises the smallest angle of
  /// its cells; returns whether it moved. `checkQuality` false (tests only:
  /// the quality check switched off) takes the first candidate regardless of
  /// orientation and angles.
  bool TryMove(EditableMesh& mesh, VertexId v, bool checkQuality = true);

private:
  /// The smallest angle of v's cells with v at `at`; `positive` false (and
  /// 0 returned) when one of them would not be positively oriented.
  double SmallestAngleAround(const EditableMesh& mesh, VertexId v, const Lattice& at, bool& positive) const;
  std::vector<VertexId> Neighbours;
  std::vector<Lattice> Candidates;
};

} // namespace labelmesher

#endif
