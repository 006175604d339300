// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H

// Which bone heats each vertex in compute_skinning_weights(): the bone nearest by the facing
// distance among the bones that see the vertex, as bone heat has it. A bone sees a vertex
// when the distance to it through the solid is about the straight one: the straight path
// stays inside the shape, so a hand resting on a thigh does not see the thigh's bone, nor a
// vertex of one leg the other leg's. The facing distance is the straight distance e divided
// by (1 + cos a + 0.001) / 2, with a the angle between the vertex's outward normal and the
// direction from the bone's nearest point to the vertex (Blender's bone heat has it): a
// bone straight below the surface is at e, one to the side at 2 e, one the surface turns
// its back on at 2000 e. The distance through the solid is what chooses when no bone sees
// the vertex (a sheet folded round, a pocket of the solid).

#include <CGAL/Geodesic_skeleton/internal/skinning/surface_heat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

class Heat_source_finder
{
public:
  static constexpr std::uint32_t none = Heat_sources::none;
  // The distance through the solid exceeds the straight one by the voxel metric's error
  // (26 neighbours: up to 8 %) and by where in its voxels a bone runs (up to a voxel's
  // diagonal); a bone within that slack sees the vertex.
  static constexpr double metric_slack = 1.1, voxel_slack = 1.5;

  // Bones whose facing distances differ by less than this share are at the same distance
  // (bone heat's tolerance): a vertex beyond a joint, whose nearest point on the bones into
  // and out of the joint is the joint itself, or on a mirror plane, is heated by all of
  // them, not by whichever the order of the searches or a rounding favours.
  static constexpr double tie = 1e-4;

  explicit Heat_source_finder(std::size_t vertices)
      : m_seen(vertices), m_nearest(vertices, none), m_through_solid(vertices, HUGE_VAL),
        m_nearest_facing(vertices, HUGE_VAL)
  {
  }

  // The facing distance, for the straight distance `e` and the cosine of the angle between
  // the vertex's outward normal and the direction from the bone to the vertex.
  static double facing_distance(double e, double cosine) { return e / (0.5 * (cosine + 1.001)); }

  // Bone `bone` is at `through_solid` voxels from vertex `v` through the solid;
  // `distances()` (computed only when it may matter) gives its straight distance and its
  // facing distance.
  template <typename Distances>
  void add(std::uint32_t v, std::uint32_t bone, double through_solid, Distances distances)
  {
    const bool nearer_through_solid = through_solid < m_through_solid[v];
    // A bone that sees the vertex is at least this far in straight line, and the facing
    // distance is at least the straight one over 1.0005.
    const bool may_see_nearer =
        (through_solid - voxel_slack) / metric_slack < 1.0005 * (1 + tie) * m_seen[v].least;
    if(!nearer_through_solid && !may_see_nearer)
      return;
    const auto [straight, facing] = distances();
    if(may_see_nearer && through_solid <= metric_slack * straight + voxel_slack)
      m_seen[v].offer(bone, facing);
    if(nearer_through_solid)
    {
      m_nearest[v] = bone;
      m_through_solid[v] = through_solid;
      m_nearest_facing[v] = facing;
    }
  }

  // Per vertex, the bones that heat it and the facing distance to them (bone `none` for a
  // vertex no bone reached).
  Heat_sources sources() const
  {
    const std::size_t n = m_seen.size();
    Heat_sources s;
    s.bone.assign(n, none);
    s.distance.assign(n, HUGE_VAL);
    s.tied.assign(n, Heat_sources::no_tied_bones());
    for(std::size_t v = 0; v < n; ++v)
      if(const Seen_bones& seen = m_seen[v]; seen.count > 0)
      {
        s.bone[v] = seen.bone[0];
        s.distance[v] = seen.least;
        std::copy(seen.bone.begin() + 1, seen.bone.begin() + seen.count, s.tied[v].begin());
      }
      else
      {
        s.bone[v] = m_nearest[v];
        s.distance[v] = m_nearest_facing[v];
      }
    return s;
  }

private:
  // The bones that see a vertex within `tie` of the least facing distance.
  struct Seen_bones
  {
    static constexpr std::size_t capacity = Heat_sources::most_tied + 1;
    std::array<std::uint32_t, capacity> bone{};
    std::array<double, capacity> facing{};
    std::uint8_t count = 0;
    double least = HUGE_VAL;

    void offer(std::uint32_t b, double f)
    {
      if(f > least * (1 + tie))
        return;
      if(f < least)
      {
        least = f;
        std::uint8_t kept = 0;
        for(std::uint8_t i = 0; i < count; ++i)
          if(facing[i] <= least * (1 + tie))
          {
            bone[kept] = bone[i];
            facing[kept++] = facing[i];
          }
        count = kept;
      }
      if(count < capacity)
      {
        bone[count] = b;
        facing[count++] = f;
      }
    }
  };

  std::vector<Seen_bones> m_seen;
  std::vector<std::uint32_t> m_nearest;
  std::vector<double> m_through_solid;
  std::vector<double> m_nearest_facing;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H
