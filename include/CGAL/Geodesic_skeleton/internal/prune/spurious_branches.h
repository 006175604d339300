// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SPURIOUS_BRANCHES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SPURIOUS_BRANCHES_H

// The iterative snipping of short end branches that follows Algorithm 1.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/internal/prune/branched_regions.h>
#include <CGAL/Geodesic_skeleton/internal/prune/covering_balls.h>

#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// An end branch: the voxels from an end point up to (not including) its junction.
struct End_branch
{
  std::vector<Voxel_key> voxels; // from the end point inwards
  Voxel_key junction;
  double length = 0;             // arc length from the end point to the junction (voxels)
  double spuriousness = 0;       // under 1 for a spur; the smaller, the earlier it is snipped
};

// Walks on from the last voxel of `branch` along points of degree 2 until a point of
// degree 3 or more, which becomes the branch's junction. Returns false when the walk ends
// elsewhere (another end, or a fork without junction point).
template <typename VoxelSet>
bool walk_to_junction(const VoxelSet& skeleton, End_branch& branch)
{
  Voxel_key current = branch.voxels.back();
  while(true)
  {
    // The next voxel: the neighbour of `current` that is not already on the branch. Near
    // a junction a branch voxel may touch two voxels ahead (a 26-adjacent triangle); the
    // walk stops at the first neighbour of degree 3 or more then.
    Voxel_key next = current;
    int ahead = 0;
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const Voxel_key n = current + offset;
      if(!skeleton.contains(n) || std::find(branch.voxels.begin(), branch.voxels.end(), n) != branch.voxels.end())
        continue;
      ++ahead;
      if(next == current || skeleton_degree(skeleton, n) >= 3)
        next = n;
    }
    if(ahead == 0)
      return false; // reached another end: the component is a path
    branch.length += step_length(current, next);
    if(skeleton_degree(skeleton, next) >= 3)
    {
      branch.junction = next;
      return true;
    }
    if(ahead > 1)
      return false; // a fork without a junction point: leave it alone
    current = next;
    branch.voxels.push_back(current);
  }
}

// The junction that `j` belongs to: the 26-connected cluster of points of degree 3 or more
// around `j` (thinning leaves small clusters where branches meet), and its exits, the
// skeleton points next to the cluster that start a branch: an end point, or a point that
// leads on out of the cluster. A point next to the cluster whose neighbours are all in
// the cluster closes a little triangle inside the junction and starts no branch.
struct Junction_cluster
{
  std::vector<Voxel_key> voxels;   // sorted
  std::vector<Voxel_key> exits;    // sorted
  std::vector<Voxel_key> tucked_in; // next to the cluster, no exit: all their neighbours in it
};

template <typename VoxelSet>
Junction_cluster junction_cluster(const VoxelSet& skeleton, const Voxel_key& j)
{
  Voxel_key_set cluster{j};
  std::vector<Voxel_key> stack{j};
  Voxel_key_set next_to_cluster;
  while(!stack.empty())
  {
    const Voxel_key k = stack.back();
    stack.pop_back();
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const Voxel_key n = k + offset;
      if(!skeleton.contains(n) || cluster.count(n) != 0)
        continue;
      if(skeleton_degree(skeleton, n) >= 3)
      {
        cluster.insert(n);
        stack.push_back(n);
      }
      else
        next_to_cluster.insert(n);
    }
  }
  Junction_cluster result;
  result.voxels.assign(cluster.begin(), cluster.end());
  std::sort(result.voxels.begin(), result.voxels.end());
  for(const Voxel_key& e : next_to_cluster)
  {
    bool leads_out = skeleton_degree(skeleton, e) == 1;
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const Voxel_key n = e + offset;
      if(skeleton.contains(n) && cluster.count(n) == 0)
        leads_out = true;
    }
    (leads_out ? result.exits : result.tucked_in).push_back(e);
  }
  std::sort(result.exits.begin(), result.exits.end());
  std::sort(result.tucked_in.begin(), result.tucked_in.end());
  return result;
}

