// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_DISJOINT_SETS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_DISJOINT_SETS_H

#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Union-find over the integer ids 0, 1, ... (path halving): `n` singletons at first, more
// with add().
class Disjoint_sets
{
public:
  explicit Disjoint_sets(std::size_t n = 0) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::size_t(0)); }
  // A new singleton; returns its id.
  std::size_t add()
  {
    m_parent.push_back(m_parent.size());
    return m_parent.back();
  }
  std::size_t find(std::size_t a)
  {
    while(m_parent[a] != a)
      a = m_parent[a] = m_parent[m_parent[a]];
    return a;
  }
  // Joins the sets of `a` and `b`; false when they were one already.
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return false;
    m_parent[b] = a;
    return true;
  }

private:
  std::vector<std::size_t> m_parent;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_DISJOINT_SETS_H
