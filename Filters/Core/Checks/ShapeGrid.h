// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_ShapeGrid_h
#define labelmesher_ShapeGrid_h

/**
 * @file ShapeGrid.h
 * Internal to the checks (not installed, not part of the public API): the one
 * uniform spatial grid of the checks, over items known by their axis-aligned
 * bounding boxes: the boundary pieces of the Hausdorff distance check
 * (DirectedDistance.cxx) and the mesh points of the hanging-vertex test
 * (MeshConformity.cxx). A point is a box with lo == hi.
 *
 * An item id is listed in every cell its box overlaps (a counting sort into
 * one array: no allocation per cell). Coordinates beyond the grid are clamped
 * into its border cells, so a query box never misses an item. Ids are 32-bit.
 */

#include "Mesh/SimplexMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <vector>

namespace labelmesher
{
namespace checks_detail
{

/// How the grid chooses its cell edge from the items.
enum class GridCells
{
  /// Edge 2 (index units), coarsened by 1.5 while the grid has more than 16M
  /// cells: for boundary pieces, which are about a voxel or a leaf in size.
  Voxels,
  /// About one item per cell over the extent of the items (at most 2^20
  /// cells per axis): for points, which need not lie on a lattice.
  OnePerItem
};

class ShapeGrid
{
public:
  /// Grid of the items 0 .. count-1, boxOf(i, lo, hi) giving the box of item i.
  template <class BoxOf>
  ShapeGrid(std::size_t count, GridCells cells, BoxOf&& boxOf);

  /// Smallest sqDist(id) over all items, sqDist(id) being the squared distance
  /// from p to item id: a ring search outward from p's cell, which stops once
  /// the cells not yet visited are farther than the best found. +infinity if
  /// there are no items.
  template <class SqDist>
  double NearestSq(const Point3& p, SqDist&& sqDist) const;

  /// Calls f(id) for the items listed in the cells overlapping [lo, hi] (an
  /// item overlapping several of them comes once per cell).
  template <class F>
  void ForEachInBox(const Point3& lo, const Point3& hi, F&& f) const
  {
    ForEachInBox(lo, hi, [](int, int, int) { return true; }, f);
  }

  /// The same, restricted to the non-empty cells (i, j, k) for which
  /// keepCell(i, j, k) is true (e.g. the cells a plane passes through).
  template <class KeepCell, class F>
  void ForEachInBox(const Point3& lo, const Point3& hi, KeepCell&& keepCell, F&& f) const
  {
    ForEachCell(lo, hi, [&](int i, int j, int k) {
      const std::size_t cell = Cell(i, j, k);
      if (Start[cell] == Start[cell + 1] || !keepCell(i, j, k))
        return;
      for (std::size_t q = Start[cell]; q < Start[cell + 1]; ++q)
        f(Items[q]);
    });
  }

  /// Box of cell (i, j, k). Border cells are unbounded outwards: they also
  /// hold what lies beyond the grid.
  void CellBox(int i, int j, int k, Point3& lo, Point3& hi) const
  {
    const double infinity = std::numeric_limits<double>::infinity();
    const int c[3] = { i, j, k };
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = c[a] == 0 ? -infinity : Lo[a] + c[a] * Size;
      hi[a] = c[a] == N[a] - 1 ? infinity : Lo[a] + (c[a] + 1) * Size;
    }
  }

private:
  /// Sets Lo, Size and N for items spanning [lo, hi].
  void Layout(const Point3& lo, const Point3& hi, std::size_t count, GridCells cells);

  int Coord(double x, int a) const
  {
    const double t = std::floor((x - Lo[a]) / Size);
    if (!(t > 0))
      return 0;
    return t >= N[a] - 1 ? N[a] - 1 : static_cast<int>(t);
  }
  std::size_t Cell(int i, int j, int k) const
  {
    return (static_cast<std::size_t>(k) * N[1] + j) * N[0] + i;
  }
  /// Calls f(i, j, k) for the cells overlapping [lo, hi].
  template <class F>
  void ForEachCell(const Point3& lo, const Point3& hi, F&& f) const
  {
    int a0[3], a1[3];
    for (int a = 0; a < 3; ++a)
    {
      a0[a] = Coord(lo[a], a);
      a1[a] = Coord(hi[a], a);
    }
    for (int k = a0[2]; k <= a1[2]; ++k)
      for (int j = a0[1]; j <= a1[1]; ++j)
        for (int i = a0[0]; i <= a1[0]; ++i)
          f(i, j, k);
  }