// How many branches leave the junction that `j` belongs to.
template <typename VoxelSet>
std::size_t branches_at_junction(const VoxelSet& skeleton, const Voxel_key& j)
{
  return junction_cluster(skeleton, j).exits.size();
}

// Traces the end branch from the end point `end` to its junction: along points of degree
// 2, and on through any cluster of points of degree 3 or more that only two branches
// leave (a lump on a chain, not a junction). Returns false when the walk ends elsewhere
// (the component is a path or a cycle fragment without junction), which is never a
// spurious branch.
template <typename VoxelSet>
bool trace_end_branch(const VoxelSet& skeleton, const Voxel_key& end, End_branch& branch)
{
  branch.voxels.assign(1, end);
  branch.length = 0;
  while(walk_to_junction(skeleton, branch))
  {
    const Junction_cluster cluster = junction_cluster(skeleton, branch.junction);
    if(cluster.exits.size() != 2)
      return true;
    // Copies: the pushes below may move the branch's voxels.
    const Voxel_key last = branch.voxels.back();
    const Voxel_key other = cluster.exits[0] == last ? cluster.exits[1] : cluster.exits[0];
    if(other == last || std::find(branch.voxels.begin(), branch.voxels.end(), other) != branch.voxels.end())
      return false; // the lump closes a loop onto the branch
    // The voxels tucked into the lump go with it: they would be left alone when the branch
    // is snipped.
    for(const Voxel_key& k : cluster.voxels)
      branch.voxels.push_back(k);
    for(const Voxel_key& k : cluster.tucked_in)
      branch.voxels.push_back(k);
    branch.length += std::sqrt(double(squared_distance_between(last, other))) - step_length(last, branch.junction);
    branch.voxels.push_back(other);
  }
  return false;
}

// The thresholds of the snipping: an end branch is a spur when it is shorter than
// `spur_length_factor` radii at its junction, or when its balls reach less than
// `limb_protrusion_factor` times the largest radius of its skeleton piece out of its
// junction's ball and out of the maximal balls of the rest of the skeleton. A factor 0
// turns its test off.
struct Spur_thresholds
{
  double spur_length_factor = 0;
  double limb_protrusion_factor = 0;
  // The largest radius of the piece of the skeleton each voxel is in.
  std::unordered_map<Voxel_key, double, Voxel_key_hash> largest_radius_of_piece;
};

// The radii of a skeleton voxel that the snipping reads, in voxels: `judging(k)` measures
// twigs (the MAT radius, or the sheet radius where a thin sheet's is larger) and `ball(k)`
// is the radius of the maximal ball centred at k (the MAT radius).
template <typename JudgingRadius, typename BallRadius>
struct Snipping_radii
{
  JudgingRadius judging;
  BallRadius ball;
};

template <typename JudgingRadius, typename BallRadius>
Snipping_radii<JudgingRadius, BallRadius> snipping_radii(const JudgingRadius& judging, const BallRadius& ball)
{
  return {judging, ball};
}

// How far the balls of `branch` reach out of the rest of the skeleton (voxels): the
// largest, over the branch's voxels k, of how little k's ball reaches out of a ball that
// holds k, |k - c| + r(k) - r(c) for a ball centred at c, among
// - its junction's ball, with the judging radii, and
// - the maximal balls of the voxels still in `skeleton`, not on the branch, that contain
//   k, with the ball radii.
// A branch inside its junction's ball (a bump, a short stub) reaches out little; so does
// one inside the balls of the rest of the skeleton, such as a tooth of a comb of parallel
// curves that thinning left in a thick sheet. The voxels are taken from the tip inwards,
// and the count stops at `enough`.
template <typename VoxelSet, typename Radii>
double protrusion_of(const End_branch& branch, const Radii& radii, const VoxelSet& skeleton,
                     const Covering_balls& balls, double enough)
{
  std::vector<Voxel_key> own(branch.voxels);
  std::sort(own.begin(), own.end());
  const double junction_radius = radii.judging(branch.junction);
  double protrusion = 0;
  for(const Voxel_key& k : branch.voxels)
  {
    double reach = std::sqrt(double(squared_distance_between(k, branch.junction))) + radii.judging(k) - junction_radius;
    if(reach <= protrusion)
      continue;
    const double ball_radius = radii.ball(k);
    balls.for_each_ball_containing(k, [&](const Covering_balls::Ball& ball, double distance) {
      const double out_of_ball = distance + ball_radius - ball.radius;
      if(out_of_ball < reach && skeleton.contains(ball.centre) &&
         !std::binary_search(own.begin(), own.end(), ball.centre))
        reach = out_of_ball;
    });
    protrusion = std::max(protrusion, reach);
    if(protrusion >= enough)
      break;
  }
  return protrusion;
}

