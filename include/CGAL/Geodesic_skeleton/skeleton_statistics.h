// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_SKELETON_STATISTICS_H
#define CGAL_GEODESIC_SKELETON_SKELETON_STATISTICS_H

/// \file skeleton_statistics.h
/// Counts that describe the shape of a skeleton graph.

#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The counts of a skeleton graph, as the `skeletonize` JSON reports them per stage.
struct Skeleton_statistics
{
  std::size_t points = 0;     ///< vertices
  std::size_t edges = 0;      ///< edges
  std::size_t end_points = 0; ///< vertices of degree 1
  std::size_t junctions = 0;  ///< vertices of degree 3 or more
  std::size_t components = 0; ///< connected components
  /// Independent cycles (the first Betti number, edges - points + components): the
  /// handles of the shape, for a skeleton without spurious little loops.
  std::size_t cycles = 0;
};

/// \ingroup PkgGeodesicSkeletonRef
/// Counts the vertices, ends, junctions, components and independent cycles of an
/// undirected graph with `vecS` vertex storage (a `Curve_skeleton`, a `Reeb_graph`, ...).
/// \b Complexity: O(V + E).
template <typename Graph>
Skeleton_statistics skeleton_statistics(const Graph& g)
{
  Skeleton_statistics s;
  s.points = num_vertices(g);
  s.edges = num_edges(g);
  for(std::size_t v = 0; v < s.points; ++v)
  {
    const std::size_t d = boost::degree(v, g);
    s.end_points += d == 1;
    s.junctions += d >= 3;
  }
  if(s.points > 0)
  {
    std::vector<std::size_t> component(s.points);
    s.components = static_cast<std::size_t>(boost::connected_components(g, component.data()));
  }
  s.cycles = s.edges + s.components - s.points;
  return s;
}

namespace internal {

// skeleton_statistics() of the graph that to_graph() would make of a voxel skeleton, without
// its points and mesh vertices.
template <typename VoxelSet>
Skeleton_statistics skeleton_statistics_of_voxels(const VoxelSet& skeleton)
{
  if(skeleton.size() == 0)
    return Skeleton_statistics();
  const Skeleton_adjacency adjacency =
      skeleton_adjacency(skeleton, Grid_layout(require_nonempty_box(skeleton, 0, "skeleton_statistics")));
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> graph(adjacency.nodes.size());
  for(const auto& e : adjacency.edges)
    add_edge(std::size_t(e.first), std::size_t(e.second), graph);
  return skeleton_statistics(graph);
}

} // namespace internal

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_SKELETON_STATISTICS_H
