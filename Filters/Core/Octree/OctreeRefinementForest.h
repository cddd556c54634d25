// SPDX-License-Identifier: GPL-2.0-or-later
// The body of BuildForest2 / BuildForest3, written once against p4est's 2D
// names; OctreeRefinement3D.cxx includes <p4est_to_p8est.h> first, which maps
// every p4est_ name to its p8est_ twin (p4est's own idiom for sharing code).
// Not a public header: included by exactly those two files.

#include "Criteria/RefinementCriteria.h"
#include "Octree/OctreeRefinement.h"
#include "Support/ParallelChunks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace labelmesher
{
namespace
{

enum class LeafState : std::uint8_t
{
  Unevaluated,
  Accepted,
  MarkedForRefinement
};

struct QuadrantData
{
  std::int32_t First;
  std::int32_t Second;
  std::uint16_t EdgeMidpoints;
  std::uint8_t SplitFaces;
  std::uint8_t RigidFaces;
  LeafState State;
};

struct ForestContext
{
  const LeafEvaluator* Evaluate;
  int Depth;
  const ProgressObserver* Observer;
  double ProgressAt;
  std::size_t Marked = 0;
  /// Leaves accepted since the neighbour rule last ran (copies: p4est moves
  /// quadrants when it refines). Only they can be in a new size relation.
  std::vector<p4est_quadrant_t> Fresh;
};
// p4est is C: nothing may unwind through its callbacks, so none of them calls
// the evaluator or the observer; leaves are judged between p4est calls.

QuadrantData& Data(p4est_quadrant_t* q) { return *static_cast<QuadrantData*>(q->p.user_data); }
const QuadrantData& Data(const p4est_quadrant_t* q) { return *static_cast<const QuadrantData*>(q->p.user_data); }
ForestContext& Context(p4est_t* p4est) { return *static_cast<ForestContext*>(p4est->user_pointer); }

LeafBox BoxOf(const p4est_quadrant_t* q, int depth)
{
  const p4est_qcoord_t voxel = P4EST_ROOT_LEN >> depth;
  LeafBox box;
  box.Dimension = P4EST_DIM;
  box.Origin = { static_cast<int>(q->x / voxel), static_cast<int>(q->y / voxel),
#ifdef P4_TO_P8
    static_cast<int>(q->z / voxel)
#else
    0
#endif
  };
  box.Size = 1 << (depth - q->level);
  return box;
}

void InitializeQuadrant(p4est_t*, p4est_topidx_t, p4est_quadrant_t* q)
{
  Data(q) = QuadrantData{ 0, 0, 0, 0, 0, LeafState::Unevaluated };
}

/// Judges every leaf not judged yet and marks those that must be split. The
/// verdicts are independent of each other, so they are computed on all cores
/// (each into its own slot) and applied in leaf order: the forest does not
/// depend on the number of threads. Returns the number of leaves marked.
std::size_t JudgePendingLeaves(p4est_t* forest, ForestContext& context)
{
  std::vector<p4est_quadrant_t*> pending;
  double pendingVoxels = 0.0; // what judging costs, roughly
  for (p4est_topidx_t t = forest->first_local_tree; t <= forest->last_local_tree; ++t)
  {
    p4est_tree_t* tree = p4est_tree_array_index(forest->trees, t);
    for (std::size_t i = 0; i < tree->quadrants.elem_count; ++i)
    {
      p4est_quadrant_t* q = p4est_quadrant_array_index(&tree->quadrants, i);
      if (Data(q).State == LeafState::Unevaluated)
      {
        pending.push_back(q);
        pendingVoxels += std::pow(2.0, P4EST_DIM * (context.Depth - q->level));
      }
    }
  }
  // Starting threads costs tens of microseconds: not worth it for a few small leaves.
  const unsigned threads = pendingVoxels < 65536 ? 1u : MaxThreads();
  // Blocks between progress reports; the observer is called on this thread only.
  const std::size_t block = 65536;
  std::vector<LeafVerdict> verdicts(std::min(block, pending.size()));
  std::size_t marked = 0;
  for (std::size_t begin = 0; begin < pending.size(); begin += block)
  {
    const std::size_t end = std::min(pending.size(), begin + block);
    // Small chunks when leaves are few: near the root a leaf is costly.
    const std::size_t chunk = std::clamp<std::size_t>((end - begin) / 64, 1, 256);
    ParallelChunks(
      end - begin, chunk,
      [&](unsigned, std::size_t b, std::size_t e) {
        for (std::size_t i = b; i < e; ++i)
          verdicts[i] = (*context.Evaluate)(BoxOf(pending[begin + i], context.Depth));
      },
      threads);
    for (std::size_t i = begin; i < end; ++i)
    {
      p4est_quadrant_t* q = pending[i];
      const LeafVerdict& verdict = verdicts[i - begin];
      QuadrantData& data = Data(q);
      if (verdict.Refine)
      {
        if (q->level >= context.Depth)
          throw std::logic_error("the leaf evaluator asked to split a single voxel");
        data.State = LeafState::MarkedForRefinement;
        ++marked;
        continue;
      }
      data.First = verdict.First;
      data.Second = verdict.Second;
      data.RigidFaces = verdict.RigidFaces;
      data.State = LeafState::Accepted;
      context.Fresh.push_back(*q);
    }
    if (!context.Observer->Report("octree", context.ProgressAt))
      throw AbortRequested{};
  }
  return marked;
}

int RefineMarked(p4est_t*, p4est_topidx_t, p4est_quadrant_t* q)
{
  return Data(q).State == LeafState::MarkedForRefinement ? 1 : 0;
}

/// Splits the marked leaves, then judges their children and splits again,
/// level by level, until every leaf is judged and none is marked. `onLevel`
/// hears the number of levels done (for progress).
template <typename OnLevel>
void RefineMarkedLeaves(p4est_t* forest, ForestContext& context, OnLevel&& onLevel)
{
  for (int level = 1;; ++level)
  {
    p4est_refine(forest, 0, RefineMarked, InitializeQuadrant);
    if (JudgePendingLeaves(forest, context) == 0)
      return;
    onLevel(level);
  }
}

void Mark(ForestContext& context, p4est_quadrant_t* q)
{
  QuadrantData& data = Data(q);
  if (data.State != LeafState::MarkedForRefinement)
  {
    data.State = LeafState::MarkedForRefinement;
    ++context.Marked;
  }
}

bool IsProper(const p4est_quadrant_t* q) { return Data(q).First != Data(q).Second; }

/// The neighbour rule (RefinementCriteria::LargerNeighbourMustSplit) for a
/// leaf `larger` than its face or edge neighbour `finer`; `touched` holds the
/// faces of `larger` that receive the points of `finer`.
void ApplyNeighbourRule(ForestContext& context, const p4est_quadrant_t& finer, p4est_quadrant_t* larger, unsigned touched)
{
  if (RefinementCriteria::LargerNeighbourMustSplit(IsProper(&finer), IsProper(larger), Data(larger).RigidFaces, touched))
    Mark(context, larger);
}

/// The leaves of the (single) tree by the Morton key of their first voxel:
/// leaves tile the root, so the leaf holding a voxel is the last one whose key
/// is not larger, found by one inlined binary search.
class LeafIndex
{
public:
  LeafIndex(p4est_t* forest, int depth)
    : Leaves(&p4est_tree_array_index(forest->trees, 0)->quadrants)
    , Depth(depth)
    , Keys(Leaves->elem_count)
  {
    for (std::size_t i = 0; i < Keys.size(); ++i)
      Keys[i] = p4est_quadrant_linear_id(p4est_quadrant_array_index(Leaves, i), Depth);
  }

  /// The leaf that contains quadrant `r` (r itself or an ancestor), or null
  /// when the region of r is divided into finer leaves.
  p4est_quadrant_t* Containing(const p4est_quadrant_t& r) const
  {
    const auto after = std::upper_bound(Keys.begin(), Keys.end(), p4est_quadrant_linear_id(&r, Depth));
    if (after == Keys.begin())
      return nullptr;
    p4est_quadrant_t* q = p4est_quadrant_array_index(Leaves, static_cast<std::size_t>(after - Keys.begin() - 1));
    return q->level <= r.level ? q : nullptr;
  }

  /// The leaf containing the neighbour position `r` of a leaf at `level`
  /// when that leaf is larger; null when it is not, or r lies outside the root.
  p4est_quadrant_t* LargerAt(const p4est_quadrant_t& r, int level) const
  {
    if (!p4est_quadrant_is_inside_root(&r))
      return nullptr;
    p4est_quadrant_t* q = Containing(r);
    return q && q->level < level ? q : nullptr;
  }

private:
  sc_array_t* Leaves;
  int Depth;
  std::vector<std::uint64_t> Keys;
};

/// The neighbour rule on a balanced forest, for the pairs that involve a fresh
/// leaf. A pair is always looked at from its finer leaf: a fresh leaf is never
/// larger than an older neighbour (it is a child of a leaf that was balanced
/// against it), and a larger neighbour can only lie across the faces and
/// edges a fresh leaf shares with its parent's boundary.
void ApplyNeighbourRuleToFresh(p4est_t* forest, ForestContext& context)
{
  const LeafIndex leaves(forest, context.Depth);
  for (const p4est_quadrant_t& fresh : context.Fresh)
  {
    p4est_quadrant_t* leaf = leaves.Containing(fresh);
    if (!leaf || leaf->level != fresh.level || fresh.level == 0)
      continue; // split again since it was accepted: its children are fresh too
    const int child = p4est_quadrant_child_id(&fresh);
    for (int axis = 0; axis < P4EST_DIM; ++axis)
    {
      const int face = 2 * axis + ((child >> axis) & 1);
      p4est_quadrant_t r;
      p4est_quadrant_face_neighbor(&fresh, face, &r);
      p4est_quadrant_t* larger = leaves.LargerAt(r, fresh.level);
      if (!larger)
        continue;
#ifdef P4_TO_P8
      // A split face puts points on the face and on its edges: every face of
      // the larger leaf but the opposite one, which is the fresh leaf's `face`.
      ApplyNeighbourRule(context, *leaf, larger, 0x3fu & ~(1u << face));
#else
      ApplyNeighbourRule(context, *leaf, larger, 1u << (face ^ 1));
#endif
    }
#ifdef P4_TO_P8
    // Edges on the parent's edges: the axis of the edge, and the child's side
    // in the two other axes.
    for (int axis = 0; axis < 3; ++axis)
    {
      const auto others = OtherAxes(axis);
      const int bits = ((child >> others[0]) & 1) | (((child >> others[1]) & 1) << 1);
      const int edge = 4 * axis + bits;
      p4est_quadrant_t r;
      p8est_quadrant_edge_neighbor(&fresh, edge, &r);
      p4est_quadrant_t* larger = leaves.LargerAt(r, fresh.level);
      if (!larger)
        continue;
      // The edge of r that touches the fresh leaf is edge ^ 3; it is an edge
      // of the larger leaf only if r sits on that side of it in both other
      // axes. Otherwise the larger leaf also covers a face neighbour of the
      // fresh leaf, and the face case above has dealt with it.
      const int neighbourEdge = edge ^ 3;
      const int rChild = p4est_quadrant_child_id(&r);
      const int rBits = ((rChild >> others[0]) & 1) | (((rChild >> others[1]) & 1) << 1);
      if (larger->level + 1 != fresh.level || rBits != (neighbourEdge & 3))
        continue;
      ApplyNeighbourRule(context, *leaf, larger,
        (1u << p8est_edge_faces[neighbourEdge][0]) | (1u << p8est_edge_faces[neighbourEdge][1]));
    }
#endif
  }
  context.Fresh.clear();
}

void RecordFace(p4est_iter_face_info_t* info, void*)
{
  if (info->sides.elem_count != 2)
    return;
  for (int s = 0; s < 2; ++s)
  {
    auto* side = static_cast<p4est_iter_face_side_t*>(sc_array_index(&info->sides, s));
    auto* other = static_cast<p4est_iter_face_side_t*>(sc_array_index(&info->sides, 1 - s));
    if (side->is_hanging || !other->is_hanging || !side->is.full.quad)
      continue;
    QuadrantData& data = Data(side->is.full.quad);
    const int face = side->face;
#ifdef P4_TO_P8
    data.SplitFaces |= static_cast<std::uint8_t>(1u << face);
    // The finer leaves' corners sit at the midpoints of this face's four edges.
    const int axis = face / 2;
    const auto others = OtherAxes(axis);
    for (int e = 0; e < 2; ++e)
      for (int bit = 0; bit < 2; ++bit)
      {
        std::array<int, 3> bits{ 0, 0, 0 };
        bits[axis] = face % 2;
        bits[others[1 - e]] = bit;
        data.EdgeMidpoints |= static_cast<std::uint16_t>(1u << CubeEdgeThrough(others[e], bits));
      }
#else
    data.EdgeMidpoints |= static_cast<std::uint16_t>(1u << face);
#endif
  }
}

#ifdef P4_TO_P8
void RecordEdge(p8est_iter_edge_info_t* info, void*)
{
  bool anyHanging = false;
  for (std::size_t s = 0; s < info->sides.elem_count; ++s)
    anyHanging = anyHanging || static_cast<p8est_iter_edge_side_t*>(sc_array_index(&info->sides, s))->is_hanging;
  if (!anyHanging)
    return;
  for (std::size_t s = 0; s < info->sides.elem_count; ++s)
  {
    auto* side = static_cast<p8est_iter_edge_side_t*>(sc_array_index(&info->sides, s));
    if (!side->is_hanging && side->is.full.quad)
      Data(side->is.full.quad).EdgeMidpoints |= static_cast<std::uint16_t>(1u << side->edge);
  }
}
#endif

void CollectLeaf(p4est_iter_volume_info_t* info, void* user)
{
  auto& leaves = *static_cast<std::vector<OctreeLeaf>*>(user);
  const QuadrantData& data = Data(info->quad);
  OctreeLeaf leaf;
  leaf.Box = BoxOf(info->quad, Context(info->p4est).Depth);
  leaf.First = data.First;
  leaf.Second = data.Second;
  leaf.EdgeMidpoints = data.EdgeMidpoints;
  leaf.SplitFaces = data.SplitFaces;
  leaves.push_back(leaf);
}

struct ForestDeleter
{
  void operator()(p4est_t* p) const { p4est_destroy(p); }
  void operator()(p4est_connectivity_t* c) const { p4est_connectivity_destroy(c); }
};

std::vector<OctreeLeaf> BuildForest(int depth, const LeafEvaluator& evaluate, const ProgressObserver& observer,
  double progressStart, double progressEnd)
{
  if (depth > P4EST_QMAXLEVEL)
    throw std::invalid_argument("image too large for the octree: more than 2^" +
      std::to_string(P4EST_QMAXLEVEL) + " voxels a side");
  detail::InitializeP4est();
  ForestContext context{ &evaluate, depth, &observer, progressStart, 0, {} };
#ifdef P4_TO_P8
  std::unique_ptr<p4est_connectivity_t, ForestDeleter> connectivity(p8est_connectivity_new_unitcube());
#else
  std::unique_ptr<p4est_connectivity_t, ForestDeleter> connectivity(p4est_connectivity_new_unitsquare());
#endif
  std::unique_ptr<p4est_t, ForestDeleter> forest(
    p4est_new_ext(sc_MPI_COMM_SELF, connectivity.get(), 0, 0, 1, sizeof(QuadrantData), InitializeQuadrant, &context));

  const auto report = [&](double fraction) {
    context.ProgressAt = progressStart + (progressEnd - progressStart) * fraction;
    if (!observer.Report("octree", context.ProgressAt))
      throw AbortRequested{};
  };
  // Refine by the image criteria (the first half of the progress, level by
  // level), then alternate balance and the neighbour rule until the forest is
  // stable (the second half, round by round).
  if (JudgePendingLeaves(forest.get(), context) != 0)
    RefineMarkedLeaves(forest.get(), context, [&](int level) { report(0.5 * std::min(1.0, double(level) / depth)); });
  for (int round = 0;; ++round)
  {
    report(1.0 - 0.5 / (round + 1));
#ifdef P4_TO_P8
    p4est_balance(forest.get(), P8EST_CONNECT_EDGE, InitializeQuadrant);
#else
    p4est_balance(forest.get(), P4EST_CONNECT_FACE, InitializeQuadrant);
#endif
    // Leaves made by balancing have not been judged yet.
    context.Marked = JudgePendingLeaves(forest.get(), context);
    ApplyNeighbourRuleToFresh(forest.get(), context);
    if (context.Marked == 0)
      break;
    RefineMarkedLeaves(forest.get(), context, [](int) {});
  }
  p4est_iterate(forest.get(), nullptr, nullptr, nullptr, RecordFace,
#ifdef P4_TO_P8
    RecordEdge,
#endif
    nullptr);
  std::vector<OctreeLeaf> leaves;
  leaves.reserve(forest->local_num_quadrants);
  p4est_iterate(forest.get(), nullptr, &leaves, CollectLeaf, nullptr,
#ifdef P4_TO_P8
    nullptr,
#endif
    nullptr);
  report(1.0);
  return leaves;
}

} // namespace
} // namespace labelmesher
