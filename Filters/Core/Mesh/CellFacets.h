// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_CellFacets_h
#define labelmesher_CellFacets_h

/**
 * @file CellFacets.h
 * The facets of a simplex, in one place for the algorithm (the decimator's editable mesh and
 * merges, the interface extraction): the facet opposite vertex i of a cell is the cell's other
 * vertices. Listed in cell order it faces out of a positively oriented cell (SimplexMesh.h) when
 * FacetFlips says no; sorted, it is the key every cell sharing it has.
 *
 * The independent checks (Checks/MeshIncidence.h) enumerate facets their own way on purpose:
 * they share no code with what they check.
 */

#include <array>
#include <utility>

namespace labelmesher
{

/// The facet of `cell` (dimension + 1 vertex ids) opposite its vertex `opposite`: the other
/// `dimension` ids in cell order, then -1 up to three entries.
template <typename Id>
inline std::array<Id, 3> FacetOpposite(const Id* cell, int dimension, int opposite)
{
  std::array<Id, 3> facet{ Id(-1), Id(-1), Id(-1) };
  int n = 0;
  for (int i = 0; i <= dimension; ++i)
    if (i != opposite)
      facet[n++] = cell[i];
  return facet;
}

/// The facet's `dimension` ids in increasing order (the -1 padding stays last).
template <typename Id>
inline void SortFacet(std::array<Id, 3>& facet, int dimension)
{
  // Two or three ids: a sorting network, cheaper than std::sort in the merges' inner loop.
  if (facet[0] > facet[1])
    std::swap(facet[0], facet[1]);
  if (dimension == 3)
  {
    if (facet[1] > facet[2])
      std::swap(facet[1], facet[2]);
    if (facet[0] > facet[1])
      std::swap(facet[0], facet[1]);
  }
}

/// FacetOpposite, sorted: the key shared by the cells that have the facet.
template <typename Id>
inline std::array<Id, 3> SortedFacetOpposite(const Id* cell, int dimension, int opposite)
{
  std::array<Id, 3> facet = FacetOpposite(cell, dimension, opposite);
  SortFacet(facet, dimension);
  return facet;
}

/// True when FacetOpposite(cell, dimension, opposite), listed in cell order, must swap its first
/// two ids to face out of a positively oriented cell (removing vertex i of a tetrahedron is an
/// odd permutation for odd i; in a triangle only the edge opposite vertex 1 runs backwards).
inline bool FacetFlips(int dimension, int opposite)
{
  return dimension == 3 ? opposite % 2 == 1 : opposite == 1;
}

} // namespace labelmesher

#endif
