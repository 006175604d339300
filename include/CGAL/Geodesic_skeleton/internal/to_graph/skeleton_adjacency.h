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
#include <unordered_map>
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

// `node_of(k)` is the index of the node of voxel `k` in `nodes` (sorted), or -1.
template <typename NodeOf>
Skeleton_adjacency skeleton_adjacency(std::vector<Voxel_key> nodes, const NodeOf& node_of)
{
  Skeleton_adjacency graph;
  graph.nodes = std::move(nodes);
  // Each adjacency once: the 13 offsets after the centre in neighbourhood order.
  std::vector<std::pair<int, int>> all;
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    for(int b = 13; b < 26; ++b)
    {
      const std::int32_t w = node_of(graph.nodes[v] + neighbourhood_26()[b]);
      if(w >= 0)
        all.emplace_back((std::min)(int(v), int(w)), (std::max)(int(v), int(w)));
    }
  const std::vector<bool> kept = remove_junction_triangles(graph.nodes, all);
  for(std::size_t e = 0; e < all.size(); ++e)
    if(kept[e])
      graph.edges.push_back(all[e]);
  return graph;
}

// The neighbours of each node of `graph`, in the order of its edges.
inline std::vector<std::vector<int>> neighbours_of_nodes(const Skeleton_adjacency& graph)
{
  std::vector<std::vector<int>> around(graph.nodes.size());
  for(const auto& [a, b] : graph.edges)
  {
    around[std::size_t(a)].push_back(b);
    around[std::size_t(b)].push_back(a);
  }
  return around;
}

// The voxels of `skeleton` that are end points of its graph (26-adjacency without junction
// triangles): the end points the control skeleton gets.
template <typename VoxelSet>
std::vector<Voxel_key> graph_end_points(const VoxelSet& skeleton);

// The walk from an end node (degree 1) of a graph along its nodes of degree 2: the nodes
// passed, the end node first, and the node where the walk stops, of degree 3 or more (the
// end branch's junction) or 1 (the other end of a path).
struct Walk_from_end
{
  std::vector<int> nodes;
  int stop = -1;
};

// `around`: the graph's neighbours_of_nodes(); `end` a node of degree 1.
inline Walk_from_end walk_from_end(const std::vector<std::vector<int>>& around, int end)
{
  Walk_from_end walk{{end}, around[std::size_t(end)][0]};
  int previous = end;
  while(around[std::size_t(walk.stop)].size() == 2)
  {
    const std::vector<int>& next = around[std::size_t(walk.stop)];
    const int ahead = next[0] == previous ? next[1] : next[0];
    walk.nodes.push_back(walk.stop);
    previous = walk.stop;
    walk.stop = ahead;
  }
  return walk;
}

template <typename VoxelSet>
std::vector<Voxel_key> sorted_voxels(const VoxelSet& skeleton)
{
  std::vector<Voxel_key> nodes;
  nodes.reserve(skeleton.size());
  skeleton.for_each([&](const Voxel_key& k) { nodes.push_back(k); });
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

// The graph of a voxel skeleton with the dense index of its nodes over a layout that
// covers the skeleton's voxels (its box may be larger): 4 bytes per voxel of the box.
struct Indexed_skeleton_adjacency
{
  Skeleton_adjacency graph;
  Grid_layout layout;
  std::vector<std::int32_t> node_at; // per voxel of the layout's box: its node, or -1

  // The node of voxel `k`, or -1.
  std::int32_t node_of(const Voxel_key& k) const
  {
    return layout.box.contains(k) ? node_at[layout.index(k)] : std::int32_t(-1);
  }
};

template <typename VoxelSet>
Indexed_skeleton_adjacency indexed_skeleton_adjacency(const VoxelSet& skeleton, const Grid_layout& layout)
{
  Indexed_skeleton_adjacency indexed{{}, layout, std::vector<std::int32_t>(layout.volume(), -1)};
  std::vector<Voxel_key> nodes = sorted_voxels(skeleton);
  for(std::size_t v = 0; v < nodes.size(); ++v)
    indexed.node_at[layout.index(nodes[v])] = std::int32_t(v);
  indexed.graph = skeleton_adjacency(std::move(nodes), [&](const Voxel_key& k) { return indexed.node_of(k); });
  return indexed;
}

// With a dense index over `layout` (indexed_skeleton_adjacency()), dropped once built.
template <typename VoxelSet>
Skeleton_adjacency skeleton_adjacency(const VoxelSet& skeleton, const Grid_layout& layout)
{
  return indexed_skeleton_adjacency(skeleton, layout).graph;
}

// With a hash index: memory proportional to the skeleton, not to its box.
template <typename VoxelSet>
Skeleton_adjacency skeleton_adjacency(const VoxelSet& skeleton)
{
  std::vector<Voxel_key> nodes = sorted_voxels(skeleton);
  std::unordered_map<Voxel_key, std::int32_t, Voxel_key_hash> node_at;
  node_at.reserve(nodes.size());
  for(std::size_t v = 0; v < nodes.size(); ++v)
    node_at.emplace(nodes[v], std::int32_t(v));
  return skeleton_adjacency(std::move(nodes), [&](const Voxel_key& k) {
    const auto at = node_at.find(k);
    return at != node_at.end() ? at->second : std::int32_t(-1);
  });
}

template <typename VoxelSet>
std::vector<Voxel_key> graph_end_points(const VoxelSet& skeleton)
{
  const Skeleton_adjacency graph = skeleton_adjacency(skeleton);
  const std::vector<std::vector<int>> around = neighbours_of_nodes(graph);
  std::vector<Voxel_key> ends;
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    if(around[v].size() == 1)
      ends.push_back(graph.nodes[v]);
  return ends;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_ADJACENCY_H
