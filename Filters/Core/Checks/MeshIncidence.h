// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_MeshIncidence_h
#define labelmesher_MeshIncidence_h

/**
 * @file MeshIncidence.h
 * Internal to the checks (not installed, not part of the public API): the
 * vertex -> cell incidence of a SimplexMesh and the enumeration of its distinct
 * facets (triangles of tetrahedra, edges of triangles) and edges.
 *
 * Design: no global hash table or global sort of facet keys. Every facet is
 * visited from its smallest vertex id v, by looking only at the cells incident
 * to v and sorting that short local list. Memory is the incidence table (one
 * 32-bit cell id per cell corner) plus a few small buffers, so meshes of
 * several million cells stay cheap; the time is linear in the number of cells.
 * Facets and edges are identified by vertex ids (coincident points with
 * different ids are different vertices).
 */

#include "Support/ParallelChunks.h"
#include "Mesh/SimplexMesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace labelmesher
{
namespace checks_detail
{

/// Compressed vertex -> incident cells table.
struct VertexIncidence
{
  std::vector<std::int64_t> Offsets; ///< NumberOfPoints + 1 entries
  std::vector<std::uint32_t> Cells;  ///< cell ids, grouped by vertex
  std::size_t NumberOfPoints() const { return Offsets.empty() ? 0 : Offsets.size() - 1; }
  const std::uint32_t* Begin(std::size_t v) const { return Cells.data() + Offsets[v]; }
  const std::uint32_t* End(std::size_t v) const { return Cells.data() + Offsets[v + 1]; }
};

/// Builds the incidence table. Cell vertex ids outside [0, Points.size()) are ignored.
VertexIncidence BuildVertexIncidence(const SimplexMesh& mesh);

/// Calls visit(facet, cells, count) once per distinct facet of the mesh, where
/// `facet` holds the mesh.Dimension sorted vertex ids of the facet (entry 2 is
/// -1 in 2D) and `cells` the ids of the `count` cells that have it.
template <class Visit>
void ForEachFacet(const SimplexMesh& mesh, const VertexIncidence& incidence, Visit&& visit)
{
  ForEachFacet(mesh, incidence, 0, incidence.NumberOfPoints(), visit);
}

/// ForEachFacet restricted to the facets whose smallest vertex is in [first, last):
/// disjoint ranges visit disjoint facets, so ranges can go to different threads.
template <class Visit>
void ForEachFacet(const SimplexMesh& mesh, const VertexIncidence& incidence, std::size_t first,
  std::size_t last, Visit&& visit)
{
  struct Entry
  {
    std::int64_t A, B;
    std::uint32_t Cell;
  };
  const int nv = mesh.VerticesPerCell();
  std::vector<Entry> local;
  std::vector<std::uint32_t> group;
  for (std::size_t v = first; v < last; ++v)
  {
    local.clear();
    const std::int64_t vid = static_cast<std::int64_t>(v);
    for (const std::uint32_t* c = incidence.Begin(v); c != incidence.End(v); ++c)
    {
      const std::int64_t* cv = mesh.Cell(*c);
      for (int omit = 0; omit < nv; ++omit)
      {
        if (cv[omit] == vid)
          continue;
        std::int64_t others[2] = { -1, -1 };
        int n = 0;
        bool containsV = false, vIsMin = true;
        for (int q = 0; q < nv; ++q)
        {
          if (q == omit)
            continue;
          if (cv[q] == vid && !containsV)
          {
            containsV = true;
            continue;
          }
          if (cv[q] <= vid)
            vIsMin = false;
          if (n < 2)
            others[n++] = cv[q];
        }
        if (!containsV || !vIsMin)
          continue;
        if (n == 2 && others[0] > others[1])
          std::swap(others[0], others[1]);
        local.push_back({ others[0], others[1], *c });
      }
    }
    std::sort(local.begin(), local.end(), [](const Entry& x, const Entry& y) {
      return x.A != y.A ? x.A < y.A : (x.B != y.B ? x.B < y.B : x.Cell < y.Cell);
    });
    for (std::size_t i = 0; i < local.size();)
    {
      std::size_t j = i;
      group.clear();
      while (j < local.size() && local[j].A == local[i].A && local[j].B == local[i].B)
        group.push_back(local[j++].Cell);
      const std::array<std::int64_t, 3> facet{ vid, local[i].A, local[i].B };
      visit(facet, group.data(), group.size());
      i = j;
    }
  }
}

/// Calls visit(a, b) once per distinct edge {a < b} of the mesh's cells.
/// Restricted to the edges whose smallest vertex is in [first, last).
template <class Visit>
void ForEachEdge(const SimplexMesh& mesh, const VertexIncidence& incidence, std::size_t first,
  std::size_t last, Visit&& visit)
{
  const int nv = mesh.VerticesPerCell();
  std::vector<std::int64_t> local;
  for (std::size_t v = first; v < last; ++v)
  {
    local.clear();
    const std::int64_t vid = static_cast<std::int64_t>(v);
    for (const std::uint32_t* c = incidence.Begin(v); c != incidence.End(v); ++c)
    {
      const std::int64_t* cv = mesh.Cell(*c);
      for (int q = 0; q < nv; ++q)
        if (cv[q] > vid)
          local.push_back(cv[q]);
    }
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    for (std::int64_t w : local)
      visit(vid, w);
  }
}

using labelmesher::MaxThreads;
using labelmesher::ParallelChunks;

/// One record per (mesh boundary facet, non-zero material m) such that the
/// facet lies on the boundary of m: some cell of m has it, and either it has
/// exactly one cell or one of its cells is of another material.
struct BoundaryFacetRecord
{
  std::array<std::int64_t, 3> Vertices; ///< sorted ids; entry 2 is -1 in 2D
  std::int32_t Material;
  bool FirstOfFacet; ///< first record of its facet (records of a facet are consecutive)
};
std::vector<BoundaryFacetRecord> ExtractMeshBoundary(
  const SimplexMesh& mesh, const VertexIncidence& incidence);

} // namespace checks_detail
} // namespace labelmesher

#endif
