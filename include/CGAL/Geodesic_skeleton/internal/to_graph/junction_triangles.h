// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_JUNCTION_TRIANGLES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_JUNCTION_TRIANGLES_H

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/union_find.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Rank over Z/2 of a set of rows (bit vectors of `words` 64-bit words), by elimination.
inline std::size_t rank_mod2(std::vector<std::vector<std::uint64_t>> rows)
{
  std::size_t rank = 0;
  if(rows.empty())
    return 0;
  const std::size_t bits = rows[0].size() * 64;
  for(std::size_t bit = 0; bit < bits && rank < rows.size(); ++bit)
  {
    const std::size_t w = bit / 64;
    const std::uint64_t m = std::uint64_t(1) << (bit % 64);
    std::size_t pivot = rank;
    while(pivot < rows.size() && !(rows[pivot][w] & m))
      ++pivot;
    if(pivot == rows.size())
      continue;
    std::swap(rows[pivot], rows[rank]);
    for(std::size_t r = 0; r < rows.size(); ++r)
      if(r != rank && (rows[r][w] & m))
        for(std::size_t k = 0; k < rows[r].size(); ++k)
          rows[r][k] ^= rows[rank][k];
    ++rank;
  }
  return rank;
}

// Whether triangle `t` (three edge ids) contains edge `e`.
inline bool has_edge(const std::array<int, 3>& t, int e) { return t[0] == e || t[1] == e || t[2] == e; }

// The edges of the triangles `cluster`, in increasing order: the cluster's local numbering.
inline std::vector<int> edges_of_cluster(const std::vector<std::array<int, 3>>& triangles,
                                         const std::vector<int>& cluster)
{
  std::vector<int> local_edges;
  for(int t : cluster)
    for(int e : triangles[t])
      local_edges.push_back(e);
  std::sort(local_edges.begin(), local_edges.end());
  local_edges.erase(std::unique(local_edges.begin(), local_edges.end()), local_edges.end());
  return local_edges;
}

// Removes the edges of one cluster of edge-sharing triangles, the longest first, each only
// when it lowers the rank of the remaining triangles' boundaries by exactly one, so that the
// cycle rank of the graph is kept. Each check is an elimination over the cluster: O(E T^2)
// for E edges and T triangles, for the small clusters of junctions and diagonal steps.
template <typename SquaredLength>
void reduce_cluster_exactly(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& cluster,
                            const std::vector<int>& local_edges, const std::vector<int>& local_of_edge,
                            const SquaredLength& squared_length, std::vector<bool>& kept)
{
  const std::size_t words = (local_edges.size() + 63) / 64;
  auto local = [&](int e) { return std::size_t(local_of_edge[std::size_t(e)]); };
  auto boundaries = [&](const std::vector<int>& alive) {
    std::vector<std::vector<std::uint64_t>> rows;
    for(int t : alive)
    {
      std::vector<std::uint64_t> row(words, 0);
      for(int e : triangles[t])
      {
        const std::size_t l = local(e);
        row[l / 64] |= std::uint64_t(1) << (l % 64);
      }
      rows.push_back(std::move(row));
    }
    return rows;
  };

  std::vector<int> alive = cluster;
  std::size_t rank = rank_mod2(boundaries(alive));
  std::vector<int> candidates = local_edges;
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](int a, int b) { return squared_length(a) > squared_length(b); });
  for(int e : candidates)
  {
    if(alive.empty())
      break;
    std::vector<int> without;
    for(int t : alive)
      if(!has_edge(triangles[t], e))
        without.push_back(t);
    if(without.size() == alive.size())
      continue; // in no remaining triangle
    const std::size_t r = rank_mod2(boundaries(without));
    if(rank - r != 1)
      continue;
    kept[e] = false;
    alive.swap(without);
    rank = r;
  }
  // Not expected: break what is left by its longest edges (may change the cycle count).
  for(int t : alive)
  {
    const auto& tri = triangles[t];
    if(kept[tri[0]] && kept[tri[1]] && kept[tri[2]])
      kept[*std::max_element(tri.begin(), tri.end(),
                             [&](int a, int b) { return squared_length(a) < squared_length(b); })] = false;
  }
}

