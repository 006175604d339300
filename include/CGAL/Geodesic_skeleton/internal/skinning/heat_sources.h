// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H

// Which bone heats each vertex in compute_skinning_weights(): the bone nearest in straight
// line among the bones that see the vertex, as bone heat has it. A bone sees a vertex when
// the distance to it through the solid is about the straight one: the straight path stays
// inside the shape, so a hand resting on a thigh does not see the thigh's bone, nor a
// vertex of one leg the other leg's. The distance through the solid is what chooses when no
// bone sees the vertex (a sheet folded round, a pocket of the solid).

#include <CGAL/Geodesic_skeleton/internal/skinning/surface_heat.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

class Heat_source_finder
{
public:
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  // The distance through the solid exceeds the straight one by the voxel metric's error
  // (26 neighbours: up to 8 %) and by where in its voxels a bone runs (up to a voxel's
  // diagonal); a bone within that slack sees the vertex.
  static constexpr double metric_slack = 1.1, voxel_slack = 1.5;

  explicit Heat_source_finder(std::size_t vertices)
      : m_seen(vertices, none), m_straight(vertices, HUGE_VAL), m_nearest(vertices, none),
        m_through_solid(vertices, HUGE_VAL), m_nearest_straight(vertices, HUGE_VAL)
  {
  }

  // Bone `bone` is at `through_solid` voxels from vertex `v` through the solid and at
  // `straight()` in straight line (computed only when it may matter).
  template <typename StraightDistance>
  void add(std::uint32_t v, std::uint32_t bone, double through_solid, StraightDistance straight)
  {
    const bool nearer_through_solid = through_solid < m_through_solid[v];
    // A bone that sees the vertex is at least this far in straight line.
    const bool may_see_nearer = (through_solid - voxel_slack) / metric_slack < m_straight[v];
    if(!nearer_through_solid && !may_see_nearer)
      return;
    const double e = straight();
    if(may_see_nearer && through_solid <= metric_slack * e + voxel_slack && e < m_straight[v])
    {
      m_seen[v] = bone;
      m_straight[v] = e;
    }
    if(nearer_through_solid)
    {
      m_nearest[v] = bone;
      m_through_solid[v] = through_solid;
      m_nearest_straight[v] = e;
    }
  }

  // Per vertex, the bone that heats it and the straight distance to it (bone `none` for a
  // vertex no bone reached).
  Heat_sources sources() const
  {
    Heat_sources s;
    s.bone = m_seen;
    s.distance = m_straight;
    for(std::size_t v = 0; v < s.bone.size(); ++v)
      if(s.bone[v] == none)
      {
        s.bone[v] = m_nearest[v];
        s.distance[v] = m_nearest_straight[v];
      }
    return s;
  }

private:
  std::vector<std::uint32_t> m_seen;
  std::vector<double> m_straight;
  std::vector<std::uint32_t> m_nearest;
  std::vector<double> m_through_solid;
  std::vector<double> m_nearest_straight;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_HEAT_SOURCES_H
