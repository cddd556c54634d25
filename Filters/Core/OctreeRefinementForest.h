// SPDX-License-Identifier: GPL-2.0-or-later
// The body of BuildForest2 / BuildForest3, written once against p4est's 2D
// names; OctreeRefinement3D.cxx includes <p4est_to_p8est.h> first, which maps
// every p4est_ name to its p8est_ twin (p4est's own idiom for sharing code).
// Not a public header: included by exactly those two files.

#include "OctreeRefinement.h"

#include <array>
#include <exception>
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
  std::size_t Evaluations = 0;
  /// p4est is C: nothing may unwind through its callbacks. The first error
  /// (or an abort request) is kept here, later callbacks do nothing, and it is
  /// rethrown once p4est has returned.
  std::exception_ptr Failure;
};

QuadrantData& Data(p4est_quadrant_t* q) { return *static_cast<QuadrantData*>(q->p.user_data); }
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

/// Evaluates a leaf once; returns true when it must be split.
bool EvaluateLeaf(ForestContext& context, p4est_quadrant_t* q)
{
  QuadrantData& data = Data(q);
  if (data.State == LeafState::MarkedForRefinement)
    return true;
  if (data.State == LeafState::Accepted || context.Failure)
    return false;
  LeafVerdict verdict;
  try
  {
    if (++context.Evaluations % 65536 == 0 && !context.Observer->Report("octree", context.ProgressAt))
      throw AbortRequested{};
    verdict = (*context.Evaluate)(BoxOf(q, context.Depth));
    if (verdict.Refine && q->level >= context.Depth)
      throw std::logic_error("the leaf evaluator asked to split a single voxel");
  }
  catch (...)
  {
    context.Failure = std::current_exception();
    return false;
  }
  if (verdict.Refine)
  {
    data.State = LeafState::MarkedForRefinement;
    return true;
  }
  data.First = verdict.First;
  data.Second = verdict.Second;
  data.RigidFaces = verdict.RigidFaces;
  data.State = LeafState::Accepted;
  return false;
}

int RefineCallback(p4est_t* p4est, p4est_topidx_t, p4est_quadrant_t* q)
{
  return EvaluateLeaf(Context(p4est), q) ? 1 : 0;
}

