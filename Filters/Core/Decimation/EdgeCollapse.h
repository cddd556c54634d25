// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_EdgeCollapse_h
#define labelmesher_EdgeCollapse_h

/**
 * @file EdgeCollapse.h
 * One vertex merge of section 3.1.3: vertex From moves onto its neighbour To
 * along their edge, the cells around the edge vanish and the other cells
 * around From take To instead (Figure 15). Planned locally, from the cells
 * around From and To alone, so that the checks can judge it before anything
 * changes: the cells that vanish, move and stay, and the interface faces
 * touching the two vertices before and touching To after (faces between
 * different labels, the box's faces included as faces against its outside).
 * Apply then edits the mesh.
 */

#include "Decimation/EditableMesh.h"

#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

class EdgeCollapse
{
public:
  /// Plans the merge of `from` onto `to`: which cells vanish, move and stay.
  /// Returns false when they are not neighbours.
  bool Plan(const EditableMesh& mesh, VertexId from, VertexId to);
  /// Completes the plan with the interface faces before and after (the
  /// quality check does not need them, so it runs first). Returns false when
  /// the result would not be a conforming mesh of the box (a face with three
  /// cells, or a lone face off the box): such a merge is never valid.
  bool PlanInterfaces(const EditableMesh& mesh);
  /// Carries the planned merge out.
  void Apply(EditableMesh& mesh) const;

  VertexId From = -1, To = -1;
  std::vector<CellId> Removed; ///< cells with both vertices: they vanish
  std::vector<CellId> Moved;   ///< cells with From only
  std::vector<CellId> Kept;    ///< cells with To only
  std::vector<std::array<VertexId, 4>> MovedCells; ///< Moved, with From replaced by To
  std::vector<InterfaceFace> Before; ///< interface faces touching From or To, sorted, each once
  std::vector<InterfaceFace> After;  ///< interface faces touching To after the merge, sorted

private:
  bool CollectFaces(const EditableMesh& mesh, const std::vector<const std::array<VertexId, 4>*>& cells,
    const std::vector<std::int32_t>& labels, VertexId touchA, VertexId touchB, std::vector<InterfaceFace>& out);
  struct FaceSlot
  {
    std::array<VertexId, 3> Vertices{ -1, -1, -1 };
    std::int32_t Label = 0, Other = 0;
    int Count = 0;
    std::uint32_t Generation = 0;
  };
  std::vector<FaceSlot> Table; // scratch: faces by vertices
  std::vector<std::uint32_t> Used;
  std::uint32_t Generation = 0;
  std::vector<const std::array<VertexId, 4>*> CellScratch;
  std::vector<std::int32_t> LabelScratch;
};

} // namespace labelmesher

#endif
