// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BoxBins_h
#define labelmesher_BoxBins_h

/**
 * @file BoxBins.h
 * Items binned on an unbounded uniform 2D grid by their axis-aligned boxes:
 * an item goes into every bin its box overlaps, so items whose boxes
 * overlap share a bin, and a point's bin lists every item whose box holds it.
 * The broad phase of the curver's and the checks' 2D proximity tests (grow
 * a box by a reach to find items within that reach of a point).
 */

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace labelmesher
{

class BoxBins
{
public:
  using Point = std::array<double, 2>;

  explicit BoxBins(double cell)
    : Cell(cell)
  {
  }

  void Insert(std::size_t item, const Point& lo, const Point& hi)
  {
    for (long y = Bin(lo[1]); y <= Bin(hi[1]); ++y)
      for (long x = Bin(lo[0]); x <= Bin(hi[0]); ++x)
        Bins[Key(x, y)].push_back(item);
  }

  /// The items whose boxes may hold p (every one that does).
  const std::vector<std::size_t>& At(const Point& p) const
  {
    const auto it = Bins.find(Key(Bin(p[0]), Bin(p[1])));
    return it == Bins.end() ? Empty : it->second;
  }

  /// Calls f with each non-empty bin's items (in no fixed order).
  template <class Function>
  void ForEachBin(Function f) const
  {
    for (const auto& [key, items] : Bins)
      f(items);
  }

  double CellSize() const { return Cell; }

private:
  long Bin(double x) const { return static_cast<long>(std::floor(x / Cell)); }
  /// x in the high 32 bits, y in the low ones. Shifted as unsigned: shifting a negative bin
  /// index left is undefined before C++20 (UBSan found it); the keys are the same bits as before.
  static long long Key(long x, long y)
  {
    const std::uint64_t high = static_cast<std::uint32_t>(x), low = static_cast<std::uint32_t>(y);
    return static_cast<long long>((high << 32) | low);
  }

  double Cell;
  std::unordered_map<long long, std::vector<std::size_t>> Bins;
  std::vector<std::size_t> Empty;
};

} // namespace labelmesher

#endif
