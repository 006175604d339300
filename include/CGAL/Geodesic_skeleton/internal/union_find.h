// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_UNION_FIND_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_UNION_FIND_H

// The root lookup of a union-find forest kept as a vector of parents (a root is its own
// parent), for the stages whose sets are dense integer ranges: the skinning's clusters and
// pieces, the junction triangles of to_graph(); and a forest that threads join concurrently.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The root of `x` in the forest `parent`, halving the path on the way (`x` converts to the
// forest's index type).
template <typename Index>
Index find_root(std::vector<Index>& parent, typename std::vector<Index>::value_type x)
{
  while(parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// A union-find forest over [0, n) that several threads may join at once (lock-free): each
// root is linked to a smaller one by compare-and-swap, which fails if it is no longer a root,
// so a set's root is always its smallest member and the sets, once the threads are done, are
// the same in whatever order the joins came. Paths are halved on the way, which only ever
// points a member at another member of its set.
class Concurrent_forest
{
public:
  explicit Concurrent_forest(std::size_t n) : m_parent(n)
  {
    for(std::size_t x = 0; x < n; ++x)
      m_parent[x].store(std::uint32_t(x), std::memory_order_relaxed);
  }

  std::uint32_t root(std::uint32_t x)
  {
    for(std::uint32_t p; (p = m_parent[x].load(std::memory_order_relaxed)) != x;)
    {
      const std::uint32_t grandparent = m_parent[p].load(std::memory_order_relaxed);
      if(grandparent == p)
        return p;
      m_parent[x].store(grandparent, std::memory_order_relaxed); // written only when it changes
      x = grandparent;
    }
    return x;
  }

  void join(std::uint32_t a, std::uint32_t b)
  {
    for(;;)
    {
      std::uint32_t ra = root(a), rb = root(b);
      if(ra == rb)
        return;
      if(ra < rb)
        std::swap(ra, rb);
      if(m_parent[ra].compare_exchange_weak(ra, rb, std::memory_order_relaxed))
        return;
    }
  }

private:
  std::vector<std::atomic<std::uint32_t>> m_parent;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_UNION_FIND_H
