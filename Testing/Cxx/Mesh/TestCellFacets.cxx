// SPDX-License-Identifier: GPL-2.0-or-later
// CellFacets.h: the facet opposite each vertex, its sorted key, and the flip that makes it face
// out of a positively oriented cell, checked against geometry (the outward normal points away
// from the opposite vertex) on tetrahedra and triangles in every vertex order of positive sign.
#include "Mesh/CellFacets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace
{
using labelmesher::FacetFlips;
using labelmesher::FacetOpposite;
using labelmesher::SortedFacetOpposite;
using P = std::array<double, 3>;

double Volume(const P& a, const P& b, const P& c, const P& d)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double w[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

double Area(const P& a, const P& b, const P& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

TEST(CellFacets, OrientedFacetsOfATetrahedronFaceOutward)
{
  const std::vector<P> points = { P{ 0, 0, 0 }, P{ 1, 0, 0 }, P{ 0, 1, 0 }, P{ 0, 0, 1 } };
  std::array<std::int64_t, 4> cell{ 0, 1, 2, 3 };
  int checked = 0;
  do
  {
    if (Volume(points[cell[0]], points[cell[1]], points[cell[2]], points[cell[3]]) <= 0)
      continue; // only positively oriented cells are stored
    for (int opposite = 0; opposite < 4; ++opposite)
    {
      std::array<std::int64_t, 3> f = FacetOpposite(cell.data(), 3, opposite);
      if (FacetFlips(3, opposite))
        std::swap(f[0], f[1]);
      // Outward: the opposite vertex lies behind the facet's plane.
      EXPECT_LT(Volume(points[f[0]], points[f[1]], points[f[2]], points[cell[opposite]]), 0.0) << opposite;
      const std::array<std::int64_t, 3> key = SortedFacetOpposite(cell.data(), 3, opposite);
      EXPECT_TRUE(std::is_sorted(key.begin(), key.end()));
      EXPECT_TRUE(std::is_permutation(key.begin(), key.end(), FacetOpposite(cell.data(), 3, opposite).begin()));
      ++checked;
    }
  } while (std::next_permutation(cell.begin(), cell.end()));
  EXPECT_EQ(checked, 12 * 4);
}

TEST(CellFacets, OrientedEdgesOfATriangleRunCounterClockwiseAround)
{
  const std::vector<P> points = { P{ 0, 0, 0 }, P{ 1, 0, 0 }, P{ 0, 1, 0 } };
  std::array<std::int32_t, 3> cell{ 0, 1, 2 };
  int checked = 0;
  do
  {
    if (Area(points[cell[0]], points[cell[1]], points[cell[2]]) <= 0)
      continue;
    for (int opposite = 0; opposite < 3; ++opposite)
    {
      std::array<std::int32_t, 3> e = FacetOpposite(cell.data(), 2, opposite);
      EXPECT_EQ(e[2], -1);
      if (FacetFlips(2, opposite))
        std::swap(e[0], e[1]);
      // The edge, followed with the cell on its left, has the opposite vertex on its left.
      EXPECT_GT(Area(points[e[0]], points[e[1]], points[cell[opposite]]), 0.0) << opposite;
      const std::array<std::int32_t, 3> key = SortedFacetOpposite(cell.data(), 2, opposite);
      EXPECT_LT(key[0], key[1]);
      EXPECT_EQ(key[2], -1);
      ++checked;
    }
  } while (std::next_permutation(cell.begin(), cell.end()));
  EXPECT_EQ(checked, 3 * 3);
}

TEST(CellFacets, CellsSharingAFacetShareItsKey)
{
  // Two tetrahedra on either side of the facet {2, 5, 9}, listed in different orders.
  const std::int64_t a[4] = { 9, 2, 7, 5 };
  const std::int64_t b[4] = { 5, 11, 9, 2 };
  EXPECT_EQ(SortedFacetOpposite(a, 3, 2), SortedFacetOpposite(b, 3, 1));
  EXPECT_EQ(SortedFacetOpposite(a, 3, 2), (std::array<std::int64_t, 3>{ 2, 5, 9 }));
}

} // namespace
