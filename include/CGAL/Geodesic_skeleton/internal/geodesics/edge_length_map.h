// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_EDGE_LENGTH_MAP_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_EDGE_LENGTH_MAP_H

#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A readable edge property map: the Euclidean length (as double) of an edge, computed
// from the vertex point map each time it is read (no storage, O(1) per read).
template <typename Graph, typename VertexPointMap, typename GeomTraits>
struct Edge_length_map
{
  using key_type = typename boost::graph_traits<Graph>::edge_descriptor;
  using value_type = double;
  using reference = double;
  using category = boost::readable_property_map_tag;

  const Graph* graph;
  VertexPointMap vpm;
  GeomTraits traits;

  friend double get(const Edge_length_map& m, key_type e)
  {
    const auto squared_length = m.traits.compute_squared_distance_3_object()(
        get(m.vpm, source(e, *m.graph)), get(m.vpm, target(e, *m.graph)));
    return std::sqrt(CGAL::to_double(squared_length));
  }
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_EDGE_LENGTH_MAP_H