  Point3 Lo{ 0, 0, 0 };
  double Size = 1.0;
  int N[3] = { 1, 1, 1 };
  std::vector<std::size_t> Start; ///< per cell, its first entry in Items (one past the end last)
  std::vector<std::uint32_t> Items;
};

template <class BoxOf>
ShapeGrid::ShapeGrid(std::size_t count, GridCells cells, BoxOf&& boxOf)
{
  if (count > 0xffffffffull)
    throw std::length_error("ShapeGrid: more than 2^32 items");
  Point3 lo{ 0, 0, 0 }, hi{ 0, 0, 0 };
  for (std::size_t i = 0; i < count; ++i)
  {
    Point3 l, h;
    boxOf(i, l, h);
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = i == 0 ? l[a] : std::min(lo[a], l[a]);
      hi[a] = i == 0 ? h[a] : std::max(hi[a], h[a]);
    }
  }
  Layout(lo, hi, count, cells);
  // Counting sort: sizes of the cells, then their ranges, then the ids.
  const std::size_t ncells = static_cast<std::size_t>(N[0]) * N[1] * N[2];
  Start.assign(ncells + 1, 0);
  std::vector<std::size_t> fill;
  for (int pass = 0; pass < 2; ++pass)
  {
    if (pass == 1)
    {
      for (std::size_t c = 0; c < ncells; ++c)
        Start[c + 1] += Start[c];
      Items.resize(Start[ncells]);
      fill.assign(Start.begin(), Start.end() - 1);
    }
    for (std::size_t i = 0; i < count; ++i)
    {
      Point3 l, h;
      boxOf(i, l, h);
      ForEachCell(l, h, [&](int ii, int j, int k) {
        const std::size_t c = Cell(ii, j, k);
        if (pass == 0)
          ++Start[c + 1];
        else
          Items[fill[c]++] = static_cast<std::uint32_t>(i);
      });
    }
  }
}

template <class SqDist>
double ShapeGrid::NearestSq(const Point3& p, SqDist&& sqDist) const
{
  const double infinity = std::numeric_limits<double>::infinity();
  int c[3];
  for (int a = 0; a < 3; ++a)
    c[a] = Coord(p[a], a);
  double best = infinity;
  auto visit = [&](int i, int j, int k) {
    const std::size_t cell = Cell(i, j, k);
    for (std::size_t q = Start[cell]; q < Start[cell + 1]; ++q)
      best = std::min(best, sqDist(Items[q]));
  };
  for (int r = 0;; ++r)
  {
    // The shell of cells at Chebyshev distance r from c.
    const int k0 = std::max(0, c[2] - r), k1 = std::min(N[2] - 1, c[2] + r);
    const int j0 = std::max(0, c[1] - r), j1 = std::min(N[1] - 1, c[1] + r);
    const int i0 = std::max(0, c[0] - r), i1 = std::min(N[0] - 1, c[0] + r);
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
      {
        if (std::abs(k - c[2]) == r || std::abs(j - c[1]) == r)
        {
          for (int i = i0; i <= i1; ++i)
            visit(i, j, k);
        }
        else
        {
          if (c[0] - r >= 0)
            visit(c[0] - r, j, k);
          if (r > 0 && c[0] + r < N[0])
            visit(c[0] + r, j, k);
        }
      }
    // Anything not visited yet lies outside the block of radius r.
    double lb = infinity;
    for (int a = 0; a < 3; ++a)
    {
      if (c[a] - r > 0)
        lb = std::min(lb, p[a] - (Lo[a] + (c[a] - r) * Size));
      if (c[a] + r < N[a] - 1)
        lb = std::min(lb, Lo[a] + (c[a] + r + 1) * Size - p[a]);
    }
    if (lb == infinity)
      break;
    lb = std::max(lb, 0.0);
    if (best <= lb * lb)
      break;
  }
  return best;
}

} // namespace checks_detail
} // namespace labelmesher

#endif
