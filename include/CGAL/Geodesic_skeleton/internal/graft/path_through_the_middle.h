// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_GRAFT_PATH_THROUGH_THE_MIDDLE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_GRAFT_PATH_THROUGH_THE_MIDDLE_H

// The path search of graft_coarse_end_branches()
// (include/CGAL/Geodesic_skeleton/graft_coarse_end_branches.h): not part of the API.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The cheapest 26-connected path inside the solid of `distances` from `start` to the first
// voxel that `is_goal` accepts, where a step costs its length over the MAT radius of the
// voxel it enters: the path keeps to the middle of the solid, and its cost is a length in
// MAT radii, the same on any grid. Returns the voxels of the path, `start` included and the
// goal excluded; empty when `start` is a goal or no goal is reachable (then every voxel of
// start's piece was visited).
template <typename IsGoal>
std::vector<Voxel_key> path_through_the_middle(const Voxel_distance_field& distances, const Voxel_key& start,
                                               const IsGoal& is_goal)
{
  struct Visit
  {
    double cost;
    Voxel_key previous;
  };
  using Queued = std::pair<double, Voxel_key>;
  std::priority_queue<Queued, std::vector<Queued>, std::greater<Queued>> queue;
  std::unordered_map<Voxel_key, Visit, Voxel_key_hash> visits;
  visits.reserve(1 << 12);
  visits.emplace(start, Visit{0.0, start});
  queue.push({0.0, start});
  const std::array<double, 4> step_length{0.0, 1.0, std::sqrt(2.0), std::sqrt(3.0)};
  while(!queue.empty())
  {
    const auto [cost, k] = queue.top();
    queue.pop();
    if(cost > visits.find(k)->second.cost)
      continue; // reached more cheaply since it was queued
    if(is_goal(k))
    {
      std::vector<Voxel_key> path;
      if(k == start)
        return path;
      for(Voxel_key v = visits.find(k)->second.previous; v != start; v = visits.find(v)->second.previous)
        path.push_back(v);
      path.push_back(start);
      return path;
    }
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const Voxel_key next = k + offset;
      const std::uint32_t squared_distance = distances.squared_distance(next);
      if(squared_distance == 0)
        continue; // outside
      // The MAT radius in voxels, as mat_radius_in_voxels_map() gives it: at least 1/2.
      const double radius_in_voxels = std::sqrt(double(squared_distance)) - 0.5;
      const double reached = cost + step_length[offset_order(offset)] / radius_in_voxels;
      const auto [visit, first] = visits.try_emplace(next, Visit{reached, k});
      if(first || reached < visit->second.cost)
      {
        visit->second = Visit{reached, k};
        queue.push({reached, next});
      }
    }
  }
  return {};
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_GRAFT_PATH_THROUGH_THE_MIDDLE_H
