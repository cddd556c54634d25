// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_EditableMesh_h
#define labelmesher_EditableMesh_h

/**
 * @file EditableMesh.h
 * The mesh the decimator edits: the initial mesh's points on their doubled
 * lattice (integer coordinates 2x, LeafBox.h: every point of the ORD mesh is a
 * multiple of half a voxel, and a merge only moves a vertex onto another, so
 * positions stay integers and orientation tests are exact), cells with their
 * labels, and the cells around every vertex.
 *
 * The mesh fills an axis-aligned box (the mesher's octree domain, background
 * cells included): its faces with one cell lie on that box, and the outside
 * across box plane f counts as a label of its own, OutsideLabel(f) < 0, so
 * that the box's faces, edges and corners are strata like the interfaces, and
 * a vertex on the box stays on it. Keeping the box fixed and every cell
 * positively oriented keeps the whole mesh embedded (no fold-over anywhere),
 * which a mesh without its background could not promise.
 *
 * Thread safety: a merge changes only the cells around its two vertices and
 * the lists of the vertices of those cells; merges whose stars lie in
 * disjoint vertex sets may run at once (MeshDecimator.cxx).
 */

#include "Mesh/CellFacets.h"
#include "Mesh/SimplexMesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{

using VertexId = std::int32_t;
using CellId = std::int32_t;
using Lattice = std::array<std::int32_t, 3>;

/// A face (sorted vertex ids; the third is -1 in 2D) between two different
/// labels, Low < High (outside labels are negative).
struct InterfaceFace
{
  std::array<VertexId, 3> Vertices;
  std::int32_t Low, High;

  bool Contains(VertexId v) const { return Vertices[0] == v || Vertices[1] == v || Vertices[2] == v; }
  bool SamePair(const InterfaceFace& o) const { return Low == o.Low && High == o.High; }
  bool Separates(std::int32_t label) const { return Low == label || High == label; }
};
bool operator<(const InterfaceFace& a, const InterfaceFace& b);
bool operator==(const InterfaceFace& a, const InterfaceFace& b);

class EditableMesh
{
public:
  /// Takes `mesh` (index space). Throws std::invalid_argument, naming the
  /// problem, when a point is off the half-voxel lattice, a cell is not
  /// positively oriented, a face has more than two cells, or a face with one
  /// cell is not on the bounding box (the mesh does not fill it).
  explicit EditableMesh(const SimplexMesh& mesh);
  /// The same, taking `mesh` over: each of its arrays is freed as soon as it
  /// is copied, so that the two meshes never add up (the decimator's peak).
  explicit EditableMesh(SimplexMesh&& mesh);
  /// A piece of a larger mesh (a block of the streamed pipeline,
  /// Streaming/StreamedPipeline.h), taken over: the box is the whole mesh's,
  /// [boxLow, boxHigh] on the doubled lattice, and a face with one cell off
  /// that box is the piece's border, shared with cells not here: its
  /// vertices are flagged in Border. Nothing else changes.
  EditableMesh(SimplexMesh&& mesh, const Lattice& boxLow, const Lattice& boxHigh);

  int Dimension = 3;
  int VerticesPerCell() const { return Dimension + 1; }

  std::vector<Lattice> Position;              ///< doubled lattice: 2 x index-space coordinates
  std::vector<std::array<VertexId, 4>> Cells; ///< Dimension + 1 vertices (the 4th unused in 2D)
  std::vector<std::int32_t> Labels;
  std::vector<std::uint8_t> CellAlive;
  std::vector<std::vector<CellId>> CellsOf;  ///< alive cells around each vertex
  std::vector<std::uint8_t> BoxPlanes;       ///< bit f: the vertex lies on box plane f (axis f/2, high side f%2)
  Lattice BoxLow{}, BoxHigh{};
  /// Per vertex, pieces only (else empty): on the piece's border. A border
  /// vertex must never move or vanish (the decimator freezes it), and no
  /// interface is seen across the border (InterfaceFaces skips its faces).
  std::vector<std::uint8_t> Border;

  static std::int32_t OutsideLabel(int plane) { return -1 - plane; }
  static bool IsOutside(std::int32_t label) { return label < 0; }

  bool Contains(CellId c, VertexId v) const;
  /// Exact orientation of the cell with these vertices: > 0 positive.
  static long long Orientation(int dimension, const Lattice* p);

  /// The box plane all vertices of `face` lie on, or -1.
  int OutsidePlane(const std::array<VertexId, 3>& face) const;

  /// Every face between two different labels (the box's faces against its
  /// outside included; a piece's border faces not), each once, ordered by vertices.
  std::vector<InterfaceFace> InterfaceFaces() const;

  /// The alive cells, with their points renumbered in order of first use
  /// (unused points dropped), in index space.
  SimplexMesh ToSimplexMesh() const;
  std::size_t AliveCells() const;
  std::size_t AliveVertices() const;

private:
  /// Every constructor: `release` is `mesh` when taken over (its arrays are
  /// freed once copied), else null; `box` (low, high) the given box of a
  /// piece, else null (the points' bounding box, and no border allowed).
  void Build(const SimplexMesh& mesh, SimplexMesh* release, const Lattice* box);

  struct FaceUse
  {
    std::array<VertexId, 3> Vertices; ///< sorted, -1 padded
    CellId Cell;
    bool operator<(const FaceUse& o) const { return Vertices < o.Vertices || (Vertices == o.Vertices && Cell < o.Cell); }
  };
  /// Calls visit(uses, count) once per face whose smallest vertex is v, with
  /// the (one or more) cells that have it.
  template <typename Visit>
  void ForEachFaceFrom(VertexId v, std::vector<FaceUse>& scratch, Visit&& visit) const
  {
    scratch.clear();
    for (CellId c : CellsOf[v])
      for (int opposite = 0; opposite <= Dimension; ++opposite)
      {
        const FaceUse use{ SortedFacetOpposite(Cells[c].data(), Dimension, opposite), c };
        if (use.Vertices[0] == v)
          scratch.push_back(use);
      }
    std::sort(scratch.begin(), scratch.end());
    for (std::size_t f = 0; f < scratch.size();)
    {
      std::size_t g = f + 1;
      while (g < scratch.size() && scratch[g].Vertices == scratch[f].Vertices)
        ++g;
      visit(&scratch[f], g - f);
      f = g;
    }
  }
};

} // namespace labelmesher

#endif
