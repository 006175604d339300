// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_DISTANCE_FIELDS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_DISTANCE_FIELDS_H

#include <CGAL/Geodesic_skeleton/geodesic_distances.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/vertex_components.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Geodesic distances from `sources`, as a vector indexed by the vertex index map.
template <typename FaceGraph, typename VertexIndexMap, typename Sources, typename NamedParameters>
std::vector<double> distance_field(const FaceGraph& g, VertexIndexMap vim, const Sources& sources,
                                   const NamedParameters& np)
{
  std::vector<double> d(static_cast<std::size_t>(num_vertices(g)),
                        std::numeric_limits<double>::infinity());
  geodesic_distances(g, sources, boost::make_iterator_property_map(d.begin(), vim), np);
  return d;
}

// For each component, its vertex of largest finite value in `field` (ties: the first in
// the order of vertices(g)).
template <typename FaceGraph, typename VertexIndexMap>
std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>
farthest_vertex_per_component(const FaceGraph& g, VertexIndexMap vim,
                              const Vertex_components& components, const std::vector<double>& field)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  std::vector<vertex_descriptor> farthest(components.count);
  std::vector<double> best(components.count, -1.0);
  for(vertex_descriptor v : vertices(g))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    const std::size_t c = components.component_of[i];
    if(std::isfinite(field[i]) && field[i] > best[c])
    {
      best[c] = field[i];
      farthest[c] = v;
    }
  }
  return farthest;
}

// One source per connected component, by a double sweep: the vertex farthest from the
// component's first vertex, a deterministic stand-in for an end of the component's
// geodesic diameter. Costs one Dijkstra run over the whole mesh.
template <typename FaceGraph, typename VertexIndexMap, typename NamedParameters>
std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>
diameter_end_per_component(const FaceGraph& g, VertexIndexMap vim,
                           const Vertex_components& components, const NamedParameters& np)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  std::vector<vertex_descriptor> first(components.count);
  std::vector<bool> seen(components.count, false);
  for(vertex_descriptor v : vertices(g))
  {
    const std::size_t c = components.component_of[static_cast<std::size_t>(get(vim, v))];
    if(!seen[c])
    {
      seen[c] = true;
      first[c] = v;
    }
  }
  return farthest_vertex_per_component(g, vim, components, distance_field(g, vim, first, np));
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_DISTANCE_FIELDS_H
