// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_POINTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_POINTS_H

// The end points of the same shape's skeleton on a coarser grid, which tell the snipping
// which end branches a finer grid resolves that the coarser one does not.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Throws std::invalid_argument, naming `caller`, when a coarse end point is not finite.
inline void check_coarse_end_points_are_finite(const std::vector<std::array<double, 3>>& points, const char* caller)
{
  for(const std::array<double, 3>& p : points)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw std::invalid_argument(std::string(caller) + ": a coarse end point has a non-finite coordinate");
}

// The voxels of `skeleton` that are end points of its graph, the one to_graph() makes
// (26-adjacency without junction triangles): the end points the control skeleton gets.
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

// The centre of voxel `k`, in grid coordinates.
inline Vec3 centre_in_grid(const Voxel_key& k)
{
  return Vec3{k.x + 0.5, k.y + 0.5, k.z + 0.5};
}

// Whether the coarse end point `p` is within `squared_tolerance` of the centre of `k`.
inline bool is_near(const std::array<double, 3>& p, const Voxel_key& k, double squared_tolerance)
{
  return squared_distance3(p, centre_in_grid(k)) <= squared_tolerance;
}

// Whether one of the coarse end points `points` is within `squared_tolerance` of the centre
// of `k`.
inline bool is_near_any(const std::vector<std::array<double, 3>>& points, const Voxel_key& k,
                        double squared_tolerance)
{
  return std::any_of(points.begin(), points.end(),
                     [&](const std::array<double, 3>& p) { return is_near(p, k, squared_tolerance); });
}

// Whether one of the voxels `ends` (the end points of a skeleton's graph) has its centre
// within `squared_tolerance` of the coarse end point `p`: the skeleton has p's branch.
inline bool has_end_near(const std::vector<Voxel_key>& ends, const std::array<double, 3>& p,
                         double squared_tolerance)
{
  return std::any_of(ends.begin(), ends.end(), [&](const Voxel_key& e) { return is_near(p, e, squared_tolerance); });
}

// How much larger the snipping's thresholds are for an end branch that the coarser
// skeleton does not have: 3 times the default level of detail (0.75 of the body's thickness)
// is more than 2 thicknesses, more than the corner branches of a block reach out, and less
// than a limb, which reaches out several thicknesses; such a branch is snipped only while
// the finer skeleton has more end points than the coarser.
constexpr double unmatched_threshold_factor = 3.;

// What the snipping reads of a coarser skeleton: its end points, in the grid coordinates
// of the skeleton being pruned, and how near one must be to a branch's tip for the coarse
// grid to have the branch too. An end branch whose tip is not paired with one
// (match_tips(), run on the tips of each round) is judged with thresholds
// `unmatched_factor` times larger, as long as the pruned skeleton has more end points than
// the coarse one (`budget`, spent by each branch snipped that only the larger thresholds
// call a spur).
struct Coarse_end_point_guide
{
  std::vector<std::array<double, 3>> points;
  double tolerance = 0;
  double unmatched_factor = 1;
  std::size_t budget = 0;
  // The tips that match_tips() paired with a coarse end point, sorted.
  std::vector<Voxel_key> matched_tips;

  // Pairs the end branches' `tips` with the coarse end points one to one, nearest pairs
  // first (within the tolerance; ties by coarse point, then by tip): a coarse end point
  // vouches for one end branch only, so that of two teeth of a comb that end near the
  // coarse skeleton's one end, the farther is judged as detail the coarser grid does not
  // have.
  void match_tips(const std::vector<Voxel_key>& tips)
  {
    const double squared_tolerance = tolerance * tolerance;
    std::vector<std::tuple<double, std::size_t, Voxel_key, std::size_t>> pairs; // distance, coarse, tip, tip index
    for(std::size_t c = 0; c < points.size(); ++c)
      for(std::size_t t = 0; t < tips.size(); ++t)
      {
        const double d = squared_distance3(points[c], centre_in_grid(tips[t]));
        if(d <= squared_tolerance)
          pairs.emplace_back(d, c, tips[t], t);
      }
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> coarse_taken(points.size(), false), tip_taken(tips.size(), false);
    matched_tips.clear();
    for(const auto& [d, c, tip, t] : pairs)
      if(!coarse_taken[c] && !tip_taken[t])
      {
        coarse_taken[c] = tip_taken[t] = true;
        matched_tips.push_back(tip);
      }
    std::sort(matched_tips.begin(), matched_tips.end());
  }

