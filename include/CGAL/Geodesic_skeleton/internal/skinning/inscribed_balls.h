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

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/skinning_fields.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Per solid voxel, its distance through the solid (in hundredths of a voxel) to the nearest
// voxel at the surface: a solid voxel with an outside voxel among its 26 neighbours.
inline std::vector<Voxel_distance> depth_below_surface(const Solid_voxels& solid, Bucket_queue& queue)
{
  std::vector<std::uint32_t> surface;
  for(std::uint32_t u = 0; u < solid.size(); ++u)
  {
    const std::ptrdiff_t cell = std::ptrdiff_t(solid.cell_of_solid[u]);
    for(std::ptrdiff_t offset : solid.offsets)
      if(solid.solid_of_cell[std::size_t(cell + offset)] < 0)
      {
        surface.push_back(u);
        break;
      }
  }
  std::vector<Voxel_distance> depth(solid.size(), unreached);
  std::vector<std::uint32_t> reached;
  voxel_dijkstra(solid, surface, depth, reached, queue, [](std::uint32_t, Voxel_distance) { return true; });
  return depth;
}

// The centre of the ball inside the solid that touches the surface at `point` (grid
// coordinates) with outward unit normal `normal`: the point `point - t normal` of largest t
// such that every point of the segment before it, in steps of half a voxel, lies in the
// solid at a depth of at least its distance t from `point`, less a slack of 2 voxels (the
// depth runs between voxel centres, up to a voxel short of the surface, and the voxel
// metric is up to 8 % long). Points outside the solid within the slack of `point` are
// passed over (the vertex is on the surface, which its voxels may not cover). `point`
// itself when the normal is 0 or the solid is not met.
inline Vec3 inscribed_ball_centre(const Vec3& point, const Vec3& normal, const Solid_voxels& solid,
                                  const std::vector<Voxel_distance>& depth)
{
  constexpr double step = 0.5, slack = 2;
  Vec3 centre = point;
  if(dot3(normal, normal) == 0)
    return centre;
  for(double t = 0;; t += step)
  {
    const Vec3 p{point[0] - t * normal[0], point[1] - t * normal[1], point[2] - t * normal[2]};
    const std::int32_t u = solid.solid(Voxel_key{int(std::floor(p[0])), int(std::floor(p[1])), int(std::floor(p[2]))});
    if(u < 0)
    {
      if(t < slack)
        continue;
      return centre;
    }
    // A depth is finite: every piece of the solid has a voxel at its surface.
    if(depth[std::size_t(u)] * voxels_per_unit + slack < t)
      return centre;
    centre = p;
  }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_INSCRIBED_BALLS_H
