// SPDX-License-Identifier: GPL-2.0-or-later
/**
 * @file ShapeGrid.cxx
 * The grid's layout: its cell edge and cell counts per axis, by GridCells.
 */

#include "Checks/ShapeGrid.h"

namespace labelmesher
{
namespace checks_detail
{

void ShapeGrid::Layout(const Point3& lo, const Point3& hi, std::size_t count, GridCells cells)
{
  Lo = lo;
  if (cells == GridCells::Voxels)
  {
    // Small cells keep the candidate lists short; the cap bounds the memory.
    constexpr double MaxCells = 16.0 * 1024 * 1024;
    Size = 2.0;
    for (;;)
    {
      double total = 1;
      for (int a = 0; a < 3; ++a)
      {
        N[a] = static_cast<int>(std::floor((hi[a] - lo[a]) / Size)) + 1;
        total *= N[a];
      }
      if (total <= MaxCells)
        return;
      Size *= 1.5;
    }
  }
  // OnePerItem: the edge that gives one item per cell over the axes of extent.
  double volume = 1.0;
  int dims = 0;
  double ext[3];
  for (int a = 0; a < 3; ++a)
  {
    ext[a] = hi[a] - lo[a];
    if (ext[a] > 0)
    {
      volume *= ext[a];
      ++dims;
    }
  }
  Size = 1.0;
  if (dims > 0 && count > 0)
    Size = std::pow(volume / static_cast<double>(count), 1.0 / dims);
  if (!(Size > 0) || !std::isfinite(Size))
    Size = 1.0;
  for (int a = 0; a < 3; ++a)
    N[a] = std::max(1, std::min(1 << 20, static_cast<int>(ext[a] / Size) + 1));
}

} // namespace checks_detail
} // namespace labelmesher