// How spurious `branch` is: the smaller of its length over the spur length and its
// protrusion (protrusion_of()) over the smallest limb protrusion (each infinite when its
// test is off). The protrusion is measured only until it
// reaches the smallest limb protrusion: past 1, its ratio says only that the branch is no
// spur by that test.
template <typename VoxelSet, typename Radii>
double spuriousness_of(const End_branch& branch, const Radii& radii, const Spur_thresholds& thresholds,
                       const VoxelSet& skeleton, const Covering_balls& balls)
{
  double s = std::numeric_limits<double>::infinity();
  const double junction_radius = std::max(radii.judging(branch.junction), 1e-12);
  if(thresholds.spur_length_factor > 0)
    s = branch.length / (thresholds.spur_length_factor * junction_radius);
  if(thresholds.limb_protrusion_factor > 0)
  {
    const auto piece = thresholds.largest_radius_of_piece.find(branch.junction);
    const double largest = piece != thresholds.largest_radius_of_piece.end() ? piece->second : junction_radius;
    const double smallest_limb = thresholds.limb_protrusion_factor * std::max(largest, 1e-12);
    s = std::min(s, protrusion_of(branch, radii, skeleton, balls, smallest_limb) / smallest_limb);
  }
  return s;
}

struct Snipping
{
  std::size_t branches = 0, points = 0;
};

// The branches among `branches` that `thresholds` calls spurs, with their spuriousness,
// the most spurious first (ties by end voxel).
template <typename VoxelSet, typename Radii>
std::vector<End_branch> spurs_among(std::vector<End_branch> branches, const Radii& radii,
                                    const Spur_thresholds& thresholds, const VoxelSet& skeleton,
                                    const Covering_balls& balls)
{
  std::vector<End_branch> spurs;
  for(End_branch& branch : branches)
  {
    branch.spuriousness = spuriousness_of(branch, radii, thresholds, skeleton, balls);
    if(!(branch.spuriousness < 1))
      continue;
    spurs.push_back(std::move(branch));
  }
  std::sort(spurs.begin(), spurs.end(), [](const End_branch& a, const End_branch& b) {
    return std::tie(a.spuriousness, a.voxels.front()) < std::tie(b.spuriousness, b.voxels.front());
  });
  return spurs;
}

// Snips the `spurs` in their order, each one that `may_snip(spur)`, asked after the snips
// before it, allows.
template <typename VoxelSet, typename MaySnip>
Snipping snip_in_order(VoxelSet& skeleton, const std::vector<End_branch>& spurs,
                       MaySnip may_snip)
{
  Snipping result;
  for(const End_branch& spur : spurs)
  {
    if(!may_snip(spur))
      continue;
    for(const Voxel_key& k : spur.voxels)
      skeleton.erase(k);
    ++result.branches;
    result.points += spur.voxels.size();
  }
  return result;
}

