// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_ROUTE_LONE_PATHS_THROUGH_THE_MIDDLE_H
#define CGAL_GEODESIC_SKELETON_ROUTE_LONE_PATHS_THROUGH_THE_MIDDLE_H

/// \file route_lone_paths_through_the_middle.h
/// Routes the pieces of a pruned skeleton that are a lone path (two ends, no junction)
/// through the middle of the solid between their ends, where thinning left a detour.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/path_through_the_middle.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

namespace internal {

// The pieces of `skeleton`'s graph (the one to_graph() makes) that are a lone path: each as
// its voxels from one end to the other, starting at the end of lower key.
template <typename VoxelSet>
std::vector<std::vector<Voxel_key>> lone_paths(const VoxelSet& skeleton)
{
  const Skeleton_adjacency graph = skeleton_adjacency(skeleton);
  const std::vector<std::vector<int>> around = neighbours_of_nodes(graph);
  std::vector<std::vector<Voxel_key>> paths;
  std::vector<bool> walked(graph.nodes.size(), false);
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
  {
    if(around[v].size() != 1 || walked[v])
      continue;
    const Walk_from_end walk = walk_from_end(around, int(v));
    if(around[std::size_t(walk.stop)].size() != 1)
      continue; // an end branch
    walked[std::size_t(walk.stop)] = true;
    std::vector<Voxel_key>& path = paths.emplace_back();
    for(int n : walk.nodes)
      path.push_back(graph.nodes[std::size_t(n)]);
    path.push_back(graph.nodes[std::size_t(walk.stop)]);
  }
  return paths;
}

// The voxels of the straight segment from the centre of `a` to that of `b`, a 26-connected
// path: one per step along the axis of their largest difference, rounded to the nearest voxel.
inline std::vector<Voxel_key> straight_voxel_path(const Voxel_key& a, const Voxel_key& b)
{
  const int steps = (std::max)({std::abs(b.x - a.x), std::abs(b.y - a.y), std::abs(b.z - a.z)});
  std::vector<Voxel_key> path;
  path.reserve(std::size_t(steps) + 1);
  auto at = [&](int from, int to, int i) {
    return from + int(std::lround(double(to - from) * double(i) / double((std::max)(steps, 1))));
  };
  for(int i = 0; i <= steps; ++i)
    path.push_back(Voxel_key{at(a.x, b.x, i), at(a.y, b.y, i), at(a.z, b.z, i)});
  return path;
}

// Whether the voxels `path` make a lone path of the graph on their own (two ends, every
// other voxel of degree 2) and none of them touches a voxel of `skeleton` outside `path`
// and `replaced`: inserted in place of `replaced`, they neither branch nor join another piece.
template <typename VoxelSet>
bool fits_as_lone_path(const VoxelSet& skeleton, const std::vector<Voxel_key>& replaced,
                       const std::vector<Voxel_key>& path)
{
  const std::unordered_set<Voxel_key, Voxel_key_hash> in_path(path.begin(), path.end());
  const std::unordered_set<Voxel_key, Voxel_key_hash> in_replaced(replaced.begin(), replaced.end());
  for(const Voxel_key& k : path)
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const Voxel_key next = k + offset;
      if(skeleton.contains(next) && in_path.count(next) == 0 && in_replaced.count(next) == 0)
        return false;
    }
  std::vector<Voxel_key> nodes = path;
  std::sort(nodes.begin(), nodes.end());
  const Skeleton_adjacency graph = skeleton_adjacency(nodes, [&](const Voxel_key& k) {
    const auto at = std::lower_bound(nodes.begin(), nodes.end(), k);
    return at != nodes.end() && *at == k ? std::int32_t(at - nodes.begin()) : std::int32_t(-1);
  });
  const std::vector<std::vector<int>> around = neighbours_of_nodes(graph);
  const auto ends = std::count_if(around.begin(), around.end(), [](const std::vector<int>& a) { return a.size() == 1; });
  const bool all_on_path = std::all_of(around.begin(), around.end(),
                                       [](const std::vector<int>& a) { return a.size() == 1 || a.size() == 2; });
  return ends == 2 && all_on_path && graph.edges.size() + 1 == nodes.size();
}

} // namespace internal

