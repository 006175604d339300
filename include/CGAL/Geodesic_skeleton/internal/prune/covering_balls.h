// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_COVERING_BALLS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_COVERING_BALLS_H

// The maximal balls of a skeleton's voxels, searched for the balls that contain a point:
// the snipping asks whether an end branch lies inside the balls of the rest of the
// skeleton.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

class Covering_balls
{
public:
  struct Ball
  {
    Voxel_key centre;
    double radius; // voxels
  };

  // The balls of every voxel of `skeleton`, of radius `ball_radius(k)` (voxels).
  template <typename VoxelSet, typename BallRadius>
  Covering_balls(const VoxelSet& skeleton, const BallRadius& ball_radius)
  {
    skeleton.for_each([&](const Voxel_key& k) {
      const double r = ball_radius(k);
      balls_.push_back({k, r});
      largest_ = (std::max)(largest_, r);
    });
    // Sorted by key, so by third coordinate first: a query scans one slab of them.
    std::sort(balls_.begin(), balls_.end(), [](const Ball& a, const Ball& b) { return a.centre < b.centre; });
  }

  // Calls `f(ball, distance)` for every ball whose open interior contains the centre of
  // voxel `k`, with the distance from `k` to its centre (voxels), in key order.
  template <typename F>
  void for_each_ball_containing(const Voxel_key& k, F f) const
  {
    const int reach = int(std::ceil(largest_));
    const auto first = std::lower_bound(balls_.begin(), balls_.end(), k.z - reach,
                                        [](const Ball& b, int z) { return b.centre.z < z; });
    for(auto it = first; it != balls_.end() && it->centre.z <= k.z + reach; ++it)
    {
      const std::int64_t dx = it->centre.x - k.x, dy = it->centre.y - k.y, dz = it->centre.z - k.z;
      const double d2 = double(dx * dx + dy * dy + dz * dz);
      if(d2 < it->radius * it->radius)
        f(*it, std::sqrt(d2));
    }
  }

private:
  std::vector<Ball> balls_;
  double largest_ = 0;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_COVERING_BALLS_H
