// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_ADJACENCY_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_ADJACENCY_H

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/junction_triangles.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The graph of a voxel skeleton: its voxels in increasing (z, y, x) order, and the edges
// between 26-adjacent voxels (node indices, first < second) that make no junction triangle
// (internal/to_graph/junction_triangles.h), so that its cycle rank E - V + C is the number of
// tunnels of the skeleton.
struct Skeleton_adjacency
{
  std::vector<Voxel_key> nodes;
  std::vector<std::pair<int, int>> edges;
};

// `layout` covers the skeleton's voxels (its box may be larger).
template <typename VoxelSet>
Skeleton_adjacency skeleton_adjacency(const VoxelSet& skeleton, const Grid_layout& layout)
{
  Skeleton_adjacency graph;
  graph.nodes.reserve(skeleton.size());
  skeleton.for_each([&](const Voxel_key& k) { graph.nodes.push_back(k); });
  std::sort(graph.nodes.begin(), graph.nodes.end());
  std::vector<std::int32_t> node_at(layout.volume(), -1);
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    node_at[layout.index(graph.nodes[v])] = std::int32_t(v);

  // Each adjacency once: the 13 offsets after the centre in neighbourhood order.
  std::vector<std::pair<int, int>> all;
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    for(int b = 13; b < 26; ++b)
    {
      const Voxel_key n = graph.nodes[v] + neighbourhood_26()[b];
      if(!layout.box.contains(n))
        continue;
      const std::int32_t w = node_at[layout.index(n)];
      if(w >= 0)
        all.emplace_back((std::min)(int(v), int(w)), (std::max)(int(v), int(w)));
    }
  const std::vector<bool> kept = remove_junction_triangles(graph.nodes, all);
  for(std::size_t e = 0; e < all.size(); ++e)
    if(kept[e])
      graph.edges.push_back(all[e]);
  return graph;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_ADJACENCY_H