  bool has_match(const Voxel_key& tip) const
  {
    return std::binary_search(matched_tips.begin(), matched_tips.end(), tip);
  }

  // The factor of the snipping's thresholds for the end branch whose tip is `tip`.
  double threshold_factor(const Voxel_key& tip) const
  {
    return budget > 0 && !has_match(tip) ? unmatched_factor : 1.;
  }

  // Records the snipping of an end branch that only the larger thresholds call a spur.
  void snipped()
  {
    if(budget > 0)
      --budget;
  }
};

// What cutting back to the coarse end points removed.
struct Cut_back
{
  std::size_t branches = 0; // end branches cut back
  std::size_t points = 0;   // voxels removed
};

// The index in `branch` (voxel centres `centre(branch[i])`) of the voxel nearest `point`
// among all but the last one, if one is within its squared tolerance
// `squared_tolerance(branch[i])`; ties to rounding (clearly_greater()) go to the first,
// nearest the tip. The coarse end points are converted from the coarser grid's frame, and a
// coarse voxel centre falls on the face between two voxels of a grid twice as fine: the two
// are equally near it, and the rounding of a moved mesh would pick either.
// `branch.size()` when none is.
template <typename Centre, typename SquaredTolerance>
std::size_t nearest_branch_voxel(const std::vector<int>& branch, const Vec3& point,
                                 const SquaredTolerance& squared_tolerance, const Centre& centre)
{
  std::size_t nearest = branch.size();
  double nearest_distance = 0;
  for(std::size_t i = 0; i + 1 < branch.size(); ++i)
  {
    const double d = squared_distance3(point, centre(branch[i]));
    if(d <= squared_tolerance(branch[i]) && (nearest == branch.size() || clearly_greater(nearest_distance, d)))
    {
      nearest = i;
      nearest_distance = d;
    }
  }
  return nearest;
}

// The middle voxels of the paths of `skeleton`'s graph (its components without junction):
// one for a path of an odd number of voxels, the two around its middle for an even one,
// sorted. Cutting back never takes an end of a path past its middle as it was before any
// cut (end_branch_to_cut()): the other half is the other end's. When the coarser skeleton
// has both its ends near one end of a path (a U whose ends lie close, which the finer grid
// thinned straight), the far end would be cut back to the one nearer the other, the near
// end to its own, and a few voxels of the path would be left.
template <typename VoxelSet>
std::vector<Voxel_key> path_middles(const VoxelSet& skeleton)
{
  const Skeleton_adjacency graph = skeleton_adjacency(skeleton);
  const std::vector<std::vector<int>> around = neighbours_of_nodes(graph);
  std::vector<Voxel_key> middles;
  for(int v = 0; v < int(graph.nodes.size()); ++v)
    if(around[std::size_t(v)].size() == 1)
    {
      const Walk_from_end walk = walk_from_end(around, v);
      if(around[std::size_t(walk.stop)].size() == 1) // a path of walk.nodes.size() + 1 voxels
        middles.push_back(graph.nodes[std::size_t(walk.nodes[walk.nodes.size() / 2])]);
    }
  std::sort(middles.begin(), middles.end());
  middles.erase(std::unique(middles.begin(), middles.end()), middles.end());
  return middles;
}

// The voxels of the end branch from `end` that cutting back may remove, the tip first, and
// the voxel after them, which stays: the branch up to its junction (walk_from_end()), on a
// path up to and including the first of `middles` (path_middles()) met.
inline std::vector<int> end_branch_to_cut(const Skeleton_adjacency& graph, const std::vector<std::vector<int>>& around,
                                          int end, const std::vector<Voxel_key>& middles)
{
  std::vector<int> branch = walk_from_end(around, end).nodes;
  for(std::size_t i = 0; i + 2 < branch.size(); ++i)
    if(std::binary_search(middles.begin(), middles.end(), graph.nodes[std::size_t(branch[i])]))
    {
      branch.resize(i + 2);
      break;
    }
  return branch;
}

