// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_FINISH_WEIGHTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_FINISH_WEIGHTS_H

// The last step of compute_skinning_weights(): a vertex's diffused weights made its
// skinning weights (the joints' preference and sharpening, the largest kept, normalised).

#include <CGAL/Geodesic_skeleton/Bone_weights.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {
// How much more a joint's heat counts than its child's, before the sharpening: at a joint,
// artists paint the parent bone's weight past the joint into the child's bone (val: of the
// vertices whose top joint was not the artist's, 4.6 % took the next joint down the chain and
// 1.9 % the one above). Calibrated on train (1, 1.1, 1.15, 1.2: top joint right 0.868, 0.870,
// 0.871, 0.870, L1 0.2886, 0.2885, 0.2911, 0.2915).
inline constexpr double parent_joint_preference = 1.1;

// Turns the diffused weights of a vertex into its skinning weights: divides each joint's
// weight (the sum over the bones that leave it, which all turn about it) by
// parent_joint_preference to the power of its depth below the vertex's shallowest joint,
// raises it to the power `exponent`, sharing it among those bones as before (the joint
// that leads keeps its lead and the blend around a joint narrows); keeps the `k` largest,
// drops those under `minimum` of their total (never the largest), and scales the rest to
// sum 1, by decreasing weight (bone number for ties).
inline void finish_weights(Bone_weights& weights, double exponent, const std::vector<std::uint32_t>& joint_of_bone,
                           const std::vector<std::uint32_t>& joint_depth, std::size_t k, double minimum)
{
  const std::size_t n = weights.size();
  if(n == 0)
    return;
  std::array<std::uint32_t, Bone_weights::capacity> joint{};
  std::array<float, Bone_weights::capacity> sharpened{};
  std::uint32_t shallowest = std::numeric_limits<std::uint32_t>::max();
  for(std::size_t i = 0; i < n; ++i)
  {
    joint[i] = joint_of_bone[weights.bone[i]];
    shallowest = std::min(shallowest, joint_depth[joint[i]]);
  }
  // 1 / parent_joint_preference^d, for d up to 255 (1.1^-255 is 3e-11: deeper, the same).
  static const std::array<float, 256> preference = [] {
    std::array<float, 256> p{};
    for(std::size_t d = 0; d < p.size(); ++d)
      p[d] = float(std::pow(parent_joint_preference, -double(d)));
    return p;
  }();
  for(std::size_t i = 0; i < n; ++i)
    weights.weight[i] *= preference[std::min<std::size_t>(joint_depth[joint[i]] - shallowest, preference.size() - 1)];
  for(std::size_t i = 0; i < n; ++i)
  {
    double joint_total = 0;
    for(std::size_t j = 0; j < n; ++j)
      if(joint[j] == joint[i])
        joint_total += weights.weight[j];
    sharpened[i] = weights.weight[i] * std::pow(float(joint_total), float(exponent - 1));
  }
  std::array<std::size_t, Bone_weights::capacity> order{};
  for(std::size_t i = 0; i < n; ++i) // insertion sort: a handful of pairs
  {
    std::size_t j = i;
    for(; j > 0; --j)
    {
      const std::size_t o = order[j - 1];
      if(sharpened[o] > sharpened[i] || (sharpened[o] == sharpened[i] && weights.bone[o] < weights.bone[i]))
        break;
      order[j] = o;
    }
    order[j] = i;
  }
  const std::size_t kept = std::min(n, k);
  double total = 0;
  for(std::size_t i = 0; i < kept; ++i)
    total += sharpened[order[i]];
  Bone_weights result;
  double kept_total = 0;
  for(std::size_t i = 0; i < kept; ++i)
    if(i == 0 || sharpened[order[i]] >= minimum * total)
    {
      result.push_back(weights.bone[order[i]], sharpened[order[i]]);
      kept_total += sharpened[order[i]];
    }
  for(std::size_t i = 0; i < result.size(); ++i)
    result.weight[i] = float(result.weight[i] / kept_total);
  weights = result;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_FINISH_WEIGHTS_H
