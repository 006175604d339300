// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_BRANCHED_REGIONS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_BRANCHED_REGIONS_H

// Steps (3) to (8) of the paper's Algorithm 1.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths_no_color_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

using Voxel_key_set = std::unordered_set<Voxel_key, Voxel_key_hash>;

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

// Steps (6) and (7): Dijkstra from the centroid through the region (Boost.Graph's, on a
// graph of the region voxels and the terminators with edges out of the region voxels only,
// so that terminators end paths and are never passed through); returns the region voxels
// that lie on a shortest path to some terminator. The paths are deterministic: after the
// search each voxel v takes as predecessor, among its neighbours u that reach it on a
// shortest path (dist(u) + step(u, v) <= dist(v) + 1e-12), the one with the smallest
// (dist(u), z, y, x).
inline Voxel_key_set voxels_on_shortest_paths(const std::vector<Voxel_key>& region,
                                              const Voxel_key_set& terminators,
                                              const Voxel_key& centroid)
{
  // The voxels numbered 0, 1, ...: the region's, then the terminators' in key order.
  std::vector<Voxel_key> voxels = region;
  voxels.insert(voxels.end(), terminators.begin(), terminators.end());
  std::sort(voxels.begin() + std::ptrdiff_t(region.size()), voxels.end());
  std::unordered_map<Voxel_key, std::size_t, Voxel_key_hash> index_of;
  for(std::size_t i = 0; i < voxels.size(); ++i)
    index_of.emplace(voxels[i], i);

  struct Step
  {
    double length; // voxels
  };
  std::vector<std::pair<std::size_t, std::size_t>> steps;
  std::vector<Step> lengths;
  for(std::size_t i = 0; i < region.size(); ++i)
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const auto to = index_of.find(voxels[i] + offset);
      if(to == index_of.end())
        continue;
      steps.emplace_back(i, to->second);
      lengths.push_back(Step{step_length(voxels[i], to->first)});
    }
  // An adjacency list, not a compressed_sparse_row_graph: the latter's boost::detail::get
  // hides the property map get() that boost/pending/disjoint_sets.hpp needs when it is
  // included after it.
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS, boost::no_property, Step>;
  const Graph graph(steps.begin(), steps.end(), lengths.begin(), voxels.size());
  std::vector<double> distance(voxels.size());
  boost::dijkstra_shortest_paths_no_color_map(
      graph, index_of.at(centroid),
      boost::distance_map(distance.data()).weight_map(get(&Step::length, graph)));

  const double unreached = std::numeric_limits<double>::max(); // Boost's default "infinity"
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> predecessor(voxels.size(), none);
  auto tie_key = [&](std::size_t u) {
    return std::make_tuple(distance[u], voxels[u].z, voxels[u].y, voxels[u].x);
  };
  for(std::size_t e = 0; e < steps.size(); ++e)
  {
    const auto [u, v] = steps[e];
    if(distance[u] < unreached && distance[u] + lengths[e].length <= distance[v] + 1e-12 &&
       (predecessor[v] == none || tie_key(u) < tie_key(predecessor[v])))
      predecessor[v] = u;
  }

  Voxel_key_set on_path{centroid};
  for(std::size_t t = region.size(); t < voxels.size(); ++t)
  {
    if(predecessor[t] == none)
      continue; // cannot happen: every terminator touches the connected region
    for(std::size_t k = predecessor[t]; on_path.insert(voxels[k]).second; k = predecessor[k])
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
  for(const std::vector<Voxel_key>& region : voxel_components(branched))
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