// Removes the edges of a large cluster of triangles (a patch of sheet that thinning left,
// thousands of triangles, on which the exact reduction ran for more than ten minutes) by
// collapses: an edge
// in one remaining triangle only, the longest first, goes with its triangle, which keeps
// the cycle rank (the triangle's boundary is the only one holding that edge). When no such
// edge is left and triangles remain (a closed patch), the longest edge of those goes, which
// may change the cycle count. O(T log T) for T triangles.
template <typename SquaredLength>
void reduce_cluster_by_collapses(const std::vector<std::array<int, 3>>& triangles, const std::vector<int>& cluster,
                                 const std::vector<int>& local_edges, const std::vector<int>& local_of_edge,
                                 const SquaredLength& squared_length, std::vector<bool>& kept)
{
  auto local = [&](int e) { return std::size_t(local_of_edge[std::size_t(e)]); };
  // The triangles of each edge (positions in `cluster`), in compressed rows.
  std::vector<int> first_triangle(local_edges.size() + 1, 0), triangle_list(3 * cluster.size());
  for(int t : cluster)
    for(int e : triangles[t])
      ++first_triangle[local(e) + 1];
  for(std::size_t l = 0; l < local_edges.size(); ++l)
    first_triangle[l + 1] += first_triangle[l];
  std::vector<int> alive_triangles_of_edge(local_edges.size());
  for(std::size_t i = 0; i < cluster.size(); ++i)
    for(int e : triangles[cluster[i]])
      triangle_list[std::size_t(first_triangle[local(e)] + alive_triangles_of_edge[local(e)]++)] = int(i);
  std::vector<bool> alive(cluster.size(), true);

  // Longest first, then by id, so that the result does not depend on the heap's order.
  auto longer = [&](int a, int b) {
    const auto la = squared_length(local_edges[a]), lb = squared_length(local_edges[b]);
    return la != lb ? la < lb : a > b;
  };
  std::vector<int> free_edges;
  auto push_free = [&](int l) {
    free_edges.push_back(l);
    std::push_heap(free_edges.begin(), free_edges.end(), longer);
  };
  auto remove_edge = [&](int l) {
    kept[local_edges[l]] = false;
    for(int k = first_triangle[l]; k < first_triangle[l + 1]; ++k)
    {
      const int i = triangle_list[std::size_t(k)];
      if(!alive[i])
        continue;
      alive[i] = false;
      for(int e : triangles[cluster[i]])
      {
        const int f = int(local(e));
        if(--alive_triangles_of_edge[f] == 1 && kept[e])
          push_free(f);
      }
    }
  };
  for(std::size_t l = 0; l < local_edges.size(); ++l)
    if(alive_triangles_of_edge[l] == 1)
      push_free(int(l));
  std::vector<int> by_length(local_edges.size());
  std::iota(by_length.begin(), by_length.end(), 0);
  std::sort(by_length.begin(), by_length.end(), [&](int a, int b) { return longer(b, a); });
  std::size_t next_longest = 0;
  for(;;)
  {
    if(!free_edges.empty())
    {
      std::pop_heap(free_edges.begin(), free_edges.end(), longer);
      const int l = free_edges.back();
      free_edges.pop_back();
      if(kept[local_edges[l]] && alive_triangles_of_edge[l] == 1)
        remove_edge(l);
      continue;
    }
    while(next_longest < by_length.size() &&
          (!kept[local_edges[by_length[next_longest]]] || alive_triangles_of_edge[by_length[next_longest]] == 0))
      ++next_longest;
    if(next_longest == by_length.size())
      break;
    remove_edge(by_length[next_longest]);
  }
}

// The edges of the 26-adjacency graph of a voxel skeleton make little triangles (and
// tetrahedra) wherever three voxels are pairwise adjacent, at junctions and on diagonal
// steps. Viewed as the clique complex of the graph, which has the homotopy type of the
// union of the voxels' closed cubes (nerve theorem; boxes meeting pairwise meet all
// together), the skeleton's number of independent cycles is
//   b1 = (E - V + C) - rank(boundaries of the triangles).
// This removes edges, the longest first (corner before edge before face diagonals), each
// only when it kills exactly one dimension of triangle boundaries, until no triangle is
// left: the graph then has no triangle and its cycle rank is b1, the true number of
// tunnels. Triangles sharing no edge are independent, so the work is done per cluster of
// edge-sharing triangles, which are tiny at junctions; a cluster of more than
// `largest_exactly_reduced_cluster` triangles (a patch of sheet) is reduced by collapses.
//
// `keys[v]` is the voxel of node v, `edges` are pairs of node indices (first < second).
// Returns, per edge, whether it is kept.
inline std::vector<bool> remove_junction_triangles(const std::vector<Voxel_key>& keys,
                                                   const std::vector<std::pair<int, int>>& edges)
{
  // Up to this size the exact reduction costs about as much as the rest of to_graph().
  constexpr std::size_t largest_exactly_reduced_cluster = 64;
  const std::size_t n = keys.size();
  std::vector<bool> kept(edges.size(), true);
  std::vector<std::vector<std::pair<int, int>>> around(n); // (neighbour, edge)
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    around[edges[e].first].emplace_back(edges[e].second, int(e));
    around[edges[e].second].emplace_back(edges[e].first, int(e));
  }
  for(auto& a : around)
    std::sort(a.begin(), a.end());

  // Triangles a < b < c, as triples of edge ids.
  std::vector<std::array<int, 3>> triangles;
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    const int a = edges[e].first, b = edges[e].second;
    auto i = around[a].begin(), j = around[b].begin();
    while(i != around[a].end() && j != around[b].end())
    {
      if(i->first < j->first) ++i;
      else if(j->first < i->first) ++j;
      else
      {
        if(i->first > b)
          triangles.push_back({int(e), i->second, j->second});
        ++i;
        ++j;
      }
    }
  }
  if(triangles.empty())
    return kept;

  // Clusters of edge-sharing triangles (union-find over edges).
  std::vector<int> parent(edges.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) { return find_root(parent, x); };
  for(const auto& t : triangles)
  {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::vector<std::vector<int>> cluster_triangles(edges.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
    cluster_triangles[find(triangles[t][0])].push_back(int(t));

  auto squared_length = [&](int e) {
    const Voxel_key& p = keys[edges[e].first];
    const Voxel_key& q = keys[edges[e].second];
    return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z);
  };
  // Each cluster numbers its edges 0, 1, ... in increasing order (local_of_edge, -1 outside
  // the cluster at hand).
  std::vector<int> local_of_edge(edges.size(), -1);
  for(const std::vector<int>& cluster : cluster_triangles)
  {
    if(cluster.empty())
      continue;
    const std::vector<int> local_edges = edges_of_cluster(triangles, cluster);
    for(std::size_t l = 0; l < local_edges.size(); ++l)
      local_of_edge[std::size_t(local_edges[l])] = int(l);
    if(cluster.size() > largest_exactly_reduced_cluster)
      reduce_cluster_by_collapses(triangles, cluster, local_edges, local_of_edge, squared_length, kept);
    else
      reduce_cluster_exactly(triangles, cluster, local_edges, local_of_edge, squared_length, kept);
    for(int e : local_edges)
      local_of_edge[std::size_t(e)] = -1;
  }
  return kept;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_JUNCTION_TRIANGLES_H
