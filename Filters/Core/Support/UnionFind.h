// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_UnionFind_h
#define labelmesher_UnionFind_h

/**
 * @file UnionFind.h
 * Disjoint sets over 0..n-1 (path halving, the smaller root wins a union),
 * the one union-find of the core: components of leaf faces and lattice points
 * in the single manifold condition, of the intersection polygon in the surface
 * patch, and of voxels and cells in the topology check.
 *
 * The smaller root winning makes every root the smallest element of its set,
 * so results never depend on the order of unions. Reset keeps the storage, so
 * one object can serve a loop without allocating.
 */

#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace labelmesher
{

class UnionFind
{
public:
  UnionFind() = default;
  explicit UnionFind(std::size_t n) { Reset(n); }

  /// n singletons (previous sets are forgotten).
  void Reset(std::size_t n)
  {
    Parent.resize(n);
    std::iota(Parent.begin(), Parent.end(), std::size_t(0));
  }
  /// A new singleton; returns its element.
  std::size_t Add()
  {
    Parent.push_back(Parent.size());
    return Parent.back();
  }
  std::size_t Size() const { return Parent.size(); }

  std::size_t Find(std::size_t x)
  {
    while (Parent[x] != x)
      x = Parent[x] = Parent[Parent[x]];
    return x;
  }
  /// Joins the sets of a and b; returns the root of the union.
  std::size_t Unite(std::size_t a, std::size_t b)
  {
    a = Find(a);
    b = Find(b);
    if (a < b)
      std::swap(a, b);
    Parent[a] = b;
    return b;
  }
  bool IsRoot(std::size_t x) const { return Parent[x] == x; }

private:
  std::vector<std::size_t> Parent;
};

} // namespace labelmesher

#endif
