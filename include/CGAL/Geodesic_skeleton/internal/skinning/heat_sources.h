// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H

// Which bone heats each vertex in compute_skinning_weights(). A bone sees a vertex when the
// distance to it through the solid is about the straight one: the straight path stays
// inside the shape, so a hand resting on a thigh does not see the thigh's bone, nor a
// vertex of one leg the other leg's. Among the bones that see it, the vertex is heated by
// the bone nearest to the centre of its inscribed ball (inscribed_balls.h): the bone of the
// part of the body the vertex bounds, not the one that happens to pass nearest to it (an
// arm's bone running through the lower part of a big head, a thigh's bone beside the hip).
// The heat is set by the facing distance to that bone: the straight distance e divided by
// (1 + cos a + 0.001) / 2, with a the angle between the vertex's outward normal and the
// direction from the bone's nearest point to the vertex (Blender's bone heat has it): a
// bone straight below the surface is at e, one to the side at 2 e. The distance through
// the solid is what chooses when no bone sees the vertex (a sheet folded round, a pocket
// of the solid).

#include <CGAL/Geodesic_skeleton/internal/parallel_parts.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/surface_heat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
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

  // Bones whose distances to the centre differ by less than this share are at the same
  // distance (bone heat's tolerance): a vertex whose centre is at a joint, or on a mirror
  // plane, is heated by all of them, not by whichever the order of the searches or a
  // rounding favours.
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
  // `distances()` gives its straight distance and its facing distance.
  template <typename Distances>
  void add(std::uint32_t v, std::uint32_t bone, double through_solid, Distances distances)
  {
    const auto [straight, facing] = distances();
    if(through_solid <= metric_slack * straight + voxel_slack)
      m_seen[v].offer(bone, straight, facing);
    if(through_solid < m_through_solid[v])
    {
      m_nearest[v] = bone;
      m_through_solid[v] = through_solid;
      m_nearest_facing[v] = facing;
    }
  }

  // Per vertex, the bones that heat it and the facing distance to them (bone `none` for a
  // vertex no bone reached). `to_centre(v, b)` is the distance from the centre of vertex
  // v's inscribed ball to bone b; it is asked only of vertices that several bones see, on up
  // to `threads` threads at once.
  template <typename DistanceToCentre>
  Heat_sources sources(DistanceToCentre to_centre, unsigned threads) const
  {
    const std::size_t n = m_seen.size();
    Heat_sources s;
    s.bone.assign(n, none);
    s.distance.assign(n, HUGE_VAL);
    s.tied.assign(n, Heat_sources::no_tied_bones());
    for_each_index(n, threads, [&](std::size_t v) {
      const Seen_bones& seen = m_seen[v];
      if(seen.count == 0)
      {
        s.bone[v] = m_nearest[v];
        s.distance[v] = m_nearest_facing[v];
        return;
      }
      // The seen bones by distance to the centre, then by number.
      std::array<std::pair<double, std::uint8_t>, Seen_bones::capacity> order;
      for(std::uint8_t i = 0; i < seen.count; ++i)
        order[i] = {seen.count > 1 ? to_centre(v, seen.bone[i]) : 0., i};
      std::sort(order.begin(), order.begin() + seen.count, [&](const auto& a, const auto& b) {
        return a.first != b.first ? a.first < b.first : seen.bone[a.second] < seen.bone[b.second];
      });
      s.bone[v] = seen.bone[order[0].second];
      s.distance[v] = seen.facing[order[0].second];
      for(std::size_t i = 1, tied = 0; i < seen.count && tied < Heat_sources::most_tied; ++i)
        if(order[i].first <= order[0].first * (1 + tie))
          s.tied[v][tied++] = seen.bone[order[i].second];
    });
    return s;
  }

private:
  // The bones that see a vertex: the `capacity` nearest in straight line.
  struct Seen_bones
  {
    static constexpr std::size_t capacity = 8;
    std::array<std::uint32_t, capacity> bone{};
    std::array<float, capacity> straight{};
    std::array<double, capacity> facing{};
    std::uint8_t count = 0;

    void offer(std::uint32_t b, double e, double f)
    {
      std::size_t slot = count;
      if(count == capacity)
      {
        slot = std::size_t(std::max_element(straight.begin(), straight.end()) - straight.begin());
        if(straight[slot] <= e)
          return;
      }
      else
        ++count;
      bone[slot] = b;
      straight[slot] = float(e);
      facing[slot] = f;
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
