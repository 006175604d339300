// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_INDEXED_VERTICES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_INDEXED_VERTICES_H

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The vertices of a graph, stored at their index. Building it checks that the vertex index
// map is a bijection onto [0, num_vertices(g)), which Boost.Graph's algorithms assume (a
// Surface_mesh with removed vertices breaks it until collect_garbage() is called), and it
// answers in O(1) whether a vertex descriptor belongs to the graph.
template <typename Graph, typename VertexIndexMap>
class Indexed_vertices
{
public:
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;

  Indexed_vertices(const Graph& g, VertexIndexMap vim, const char* caller)
    : m_vim(vim), m_caller(caller)
  {
    const std::size_t n = static_cast<std::size_t>(num_vertices(g));
    m_vertex_at.resize(n);
    std::vector<bool> seen(n, false);
    for(vertex_descriptor v : vertices(g))
    {
      const std::size_t i = static_cast<std::size_t>(get(m_vim, v));
      if(i >= n || seen[i])
        throw std::invalid_argument(
            std::string(caller) +
            ": the vertex index map is not a bijection onto [0, num_vertices(g)) "
            "(a Surface_mesh with removed elements needs collect_garbage() first)");
      seen[i] = true;
      m_vertex_at[i] = v;
    }
  }

  std::size_t size() const { return m_vertex_at.size(); }

  bool contains(vertex_descriptor v) const
  {
    if(v == boost::graph_traits<Graph>::null_vertex())
      return false;
    const std::size_t i = static_cast<std::size_t>(get(m_vim, v));
    return i < m_vertex_at.size() && m_vertex_at[i] == v;
  }

  // Throws std::invalid_argument naming `what` when `v` is not a vertex of the graph.
  void require(vertex_descriptor v, const char* what) const
  {
    if(!contains(v))
      throw std::invalid_argument(std::string(m_caller) + ": the " + what +
                                  " is not a vertex of the mesh");
  }

private:
  VertexIndexMap m_vim;
  const char* m_caller;
  std::vector<vertex_descriptor> m_vertex_at;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_INDEXED_VERTICES_H
