// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CHAIN_JOINTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CHAIN_JOINTS_H

// Where the joints of a chain go as artists place them, once Algorithm 2 has cut a branch
// at its bends: a chain ends short of the tip (at the wrist, the head joint, the last tail
// joint), and a long bone gets the joints that an artist spaces along a spine or a limb.
// Both work on the cut indices of one branch and its arc lengths.

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The index k in [lo, hi] whose arc length is nearest `target`. On a grid a target often
// falls half way between two points: ties, up to rounding, go to the lower index, or to the
// higher one with `ties_up`. The caller picks the side by the shape (towards the body, not
// the tip), so that mirror-image branches walked in opposite directions cut alike, and the
// rounding of the mesh's placement never decides.
inline std::size_t nearest_arc_length(const std::vector<double>& arc, double target, std::size_t lo, std::size_t hi,
                                      bool ties_up = false)
{
  const double rounding = 1e-9 * (std::abs(arc[hi]) + std::abs(target));
  std::size_t best = lo;
  for(std::size_t k = lo + 1; k <= hi; ++k)
  {
    const double d = std::abs(arc[k] - target), best_d = std::abs(arc[best] - target);
    if(d < best_d - rounding || (ties_up && d <= best_d + rounding))
      best = k;
  }
  return best;
}

// The whole number nearest `x`; a half, up to rounding, rounds down.
inline double nearest_whole_number(double x) { return std::ceil(x - 0.5 - 1e-9 * std::abs(x)); }

// Moves the joint at a tip of the skeleton (the branch's first point when `front_is_tip`,
// its last when `back_is_tip`) back along its bone by `setback` times that bone's length,
// to the nearest point of the branch: the points beyond it are in no bone. A bone of two
// points keeps its tip. `cuts` are the branch's joints as indices into `arc` (arc length
// from the branch's first point), increasing, the first 0 and the last arc.size() - 1.
inline void set_back_tip_joints(const std::vector<double>& arc, bool front_is_tip, bool back_is_tip, double setback,
                                std::vector<std::size_t>& cuts)
{
  if(!(setback > 0) || cuts.size() < 2)
    return;
  const std::size_t last = cuts.size() - 1;
  // A lone bone with two tips is set back from both ends by the same share of its length.
  const double front_length = arc[cuts[1]] - arc[cuts[0]];
  const double back_length = arc[cuts[last]] - arc[cuts[last - 1]];
  if(back_is_tip)
  {
    const std::size_t nearest_allowed = cuts[last - 1] + 1;
    cuts[last] = nearest_arc_length(arc, arc[cuts[last]] - setback * back_length, nearest_allowed, cuts[last], false);
  }
  if(front_is_tip)
  {
    const std::size_t farthest_allowed = cuts[1] - 1;
    if(farthest_allowed >= cuts[0])
      cuts[0] = nearest_arc_length(arc, arc[cuts[0]] + setback * front_length, cuts[0], farthest_allowed, true);
  }
}

// Cuts each bone between consecutive `cuts` into n bones of about `spacing` length, n the
// whole number nearest its length over `spacing`, at the points nearest the equal-length
// positions (ties towards the branch's last point with `ties_up`); `spacing` 0 leaves the
// cuts as they are.
inline void space_joints(const std::vector<double>& arc, double spacing, std::vector<std::size_t>& cuts,
                         bool ties_up = false)
{
  if(!(spacing > 0) || cuts.size() < 2)
    return;
  std::vector<std::size_t> spaced{cuts.front()};
  for(std::size_t c = 0; c + 1 < cuts.size(); ++c)
  {
    const std::size_t i = cuts[c], j = cuts[c + 1];
    const double length = arc[j] - arc[i];
    const double bones = nearest_whole_number(length / spacing);
    for(std::size_t m = 1; double(m) < bones; ++m)
    {
      if(spaced.back() + 1 >= j)
        break;
      const double target = arc[i] + length * double(m) / bones;
      spaced.push_back(nearest_arc_length(arc, target, spaced.back() + 1, j - 1, ties_up));
    }
    spaced.push_back(j);
  }
  cuts = std::move(spaced);
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CHAIN_JOINTS_H
