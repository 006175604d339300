// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_UNION_FIND_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_UNION_FIND_H

// The root lookup of a union-find forest kept as a vector of parents (a root is its own
// parent), for the stages whose sets are dense integer ranges: the skinning's clusters and
// pieces, the junction triangles of to_graph().

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

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_UNION_FIND_H
