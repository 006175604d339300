// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_PATH_THROUGH_THE_MIDDLE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_PATH_THROUGH_THE_MIDDLE_H

// The path search of graft_coarse_end_branches() and route_lone_paths_through_the_middle():
// not part of the API.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The half width, in voxels, of the first window that the search is confined to; each
// window that cannot settle the search has twice the half width of the last.
constexpr int first_search_window_half_width = 16;

// What a search confined to a window found: the path (see path_through_the_middle()), and
// whether it is the answer of the unconfined search, i.e. the search ended before it took
// a voxel of the window's rim (one with a neighbour in the field's box outside the window):
// every path that leaves the window costs at least as much as that voxel.
struct Window_search
{
  std::vector<Voxel_key> path;
  bool settled = false;
};

// The MAT radius in voxels of a voxel inside the solid whose squared distance transform is
// `squared_distance`, as mat_radius_in_voxels_map() gives it: at least 1/2.
inline double mat_radius_in_voxels(std::uint32_t squared_distance)
{
  return std::sqrt(double(squared_distance)) - 0.5;
}

// The cost of a step of the search into voxel `next` inside the solid: its length over the
// MAT radius of `next` in voxels.
inline double step_cost_through_the_middle(const Voxel_distance_field& distances, const Voxel_key& from,
                                           const Voxel_key& next)
{
  return step_length(from, next) / mat_radius_in_voxels(distances.squared_distance(next));
}

// The cost of the 26-connected path `path` inside the solid, as the search counts it.
inline double cost_through_the_middle(const Voxel_distance_field& distances, const std::vector<Voxel_key>& path)
{
  double cost = 0;
  for(std::size_t i = 1; i < path.size(); ++i)
    cost += step_cost_through_the_middle(distances, path[i - 1], path[i]);
  return cost;
}

// What the search may know beyond its goal test: `estimate(k)`, a lower bound of the cost
// from `k` to a goal that never drops by more than a step's cost along a step (A*'s
// consistent estimate; 0 makes the search Dijkstra's), and `cost_limit`, the cost beyond
// which no path is wanted.
template <typename Estimate>
struct Search_bounds
{
  Estimate estimate;
  double cost_limit;
};

// Bounds that know nothing: Dijkstra's search, at any cost.
inline auto no_search_bounds()
{
  auto zero = [](const Voxel_key&) { return 0.0; };
  return Search_bounds<decltype(zero)>{zero, std::numeric_limits<double>::infinity()};
}

// The search of path_through_the_middle() over the voxels of `window` only, with its
// costs and the step each voxel was reached by in arrays over the window. Voxels are taken
// in order of their cost plus their estimate; the search gives up, settled, when that
// passes the cost limit.
template <typename IsGoal, typename Estimate>
Window_search search_in_window(const Voxel_distance_field& distances, const Voxel_key& start, const IsGoal& is_goal,
                               const Search_bounds<Estimate>& bounds, const Voxel_box& window)
{
  const std::array<std::size_t, 3> extent = window.extent();
  auto index = [&](const Voxel_key& k) {
    return (std::size_t(k.z - window.min.z) * extent[1] + std::size_t(k.y - window.min.y)) * extent[0] +
           std::size_t(k.x - window.min.x);
  };
  const Voxel_box field = distances.box();
  auto on_rim = [&](const Voxel_key& k) {
    return (k.x == window.min.x && k.x > field.min.x) || (k.x + 1 == window.max.x && k.x + 1 < field.max.x) ||
           (k.y == window.min.y && k.y > field.min.y) || (k.y + 1 == window.max.y && k.y + 1 < field.max.y) ||
           (k.z == window.min.z && k.z > field.min.z) || (k.z + 1 == window.max.z && k.z + 1 < field.max.z);
  };
  constexpr std::uint8_t unreached = 26;
  const auto& offsets = neighbourhood_26();
  std::vector<double> cost(window.volume(), std::numeric_limits<double>::infinity());
  std::vector<std::uint8_t> step_in(window.volume(), unreached); // offset that reached the voxel
  using Queued = std::pair<double, Voxel_key>;
  std::priority_queue<Queued, std::vector<Queued>, std::greater<Queued>> queue;
  cost[index(start)] = 0.0;
  queue.push({bounds.estimate(start), start});
  Window_search found;
  found.settled = true;
  while(!queue.empty())
  {
    const auto [bound, k] = queue.top();
    queue.pop();
    if(bound > bounds.cost_limit)
      return found; // every path left costs more
    const double reached = cost[index(k)];
    if(bound > reached + bounds.estimate(k))
      continue; // reached more cheaply since it was queued
    if(is_goal(k))
    {
      for(Voxel_key v = k; step_in[index(v)] != unreached;)
      {
        const Voxel_key& offset = offsets[step_in[index(v)]];
        v = Voxel_key{v.x - offset.x, v.y - offset.y, v.z - offset.z};
        found.path.push_back(v);
      }
      return found;
    }
    if(on_rim(k))
      found.settled = false;
    for(std::uint8_t o = 0; o < offsets.size(); ++o)
    {
      const Voxel_key next = k + offsets[o];
      if(!window.contains(next) || !distances.inside(next))
        continue;
      const double through_k = reached + step_cost_through_the_middle(distances, k, next);
      const std::size_t i = index(next);
      if(through_k < cost[i])
      {
        cost[i] = through_k;
        step_in[i] = o;
        queue.push({through_k + bounds.estimate(next), next});
      }
    }
  }
  return found;
}

// The cheapest 26-connected path inside the solid of `distances` from `start` to the first
// voxel that `is_goal` accepts, where a step costs its length over the MAT radius of the
// voxel it enters: the path keeps to the middle of the solid, and its cost is a length in
// MAT radii, the same on any grid. Returns the voxels of the path, `start` included and the
// goal excluded, from the goal's side; empty when `start` is a goal, when no goal is
// reachable, or when every path to a goal costs more than `bounds.cost_limit`. The search
// runs in a window around `start`, twice as wide each time it cannot settle there, up to
// the field's box: it reads the voxels whose cost plus estimate is below the goal's (and the
// limit), and arrays as large as its last window.
template <typename IsGoal, typename Estimate>
std::vector<Voxel_key> path_through_the_middle(const Voxel_distance_field& distances, const Voxel_key& start,
                                               const IsGoal& is_goal, const Search_bounds<Estimate>& bounds)
{
  const Voxel_box field = distances.box();
  if(!distances.inside(start))
    return {};
  for(int half_width = first_search_window_half_width;; half_width *= 2)
  {
    const Voxel_box window{
        Voxel_key{(std::max)(field.min.x, start.x - half_width), (std::max)(field.min.y, start.y - half_width),
                  (std::max)(field.min.z, start.z - half_width)},
        Voxel_key{(std::min)(field.max.x, start.x + half_width + 1), (std::min)(field.max.y, start.y + half_width + 1),
                  (std::min)(field.max.z, start.z + half_width + 1)}};
    Window_search search = search_in_window(distances, start, is_goal, bounds, window);
    if(search.settled)
      return std::move(search.path);
  }
}

template <typename IsGoal>
std::vector<Voxel_key> path_through_the_middle(const Voxel_distance_field& distances, const Voxel_key& start,
                                               const IsGoal& is_goal)
{
  return path_through_the_middle(distances, start, is_goal, no_search_bounds());
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_PATH_THROUGH_THE_MIDDLE_H
