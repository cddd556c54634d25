// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_BoxBins_h
#define labelmesher_BoxBins_h

/**
 * @file BoxBins.h
 * Items binned on an unbounded uniform 2D or 3D grid by their axis-aligned boxes:
 * an item goes into every bin its box overlaps, so items whose boxes
 * overlap share a bin, and a point's bin lists every item whose box holds it.
 * The broad phase of the curvers' and the checks' proximity tests (grow a
 * box by a reach to find items within that reach of a point).
 */

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace labelmesher
{

template <std::size_t D>
class BoxBinsOf
{
public:
  using Point = std::array<double, D>;

  explicit BoxBinsOf(double cell)
    : Cell(cell)
  {
  }

  void Insert(std::size_t item, const Point& lo, const Point& hi)
  {
    std::array<long, D> first, last, at;
    for (std::size_t a = 0; a < D; ++a)
      at[a] = first[a] = Bin(lo[a]), last[a] = Bin(hi[a]);
    for (;;)
    {
      Bins[Key(at)].push_back(item);
      std::size_t a = 0;
      while (a < D && at[a] == last[a])
        at[a] = first[a], ++a;
      if (a == D)
        return;
      ++at[a];
    }
  }

  /// The items whose boxes may hold p (every one that does).
  const std::vector<std::size_t>& At(const Point& p) const
  {
    std::array<long, D> at;
    for (std::size_t a = 0; a < D; ++a)
      at[a] = Bin(p[a]);
    const auto it = Bins.find(Key(at));
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
  /// The first axis in the highest bits (32 each in 2D, 21 in 3D). Shifted as unsigned: shifting
  /// a negative bin index left is undefined before C++20 (UBSan found it).
  static long long Key(const std::array<long, D>& at)
  {
    constexpr unsigned bits = 64 / D;
    constexpr std::uint64_t mask = bits >= 32 ? 0xffffffffu : (std::uint64_t{ 1 } << bits) - 1;
    std::uint64_t key = 0;
    for (std::size_t a = 0; a < D; ++a)
      key = (key << bits) | (static_cast<std::uint64_t>(static_cast<std::uint32_t>(at[a])) & mask);
    return static_cast<long long>(key);
  }

  double Cell;
  std::unordered_map<long long, std::vector<std::size_t>> Bins;
  std::vector<std::size_t> Empty;
};

using BoxBins = BoxBinsOf<2>;
using BoxBins3 = BoxBinsOf<3>;

} // namespace labelmesher

#endif
