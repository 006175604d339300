// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_BRANCH_SWAPS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_BRANCH_SWAPS_H

// An end branch that the snipping took, and that a coarser skeleton ends in, swapped back
// in for an end branch at the same junction that the coarser skeleton does not have.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/prune/coarse_end_points.h>
#include <CGAL/Geodesic_skeleton/internal/prune/spurious_branches.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The most squared voxel steps between the junction of a branch swapped back in and that
// of the branch it replaces: two steps along each axis, the size of the small clusters of
// branched points that thinning leaves where branches meet.
constexpr std::int64_t same_junction_squared_steps = 12;

// Whether `k` has a 26-neighbour in `skeleton` that is not in `sorted_others`.
template <typename VoxelSet>
bool touches_the_rest(const VoxelSet& skeleton, const Voxel_key& k, const std::vector<Voxel_key>& sorted_others)
{
  for(const Voxel_key& offset : neighbourhood_26())
  {
    const Voxel_key n = k + offset;
    if(skeleton.contains(n) && !std::binary_search(sorted_others.begin(), sorted_others.end(), n))
      return true;
  }
  return false;
}

// Puts back one branch of `snipped` (the latest first; each tried once, `tried`) whose tip
// is near one of `unmatched_coarse` and whose voxels are all gone, with its junction voxel
// if later rounds took that too (the branched points that no path needed once the branch
// had gone), where the junction still touches the skeleton; and snips in its place the
// shortest end branch of the graph (ties: its tip first in voxel order) that is
// `unmatched` and leaves, among three or more, a junction within
// same_junction_squared_steps of the branch put back. Takes the branch out again when
// there is none, or when the swap would leave more than `end_points` end points in the
// graph. Returns whether a swap was made.
template <typename VoxelSet, typename Unmatched>
bool swap_one_end_branch(VoxelSet& skeleton, std::size_t end_points,
                         const std::vector<std::array<double, 3>>& unmatched_coarse, double squared_tolerance,
                         const std::vector<End_branch>& snipped, std::vector<bool>& tried, const Unmatched& unmatched)
{
  for(std::size_t b = snipped.size(); b-- > 0;)
  {
    const End_branch& back = snipped[b];
    if(tried[b] || !is_near_any(unmatched_coarse, back.voxels.front(), squared_tolerance) ||
       std::any_of(back.voxels.begin(), back.voxels.end(), [&](const Voxel_key& k) { return skeleton.contains(k); }))
      continue;
    tried[b] = true;
    std::vector<Voxel_key> put_back = back.voxels;
    if(!skeleton.contains(back.junction))
      put_back.push_back(back.junction);
    std::sort(put_back.begin(), put_back.end());
    if(!touches_the_rest(skeleton, back.junction, put_back))
      continue;
    for(const Voxel_key& k : put_back)
      skeleton.insert(k);
    Graph_end_branches graph = graph_end_branches(skeleton);
    const End_branch* out = nullptr;
    for(const End_branch& branch : graph.branches)
    {
      if(!unmatched(branch.voxels.front()) || graph.junction_degree[branch.junction] < 3 ||
         squared_distance_between(branch.junction, back.junction) > same_junction_squared_steps)
        continue;
      if(out == nullptr ||
         std::make_tuple(branch.voxels.size(), branch.voxels.front()) < std::make_tuple(out->voxels.size(), out->voxels.front()))
        out = &branch;
    }
    if(out == nullptr)
    {
      for(const Voxel_key& k : put_back)
        skeleton.erase(k);
      continue;
    }
    const std::vector<Voxel_key> taken = out->voxels;
    for(const Voxel_key& k : taken)
      skeleton.erase(k);
    // A swap trades one end point for another: where the junction's voxels would leave
    // one more (a voxel of it left hanging), it is undone.
    if(graph_end_points(skeleton).size() <= end_points)
      return true;
    for(const Voxel_key& k : taken)
      skeleton.insert(k);
    for(const Voxel_key& k : put_back)
      skeleton.erase(k);
  }
  return false;
}

// While the skeleton's graph has an end point that no coarse end point is near (within
// `tolerance`) and the coarser skeleton an end point that no end point is near, swaps back
// in a snipped branch that ends near the latter for one that ends at the former at the
// same junction (swap_one_end_branch()). Returns the number of swaps.
template <typename VoxelSet>
std::size_t swap_in_coarse_end_branches(VoxelSet& skeleton, const std::vector<std::array<double, 3>>& coarse,
                                        double tolerance, const std::vector<End_branch>& snipped)
{
  const double squared_tolerance = tolerance * tolerance;
  auto unmatched = [&](const Voxel_key& end) { return !is_near_any(coarse, end, squared_tolerance); };
  std::vector<bool> tried(snipped.size(), false);
  std::size_t swaps = 0;
  while(true)
  {
    const std::vector<Voxel_key> ends = graph_end_points(skeleton);
    std::vector<std::array<double, 3>> unmatched_coarse;
    for(const std::array<double, 3>& p : coarse)
      if(!has_end_near(ends, p, squared_tolerance))
        unmatched_coarse.push_back(p);
    if(unmatched_coarse.empty() || std::none_of(ends.begin(), ends.end(), unmatched) ||
       !swap_one_end_branch(skeleton, ends.size(), unmatched_coarse, squared_tolerance, snipped, tried, unmatched))
      return swaps;
    ++swaps;
  }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_BRANCH_SWAPS_H