// One round: snips the end branches that `thresholds` calls spurs, the most spurious
// first, each only while three branches or more leave its junction and while it is still a
// spur (the balls of the branches snipped before it no longer hold it).
template <typename VoxelSet, typename Radii>
Snipping snip_spurious_branches_once(VoxelSet& skeleton, const Radii& radii, const Spur_thresholds& thresholds)
{
  std::vector<Voxel_key> ends;
  skeleton.for_each([&](const Voxel_key& k) {
    if(skeleton_degree(skeleton, k) == 1)
      ends.push_back(k);
  });
  std::sort(ends.begin(), ends.end());

  std::vector<End_branch> branches;
  for(const Voxel_key& end : ends)
  {
    End_branch branch;
    if(trace_end_branch(skeleton, end, branch))
      branches.push_back(std::move(branch));
  }
  const Covering_balls balls(skeleton, radii.ball);
  return snip_in_order(skeleton, spurs_among(std::move(branches), radii, thresholds, skeleton, balls),
                       [&](const End_branch& spur) {
    // Earlier snips of this round may have changed this branch's junction, or removed the
    // balls that held it.
    return skeleton.contains(spur.voxels.front()) && skeleton.contains(spur.junction) &&
           branches_at_junction(skeleton, spur.junction) >= 3 &&
           spuriousness_of(spur, radii, thresholds, skeleton, balls) < 1;
  });
}

// The end branches of the skeleton's graph, the one to_graph() makes (26-adjacency without
// junction triangles), and the degree of their junctions in it. A graph end branch runs from
// a node of degree 1 along nodes of degree 2 up to (not including) a node of degree 3 or
// more. The voxel tracing above misses two kinds of them, which the graph, and so the
// control skeleton, turns into end points: a voxel hanging on a lump of branched points (all
// its neighbours in the lump) and a branch whose tip is a little triangle (its end voxel has
// two neighbours). Both are more frequent the finer the grid.
struct Graph_end_branches
{
  std::vector<End_branch> branches;
  std::unordered_map<Voxel_key, std::size_t, Voxel_key_hash> junction_degree;
};

template <typename VoxelSet>
Graph_end_branches graph_end_branches(const VoxelSet& skeleton)
{
  Graph_end_branches result;
  const Skeleton_adjacency graph = skeleton_adjacency(skeleton);
  const std::vector<std::vector<int>> around = neighbours_of_nodes(graph);
  const auto key = [&](int v) { return graph.nodes[std::size_t(v)]; };
  const auto degree = [&](int v) { return around[std::size_t(v)].size(); };
  for(int end = 0; end < int(graph.nodes.size()); ++end)
  {
    if(degree(end) != 1)
      continue;
    const Walk_from_end walk = walk_from_end(around, end);
    if(degree(walk.stop) < 3)
      continue; // a path component: no junction
    End_branch branch;
    for(std::size_t i = 0; i < walk.nodes.size(); ++i)
    {
      const int ahead = i + 1 < walk.nodes.size() ? walk.nodes[i + 1] : walk.stop;
      branch.voxels.push_back(key(walk.nodes[i]));
      branch.length += step_length(key(walk.nodes[i]), key(ahead));
    }
    branch.junction = key(walk.stop);
    result.junction_degree[branch.junction] = degree(walk.stop);
    result.branches.push_back(std::move(branch));
  }
  return result;
}

// One round over the graph's end branches (graph_end_branches()): snips those that
// `thresholds` calls spurs, the most spurious first, each only while its junction keeps
// three branches or more in the graph and while it is still a spur.
template <typename VoxelSet, typename Radii>
Snipping snip_spurious_graph_branches_once(VoxelSet& skeleton, const Radii& radii,
                                           const Spur_thresholds& thresholds)
{
  Graph_end_branches graph = graph_end_branches(skeleton);
  const Covering_balls balls(skeleton, radii.ball);
  return snip_in_order(skeleton, spurs_among(std::move(graph.branches), radii, thresholds, skeleton, balls),
                       [&](const End_branch& spur) {
    std::size_t& branches = graph.junction_degree[spur.junction];
    if(branches < 3 ||
       !(spuriousness_of(spur, radii, thresholds, skeleton, balls) < 1))
      return false;
    --branches;
    return true;
  });
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SPURIOUS_BRANCHES_H
