// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SPURIOUS_BRANCHES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SPURIOUS_BRANCHES_H

// The iterative snipping of short end branches that follows Algorithm 1.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/internal/prune/branched_regions.h>

#include <algorithm>
#include <cstddef>
#include <tuple>
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
  double relative_length = 0;    // length / MAT radius at the junction
};

// Walks from the end point `end` along points of degree 2 until a point of degree 3 or
// more. Returns false when the walk ends elsewhere (the component is a path or a cycle
// fragment without junction), which is never a spurious branch.
template <typename VoxelSet>
bool trace_end_branch(const VoxelSet& skeleton, const Voxel_key& end, End_branch& branch)
{
  branch.voxels.assign(1, end);
  branch.length = 0;
  Voxel_key previous = end, current = end;
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
      if(n == previous || !skeleton.contains(n))
        continue;
      if(branch.voxels.size() >= 2 && n == branch.voxels[branch.voxels.size() - 2])
        continue;
      if(std::find(branch.voxels.begin(), branch.voxels.end(), n) != branch.voxels.end())
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
    previous = current;
    current = next;
    branch.voxels.push_back(current);
  }
}

// How many branches leave the junction that `j` belongs to: the junction is the
// 26-connected cluster of points of degree 3 or more around `j` (thinning leaves small
// clusters where branches meet), and a branch starts at a skeleton point next to the
// cluster that is an end point or leads on out of the cluster. A point next to the
// cluster whose neighbours are all in the cluster closes a little triangle inside the
// junction and starts no branch.
template <typename VoxelSet>
std::size_t branches_at_junction(const VoxelSet& skeleton, const Voxel_key& j)
{
  Voxel_key_set cluster{j};
  std::vector<Voxel_key> stack{j};
  Voxel_key_set exits;
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
        exits.insert(n);
    }
  }
  std::size_t branches = 0;
  for(const Voxel_key& e : exits)
  {
    bool leads_out = false;
    for(const Voxel_key& offset : neighbourhood_26())
    {
      const Voxel_key n = e + offset;
      if(skeleton.contains(n) && cluster.count(n) == 0)
      {
        leads_out = true;
        break;
      }
    }
    if(leads_out || skeleton_degree(skeleton, e) == 1)
      ++branches;
  }
  return branches;
}

struct Snipping
{
  std::size_t branches = 0, points = 0;
};

// One round: snips the end branches shorter than `factor` MAT radii at their junction,
// shortest first, each only while three branches or more leave its junction.
template <typename VoxelSet, typename Radius>
Snipping snip_spurious_branches_once(VoxelSet& skeleton, const Radius& radius, double factor)
{
  std::vector<Voxel_key> ends;
  skeleton.for_each([&](const Voxel_key& k) {
    if(skeleton_degree(skeleton, k) == 1)
      ends.push_back(k);
  });
  std::sort(ends.begin(), ends.end());

  std::vector<End_branch> spurs;
  for(const Voxel_key& end : ends)
  {
    End_branch branch;
    if(!trace_end_branch(skeleton, end, branch))
      continue;
    const double r = std::max(radius(branch.junction), 1e-12);
    branch.relative_length = branch.length / r;
    if(branch.relative_length < factor)
      spurs.push_back(std::move(branch));
  }
  std::sort(spurs.begin(), spurs.end(), [](const End_branch& a, const End_branch& b) {
    return std::tie(a.relative_length, a.voxels.front()) < std::tie(b.relative_length, b.voxels.front());
  });

  Snipping result;
  for(const End_branch& spur : spurs)
  {
    // Earlier snips of this round may have changed this branch's junction.
    if(!skeleton.contains(spur.voxels.front()) || !skeleton.contains(spur.junction) ||
       branches_at_junction(skeleton, spur.junction) < 3)
      continue;
    for(const Voxel_key& k : spur.voxels)
      skeleton.erase(k);
    ++result.branches;
    result.points += spur.voxels.size();
  }
  return result;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SPURIOUS_BRANCHES_H
