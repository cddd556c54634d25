// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_TopologyCheck_h
#define labelmesher_TopologyCheck_h

/**
 * @file TopologyCheck.h
 * Requirement 3 of section 3.1.3: a merge keeps the topology of the labelled
 * complex. We prove it with the link condition applied to each stratum, not
 * with the dissertation's union-of-leaves single manifold condition, which
 * needs the octree's leaves per face (and whose proof, Lemma 3.2.5, argues
 * one interface at a time). The subcomplexes are:
 *
 *  - K: the whole mesh, made a sphere by a vertex w joined to the box's faces
 *    (the "boundary trick" of Dey, Edelsbrunner, Guha, Nekhayev, Topology
 *    preserving edge contraction, 1999);
 *  - M_m: the closed cells of material m (background and each label);
 *  - I_P: the closed faces between the two labels of pair P (the box's faces
 *    count as faces against its outside, one label per box plane);
 *  - F: the feature curves, edges where the interfaces are not one sheet
 *    (three or more labels meet, or one pair meets itself, or a box edge).
 *
 * A merge of a into b is accepted only if
 *  1. (strata) a moves within every subcomplex it belongs to: every label and
 *     every interface pair around a is also around the edge ab; a vertex with
 *     a number of feature edges other than 0 or 2 (a corner) never moves, and
 *     one with 2 moves only along them (in 2D every vertex where interfaces
 *     meet or branch is a corner);
 *  2. (link condition) Lk(a) & Lk(b) = Lk(ab) in K, in every M_m and I_P that
 *     contains a, and in F;
 *  3. (commutation) each subcomplex after the merge is the contraction of the
 *     one before: the interface faces (with their pairs) and feature edges
 *     around b after are the images of those around a and b before, and no
 *     cell or interface face that vanishes leaves a face of its own
 *     subcomplex uncovered.
 * By 3 the merge acts on every subcomplex L as the contraction of ab; by 2 and
 * the link condition theorem (Dey et al. 1999 for the 3-sphere K, which stays a
 * triangulated ball; Attali, Lieutier, Salinas, Efficient data structure for
 * representing and simplifying simplicial complexes in high dimensions, 2012,
 * for any complex) it preserves the homotopy type of every L: each material
 * region keeps its components and Euler characteristic, as does every
 * interface and the curve network. With every cell positively oriented and the
 * box fixed (QualityCheck, strata rule), the mesh stays embedded.
 */

#include "Decimation/EdgeCollapse.h"

#include <array>
#include <vector>

namespace labelmesher
{

class TopologyCheck
{
public:
  /// True when the planned merge (with its interfaces) satisfies 1-3 above.
  bool Accepts(const EditableMesh& mesh, const EdgeCollapse& merge);
  /// The same for a merge whose vertex From lies inside one material and off
  /// the box (IsInterior): only K's link condition can fail there. Needs only
  /// EdgeCollapse::Plan.
  bool AcceptsInteriorMove(const EditableMesh& mesh, const EdgeCollapse& merge);
  /// Every cell around v has one label, and v is not on the box.
  static bool IsInterior(const EditableMesh& mesh, VertexId v);

private:
  bool StrataAllowMove(const EditableMesh& mesh, const EdgeCollapse& merge);
  bool LinkConditions(const EditableMesh& mesh, const EdgeCollapse& merge);
  bool Commutes(const EditableMesh& mesh, const EdgeCollapse& merge);
  /// Lk(a) & Lk(b) within Lk(ab) for the complex closed over `tops`.
  bool LinkCondition(VertexId a, VertexId b);
  void FeatureNeighbours(const std::vector<InterfaceFace>& faces, VertexId v, std::vector<VertexId>& out);

  int Dimension = 3;
  std::vector<std::array<VertexId, 4>> Tops; // top simplices of one subcomplex, sorted, -1 padded
  std::vector<int> TopSizes;
  std::vector<std::uint32_t> SA, SB, SAB;
  void Bind(const EditableMesh& mesh);
  std::vector<std::uint32_t> Seen; ///< per mesh vertex: the epoch it was numbered in
  std::vector<std::uint16_t> LocalId;
  std::uint32_t Epoch = 0;
  std::vector<std::int32_t> LabelsA, LabelsAB;
  std::vector<std::pair<std::int32_t, std::int32_t>> PairsA, PairsAB;
  std::vector<VertexId> FeatureA, FeatureB, FeatureAfter;
  std::vector<InterfaceFace> Image;
  std::vector<std::pair<VertexId, std::pair<std::int32_t, std::int32_t>>> EdgeUses;
};

} // namespace labelmesher

#endif
