// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_BRANCHED_REGIONS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_BRANCHED_REGIONS_H

// Steps (3) to (8) of the paper's Algorithm 1.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

using Voxel_key_set = std::unordered_set<Voxel_key, Voxel_key_hash>;

// Length of a step to a 26-neighbour: 1, sqrt 2 or sqrt 3 (voxels).
inline double step_length(const Voxel_key& a, const Voxel_key& b)
{
  static const double length[4] = {0.0, 1.0, std::sqrt(2.0), std::sqrt(3.0)};
  return length[(a.x != b.x) + (a.y != b.y) + (a.z != b.z)];
}

// The 26-connected components of `points`, each sorted by key (deterministic).
inline std::vector<std::vector<Voxel_key>> components_26(const std::vector<Voxel_key>& points)
{
  Voxel_key_set unvisited(points.begin(), points.end());
  std::vector<Voxel_key> sorted = points;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::vector<Voxel_key>> components;
  for(const Voxel_key& seed : sorted)
  {
    if(unvisited.erase(seed) == 0)
      continue;
    std::vector<Voxel_key> component{seed};
    for(std::size_t i = 0; i < component.size(); ++i)
      for(const Voxel_key& offset : neighbourhood_26())
      {
        const Voxel_key n = component[i] + offset;
        if(unvisited.erase(n) != 0)
          component.push_back(n);
      }
    std::sort(component.begin(), component.end());
    components.push_back(std::move(component));
  }
  return components;
}

// Step (5): the region voxel nearest the mean of the region, ties broken by the largest
// radius, then by the smallest key (the region is sorted).
template <typename Radius>
Voxel_key region_centroid(const std::vector<Voxel_key>& region, const Radius& radius)
{
  double mean[3] = {0, 0, 0};
  for(const Voxel_key& k : region)
  {
    mean[0] += k.x;
    mean[1] += k.y;
    mean[2] += k.z;
  }
  for(double& c : mean)
    c /= static_cast<double>(region.size());
  Voxel_key best = region.front();
  double best_distance = std::numeric_limits<double>::infinity(), best_radius = -1;
  for(const Voxel_key& k : region)
  {
    const double d = std::pow(k.x - mean[0], 2) + std::pow(k.y - mean[1], 2) + std::pow(k.z - mean[2], 2);
    const double r = radius(k);
    // Voxel coordinates are integers and the mean a ratio: compare with a small tolerance.
    if(d < best_distance - 1e-9 || (d <= best_distance + 1e-9 && r > best_radius))
    {
      best = k;
      best_distance = d;
      best_radius = r;
    }
  }
  return best;
}

// Steps (6) and (7): Dijkstra from the centroid through the region; returns the region
// voxels that lie on a shortest path to some terminator. Terminators end paths; they are
// never passed through. Ties are settled in key order, so the paths are deterministic.
inline Voxel_key_set voxels_on_shortest_paths(const std::vector<Voxel_key>& region,
                                              const Voxel_key_set& terminators,
                                              const Voxel_key& centroid)
{
  const Voxel_key_set in_region(region.begin(), region.end());
  std::unordered_map<Voxel_key, double, Voxel_key_hash> distance;
  std::unordered_map<Voxel_key, Voxel_key, Voxel_key_hash> predecessor;
  using Entry = std::tuple<double, int, int, int>; // distance, then z, y, x as tie-break
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  distance[centroid] = 0;
  queue.emplace(0.0, centroid.z, centroid.y, centroid.x);
  while(!queue.empty())
  {
    const auto [d, z, y, x] = queue.top();
    queue.pop();
    const Voxel_key k{x, y, z};
    if(d > distance.at(k) || terminators.count(k) != 0)
      continue;
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const Voxel_key n = k + offset;
      if(in_region.count(n) == 0 && terminators.count(n) == 0)
        continue;
      const double nd = d + step_length(k, n);
      auto it = distance.find(n);
      if(it == distance.end() || nd < it->second - 1e-12)
      {
        distance[n] = nd;
        predecessor[n] = k;
        queue.emplace(nd, n.z, n.y, n.x);
      }
    }
  }

  Voxel_key_set on_path{centroid};
  for(const Voxel_key& t : terminators)
  {
    if(predecessor.count(t) == 0)
      continue; // cannot happen: every terminator touches the connected region
    for(Voxel_key k = predecessor.at(t); on_path.insert(k).second; k = predecessor.at(k))
    {
    }
  }
  return on_path;
}

struct Branched_region_pruning
{
  std::size_t regions = 0, removed_points = 0;
};

// Steps (1) to (8) of Algorithm 1 on `skeleton`, in place.
template <typename VoxelSet, typename Radius>
Branched_region_pruning prune_branched_regions(VoxelSet& skeleton, const Radius& radius)
{
  std::unordered_map<Voxel_key, Skeleton_point_class, Voxel_key_hash> classes;
  classify_skeleton_points(skeleton, boost::make_assoc_property_map(classes));
  std::vector<Voxel_key> branched;
  for(const auto& [k, c] : classes)
    if(c == Skeleton_point_class::branched_connection)
      branched.push_back(k);

  Branched_region_pruning result;
  std::vector<Voxel_key> to_remove;
  for(const std::vector<Voxel_key>& region : components_26(branched))
  {
    ++result.regions;
    const Voxel_key_set in_region(region.begin(), region.end());
    Voxel_key_set terminators;
    for(const Voxel_key& k : region)
      for(const Voxel_key& offset : neighbourhood_26())
      {
        const Voxel_key n = k + offset;
        if(skeleton.contains(n) && in_region.count(n) == 0)
          terminators.insert(n);
      }
    const Voxel_key_set kept =
        voxels_on_shortest_paths(region, terminators, region_centroid(region, radius));
    for(const Voxel_key& k : region)
      if(kept.count(k) == 0)
        to_remove.push_back(k);
  }
  for(const Voxel_key& k : to_remove)
    skeleton.erase(k);
  result.removed_points = to_remove.size();
  return result;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_BRANCHED_REGIONS_H