// Cuts back one end branch of the skeleton's graph so that it ends where the coarser
// skeleton ends, and returns false when there is none to cut. An end point matches the
// coarse end points within `tolerance` of it (as Coarse_end_point_guide matches them). Its
// end branch (end_branch_to_cut()) is cut back to the branch voxel nearest
// - the coarse end point nearest the tip, when it matches one: a finer grid reaches further
//   into a tip (a hoof's curl, a finger) than the coarser one;
// - else, the coarse end point that no end point matches and that the branch passes near,
//   the first met from the tip: a finer grid carries the branch on into detail that the
//   coarser one smooths away (a hand's fingers, an open neck). Near is within `tolerance`
//   of a branch voxel, or inside its maximal ball (radius `ball_radius(k)`, voxels): in a
//   thick part the coarser grid may end its skeleton anywhere across a plateau of the
//   distance (the mid-plane of a slab, which thinning crosses in voxel order), farther from
//   the finer skeleton than the tolerance but within the part's thickness.
// The voxels from the tip up to, not including, that voxel go. The voxel next to the
// junction always stays, so no branch goes whole, and so does a path's middle voxel. The
// first end point in voxel order that has voxels to lose loses them.
template <typename VoxelSet, typename BallRadius>
bool cut_back_one_end_branch(VoxelSet& skeleton, const std::vector<std::array<double, 3>>& coarse,
                             double tolerance, const BallRadius& ball_radius,
                             const std::vector<Voxel_key>& middles, Cut_back& cut)
{
  const Skeleton_adjacency graph = skeleton_adjacency(skeleton);
  const std::vector<std::vector<int>> around = neighbours_of_nodes(graph);
  const auto centre = [&](int v) { return centre_in_grid(graph.nodes[std::size_t(v)]); };
  const double squared_tolerance = tolerance * tolerance;
  const auto squared_reach = [&](int v) {
    const double reach = (std::max)(tolerance, double(ball_radius(graph.nodes[std::size_t(v)])));
    return reach * reach;
  };
  std::vector<int> ends;
  for(int v = 0; v < int(graph.nodes.size()); ++v)
    if(around[std::size_t(v)].size() == 1)
      ends.push_back(v);
  // The coarse end point nearest each end point within the tolerance (coarse.size(): none),
  // and whether each coarse end point matches an end point.
  std::vector<std::size_t> match(ends.size(), coarse.size());
  std::vector<bool> coarse_matched(coarse.size(), false);
  for(std::size_t e = 0; e < ends.size(); ++e)
  {
    double nearest = squared_tolerance;
    for(std::size_t c = 0; c < coarse.size(); ++c)
    {
      const double d = squared_distance3(coarse[c], centre(ends[e]));
      if(d > squared_tolerance)
        continue;
      coarse_matched[c] = true;
      if(match[e] == coarse.size() || clearly_greater(nearest, d))
      {
        match[e] = c;
        nearest = d;
      }
    }
  }

  for(std::size_t e = 0; e < ends.size(); ++e)
  {
    const std::vector<int> branch = end_branch_to_cut(graph, around, ends[e], middles);
    std::size_t cut_at = branch.size(); // the first voxel that stays
    if(match[e] != coarse.size())
      cut_at = nearest_branch_voxel(branch, coarse[match[e]], [&](int) { return squared_tolerance; }, centre);
    else
      for(std::size_t c = 0; c < coarse.size(); ++c)
        if(!coarse_matched[c])
          cut_at = (std::min)(cut_at, nearest_branch_voxel(branch, coarse[c], squared_reach, centre));
    if(cut_at == 0 || cut_at == branch.size())
      continue;
    for(std::size_t i = 0; i < cut_at; ++i)
      skeleton.erase(graph.nodes[std::size_t(branch[i])]);
    ++cut.branches;
    cut.points += cut_at;
    return true;
  }
  return false;
}

// Cuts back, one by one, the end branches that reach past where the coarser skeleton ends
// (cut_back_one_end_branch(), with the maximal balls of radius `ball_radius(k)`), so that
// the skeleton ends where the coarser one does; a path is cut from each end up to its
// middle at most (path_middles()).
template <typename VoxelSet, typename BallRadius>
Cut_back cut_back_to_coarse_end_points(VoxelSet& skeleton, const std::vector<std::array<double, 3>>& coarse,
                                       double tolerance, const BallRadius& ball_radius)
{
  Cut_back cut;
  const std::vector<Voxel_key> middles = path_middles(skeleton);
  while(cut_back_one_end_branch(skeleton, coarse, tolerance, ball_radius, middles, cut))
  {
  }
  return cut;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_POINTS_H
