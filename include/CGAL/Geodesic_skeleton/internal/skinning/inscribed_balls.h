// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_INSCRIBED_BALLS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_INSCRIBED_BALLS_H

// Where a vertex sits in the shape, for compute_skinning_weights(): the centre of its
// inscribed ball, the largest ball inside the solid that touches the surface at the vertex,
// found along the vertex's inward normal. A vertex on the side of a big round head has
// its centre in the middle of the head, though an arm's bone running through the head's
// lower part is nearer the vertex itself; a vertex of a limb has it on the limb's axis; a
// vertex of a thin sheet, at the vertex.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <cmath>
#include <cstdint>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The centre of the ball inside the solid that touches the surface at `point` (grid
// coordinates) with outward unit normal `normal`: the point `point - t normal` of largest t
// such that every point of the segment before it, in steps of half a voxel, lies in a solid
// voxel whose distance to the nearest outside voxel (`depth`, the solid's
// distance_transform()) is at least t less a slack of 0.75 voxel. The distance is measured
// from the voxel's centre, up to sqrt(3) / 2 voxel from the point, so the walk needs a
// slack: 0.75 is the least that reaches the middle of a ball and the axis of a bar (test
// an_inscribed_balls_centre_is_the_middle_of_a_ball_or_the_axis_of_a_bar; at 0.5 the walk
// stops 8 voxels short of a ball's middle 15 voxels deep), and about the best on artists'
// weights (manual, section manual_skinning_method). Points outside the solid within 2
// voxels of `point` are passed over (the vertex is on the surface, which its voxels may not
// cover). `point` itself when the normal is 0 or the solid is not met.
inline Vec3 inscribed_ball_centre(const Vec3& point, const Vec3& normal, const Voxel_distance_field& depth)
{
  constexpr double step = 0.5, slack = 0.75, entry = 2;
  Vec3 centre = point;
  if(dot3(normal, normal) == 0)
    return centre;
  // The walk ends: the field is 0 outside its finite box.
  for(double t = 0;; t += step)
  {
    const Vec3 p{point[0] - t * normal[0], point[1] - t * normal[1], point[2] - t * normal[2]};
    const std::uint32_t squared = depth.squared_distance(
        Voxel_key{int(std::floor(p[0])), int(std::floor(p[1])), int(std::floor(p[2]))});
    if(squared == 0)
    {
      if(t < entry)
        continue;
      return centre;
    }
    if(std::sqrt(double(squared)) + slack < t)
      return centre;
    centre = p;
  }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_INSCRIBED_BALLS_H
