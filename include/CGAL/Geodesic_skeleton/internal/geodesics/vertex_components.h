// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_VERTEX_COMPONENTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_VERTEX_COMPONENTS_H

#include <boost/graph/graph_traits.hpp>
#include <boost/pending/disjoint_sets.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Connected components of the vertices of a graph through its edges, numbered 0, 1, ... in
// the order of their smallest vertex index (deterministic).
struct Vertex_components
{
  std::vector<std::size_t> component_of; // by vertex index (-1 for a removed vertex)
  std::size_t count = 0;
};

// `joined(e)` says whether edge e links its ends; the default links every edge.
template <typename Graph, typename VertexIndexMap, typename EdgePredicate>
Vertex_components vertex_components(const Graph& g, VertexIndexMap vim, EdgePredicate joined)
{
  const std::size_t n = static_cast<std::size_t>(num_vertices(g));
  boost::disjoint_sets_with_storage<> sets(n);
  for(std::size_t i = 0; i < n; ++i)
    sets.make_set(i);
  for(auto e : edges(g))
    if(joined(e))
      sets.union_set(static_cast<std::size_t>(get(vim, source(e, g))),
                     static_cast<std::size_t>(get(vim, target(e, g))));

  Vertex_components result;
  const std::size_t unnumbered = static_cast<std::size_t>(-1);
  std::vector<std::size_t> number_of_root(n, unnumbered);
  result.component_of.assign(n, unnumbered);
  for(auto v : vertices(g)) // not 0..n: a Surface_mesh may have removed vertices
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    const std::size_t root = sets.find_set(i);
    if(number_of_root[root] == unnumbered)
      number_of_root[root] = result.count++;
    result.component_of[i] = number_of_root[root];
  }
  return result;
}

template <typename Graph, typename VertexIndexMap>
Vertex_components vertex_components(const Graph& g, VertexIndexMap vim)
{
  return vertex_components(g, vim, [](const auto&) { return true; });
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_VERTEX_COMPONENTS_H