void EvaluateVolume(p4est_iter_volume_info_t* info, void*)
{
  ForestContext& context = Context(info->p4est);
  if (Data(info->quad).State == LeafState::Unevaluated && EvaluateLeaf(context, info->quad))
    ++context.Marked;
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

/// Quadrants around a face or edge and the finest level among them. At most eight quadrants touch a face
/// (1 + 4) or an edge (4 sides of up to 2): a fixed array, no allocation.
template <typename Side, int Hanging>
struct Neighbourhood
{
  std::array<p4est_quadrant_t*, 8> Quadrants{};
  int Count = 0;
  int FinestLevel = -1;

  explicit Neighbourhood(sc_array_t& sides)
  {
    for (std::size_t s = 0; s < sides.elem_count; ++s)
    {
      Side* side = static_cast<Side*>(sc_array_index(&sides, s));
      if (side->is_hanging)
      {
        for (int h = 0; h < Hanging; ++h)
          Add(side->is.hanging.quad[h]);
      }
      else
        Add(side->is.full.quad);
    }
  }
  void Add(p4est_quadrant_t* q)
  {
    if (!q || Count == static_cast<int>(Quadrants.size()))
      return;
    Quadrants[Count++] = q;
    FinestLevel = std::max(FinestLevel, static_cast<int>(q->level));
  }
};

bool IsProper(p4est_quadrant_t* q) { return Data(q).First != Data(q).Second; }

/// Around a face or edge where leaves of different sizes meet: a leaf larger
/// than a proper one is split (an intersection vertex would be its quarter
/// point), and so is a proper leaf whose rigid faces would receive the finer
/// leaves' points. `touched(q)` gives the faces of the larger leaf q that get
/// those points.
template <typename Hood, typename TouchedFaces>
void MarkAroundSizeChange(ForestContext& context, const Hood& hood, TouchedFaces&& touched)
{
  bool finerProper = false;
  for (int i = 0; i < hood.Count; ++i)
    finerProper = finerProper || (hood.Quadrants[i]->level == hood.FinestLevel && IsProper(hood.Quadrants[i]));
  for (int i = 0; i < hood.Count; ++i)
  {
    p4est_quadrant_t* q = hood.Quadrants[i];
    if (q->level >= hood.FinestLevel)
      continue;
    if (finerProper || (IsProper(q) && (Data(q).RigidFaces & touched(q)) != 0))
      Mark(context, q);
  }
}

void CheckFace(p4est_iter_face_info_t* info, void*)
{
  ForestContext& context = Context(info->p4est);
  const Neighbourhood<p4est_iter_face_side_t, P4EST_HALF> hood(info->sides);
  if (hood.Count < 2)
    return;
  // A split face puts points on the face and on its edges: every face of the
  // larger leaf but the opposite one.
  int face = -1;
  for (std::size_t s = 0; s < info->sides.elem_count; ++s)
  {
    auto* side = static_cast<p4est_iter_face_side_t*>(sc_array_index(&info->sides, s));
    if (!side->is_hanging)
      face = side->face;
  }
  MarkAroundSizeChange(context, hood, [face](p4est_quadrant_t*) {
#ifdef P4_TO_P8
    return static_cast<unsigned>(0x3f & ~(1u << (face ^ 1)));
#else
    return static_cast<unsigned>(1u << face);
#endif
  });
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
void CheckEdge(p8est_iter_edge_info_t* info, void*)
{
  ForestContext& context = Context(info->p4est);
  const Neighbourhood<p8est_iter_edge_side_t, 2> hood(info->sides);
  // The larger leaves get a midpoint on this edge: on the two faces holding it.
  std::array<std::pair<p4est_quadrant_t*, unsigned>, 4> faces{};
  std::size_t count = 0;
  for (std::size_t s = 0; s < info->sides.elem_count && count < faces.size(); ++s)
  {
    auto* side = static_cast<p8est_iter_edge_side_t*>(sc_array_index(&info->sides, s));
    if (side->is_hanging || !side->is.full.quad)
      continue;
    const int edge = side->edge, axis = edge / 4;
    const auto others = OtherAxes(axis);
    faces[count++] = { side->is.full.quad,
      (1u << (2 * others[0] + (edge & 1))) | (1u << (2 * others[1] + ((edge >> 1) & 1))) };
  }
  MarkAroundSizeChange(context, hood, [&](p4est_quadrant_t* q) {
    for (std::size_t i = 0; i < count; ++i)
      if (faces[i].first == q)
        return faces[i].second;
    return 0u;
  });
}

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
  detail::EnsureMPIInitialized();
  ForestContext context{ &evaluate, depth, &observer, progressStart, 0, 0, nullptr };
  #ifdef P4_TO_P8
  std::unique_ptr<p4est_connectivity_t, ForestDeleter> connectivity(p8est_connectivity_new_unitcube());
#else
  std::unique_ptr<p4est_connectivity_t, ForestDeleter> connectivity(p4est_connectivity_new_unitsquare());
#endif
  std::unique_ptr<p4est_t, ForestDeleter> forest(
    p4est_new_ext(sc_MPI_COMM_SELF, connectivity.get(), 0, 0, 1, sizeof(QuadrantData), InitializeQuadrant, &context));

  const auto report = [&](double fraction) {
    if (context.Failure)
      std::rethrow_exception(context.Failure);
    context.ProgressAt = progressStart + (progressEnd - progressStart) * fraction;
    if (!observer.Report("octree", context.ProgressAt))
      throw AbortRequested{};
  };
  // Refine by the image criteria, then alternate balance and the neighbour
  // rule until the forest is stable.
  p4est_refine(forest.get(), 1, RefineCallback, InitializeQuadrant);
  for (int round = 0;; ++round)
  {
    report(1.0 - 1.0 / (round + 2));
#ifdef P4_TO_P8
    p4est_balance(forest.get(), P8EST_CONNECT_EDGE, InitializeQuadrant);
#else
    p4est_balance(forest.get(), P4EST_CONNECT_FACE, InitializeQuadrant);
#endif
    context.Marked = 0;
    // Leaves made by balancing have not been judged yet.
    p4est_iterate(forest.get(), nullptr, nullptr, EvaluateVolume, nullptr,
#ifdef P4_TO_P8
      nullptr,
#endif
      nullptr);
    p4est_iterate(forest.get(), nullptr, nullptr, nullptr, CheckFace,
#ifdef P4_TO_P8
      CheckEdge,
#endif
      nullptr);
    if (context.Failure)
      std::rethrow_exception(context.Failure);
    if (context.Marked == 0)
      break;
    p4est_refine(forest.get(), 1, RefineCallback, InitializeQuadrant);
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