namespace internal {

// route_lone_paths_through_the_middle() once its parameter is read: compiled once per voxel
// set type, whatever the parameter pack.
template <typename VoxelSet>
std::size_t route_lone_paths_with(VoxelSet& skeleton, const Voxel_distance_field& distances, double detour_factor)
{
  if(detour_factor == 0)
    return 0;
  const double largest_radius = internal::mat_radius_in_voxels(distances.max_squared_distance());
  std::size_t routed = 0;
  for(const std::vector<Voxel_key>& path : internal::lone_paths(skeleton))
  {
    const Voxel_key& goal = path.back();
    const double cost = internal::cost_through_the_middle(distances, path);
    const std::vector<Voxel_key> straight = internal::straight_voxel_path(path.front(), goal);
    if(!std::all_of(straight.begin(), straight.end(), [&](const Voxel_key& k) { return distances.inside(k); }))
      continue;
    const double straight_cost = internal::cost_through_the_middle(distances, straight);
    if(!(detour_factor * straight_cost < cost))
      continue; // no detour
    // No step costs less than its length over the largest radius: the straight distance
    // over it bounds the cost to the goal from below, consistently along each step. The
    // straight segment is a path within the limit (rounding aside).
    auto estimate = [&](const Voxel_key& k) {
      return std::sqrt(double(internal::squared_distance_between(k, goal))) / largest_radius;
    };
    const internal::Search_bounds<decltype(estimate)> bounds{estimate, straight_cost * (1 + 1e-9)};
    std::vector<Voxel_key> middle = internal::path_through_the_middle(
        distances, path.front(), [&](const Voxel_key& k) { return k == goal; }, bounds);
    if(middle.empty())
      continue;
    std::reverse(middle.begin(), middle.end());
    middle.push_back(goal);
    if(!internal::fits_as_lone_path(skeleton, path, middle))
      continue;
    for(const Voxel_key& k : path)
      skeleton.erase(k);
    for(const Voxel_key& k : middle)
      skeleton.insert(k);
    ++routed;
  }
  return routed;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Routes each piece of a pruned skeleton that is a lone path (two end points and no
/// junction in the graph that `to_graph()` makes) through the middle of the solid between
/// its two end points, when it makes a detour: when it costs more than
/// `lone_path_detour_factor` times the straight segment between its ends, which runs inside
/// the solid.
///
/// In a thick, flat part (a dome, a lens, a slab) the medial surface is a sheet and no
/// curve on it is more central than another: thinning leaves an arbitrary one, which on
/// one grid runs straight and on another makes a U across the sheet, a detour that the
/// split into bones then cuts into more bones. Pruning keeps where the path ends, not
/// where it runs. A path is measured by the cost of its steps, each its length over the MAT
/// radius of the voxel it enters: a length in MAT radii, the same on any grid. The straight
/// segment is the 26-connected voxel path nearest the segment between the centres of the
/// two end voxels; along a limb it costs about as much as the path, or leaves the solid, and
/// the path stays. A detour is replaced by the path through the middle, the cheapest
/// 26-connected path inside the solid between the two ends (it costs no more than the
/// straight segment), when that is itself a lone path that touches no other piece of the
/// skeleton; the end points stay. A piece with a junction or a cycle is not changed.
///
/// `extract_control_skeleton()` calls it after `prune_skeleton()` and
/// `graft_coarse_end_branches()`, on every grid.
///
/// \tparam VoxelSet a model of `VoxelSet`, e.g. `Sparse_voxel_set`; read through
///         `for_each()` and `contains()`, changed with `insert()` and `erase()`.
/// \param skeleton a pruned one-voxel-thick skeleton inside the solid of `distances`;
///        its lone paths are replaced in place.
/// \param distances the distance transform of the solid (`distance_transform()`): which
///        voxels are inside, and their MAT radii.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters" among
///        the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{lone_path_detour_factor}
///     \cgalParamDescription{how many times as much as the straight segment between its
///                           ends a lone path must cost to be a detour, in [0, 1000]; 0 turns
///                           the routing off (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of lone paths replaced.
/// \pre `skeleton` and `distances` share a frame, and every voxel of `skeleton` is inside
///      the solid.
/// \throws std::invalid_argument when `lone_path_detour_factor` is out of range.
///
/// \b Complexity: O(N log N) for N skeleton voxels to find the lone paths and compare
/// each with its straight segment; then, for each detour, an A* search from one end to the
/// other (estimate: the straight distance over the largest MAT radius of the solid) that
/// gives up beyond the cost of the straight segment: it visits the V solid voxels within
/// that cost, O(V log V), and clears arrays over a box around the end, 33 voxels wide and
/// twice as wide each time the search reaches its side (at most the box of `distances`),
/// 9 bytes per voxel. A path that is no detour costs no search.
template <typename VoxelSet, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t route_lone_paths_through_the_middle(VoxelSet& skeleton, const Voxel_distance_field& distances,
                                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double detour_factor = internal::checked_parameter(
      parameter_ranges::lone_path_detour_factor,
      choose_parameter(get_parameter(np, internal_np::lone_path_detour_factor_tag),
                       parameter_ranges::lone_path_detour_factor.default_value),
      "route_lone_paths_through_the_middle");
  return internal::route_lone_paths_with(skeleton, distances, detour_factor);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_ROUTE_LONE_PATHS_THROUGH_THE_MIDDLE_H
