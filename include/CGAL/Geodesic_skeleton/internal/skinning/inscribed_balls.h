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

// Per cell of the solid's layout, the distance (in hundredths of a voxel, the steps of
// the 26 neighbours weighted 100, 141 and 173) from its centre to the centre of the nearest
// voxel outside the solid; 0 outside. Two raster passes over the layout (Rosenfeld and
// Pfaltz's chamfer transform): each cell takes the least of its neighbours' values plus the
// step, over the 13 neighbours before it in the first pass and after it in the second. The
// path to the nearest outside voxel never leaves the solid before it, so this is the
// distance through the solid. The layout's border cells are outside (it is the solid's box
// grown by one voxel).
inline std::vector<Voxel_distance> depth_in_solid(const Solid_voxels& solid)
{
  const std::size_t cells = solid.layout.volume();
  std::vector<Voxel_distance> depth(cells, 0);
  for(std::uint32_t cell : solid.cell_of_solid)
    depth[cell] = unreached;
  // The neighbours before a cell (negative offsets) and after it, with their steps.
  std::array<std::pair<std::ptrdiff_t, Voxel_distance>, 13> before, after;
  for(std::size_t n = 0, b = 0, a = 0; n < 26; ++n)
    (solid.offsets[n] < 0 ? before[b++] : after[a++]) = {solid.offsets[n], solid.steps[n]};
  auto relax = [&](std::uint32_t cell, const std::array<std::pair<std::ptrdiff_t, Voxel_distance>, 13>& side) {
    Voxel_distance d = depth[cell];
    for(const auto& [offset, step] : side)
      d = std::min(d, depth[std::size_t(std::ptrdiff_t(cell) + offset)] + step);
    depth[cell] = d;
  };
  // The solid's cells are in increasing order of their index (the grid's own order).
  for(std::uint32_t cell : solid.cell_of_solid)
    relax(cell, before);
  for(auto cell = solid.cell_of_solid.rbegin(); cell != solid.cell_of_solid.rend(); ++cell)
    relax(*cell, after);
  return depth;
}

// The centre of the ball inside the solid that touches the surface at `point` (grid
// coordinates) with outward unit normal `normal`: the point `point - t normal` of largest t
// such that every point of the segment before it, in steps of half a voxel, lies in a solid
// voxel whose `depth` (depth_in_solid()) is at least t less a slack of half a voxel (the
// steps' granularity; the depth runs to an outside voxel's centre, up to a voxel beyond the
// surface, which makes up for the voxel metric's error, up to 8 % long). The slack is the
// one constant, calibrated on artists' weights (manual, section manual_skinning_method).
// Points outside the solid within 2 voxels of `point` are passed over (the vertex is on the
// surface, which its voxels may not cover). `point` itself when the normal is 0 or the
// solid is not met.
inline Vec3 inscribed_ball_centre(const Vec3& point, const Vec3& normal, const Solid_voxels& solid,
                                  const std::vector<Voxel_distance>& depth)
{
  constexpr double step = 0.5, slack = 0.5, entry = 2;
  Vec3 centre = point;
  if(dot3(normal, normal) == 0)
    return centre;
  // The walk ends: the solid's box is finite, and a solid voxel's depth is finite.
  for(double t = 0;; t += step)
  {
    const Vec3 p{point[0] - t * normal[0], point[1] - t * normal[1], point[2] - t * normal[2]};
    const std::int32_t u = solid.solid(Voxel_key{int(std::floor(p[0])), int(std::floor(p[1])), int(std::floor(p[2]))});
    if(u < 0)
    {
      if(t < entry)
        continue;
      return centre;
    }
    if(depth[solid.cell_of_solid[std::size_t(u)]] * voxels_per_unit + slack < t)
      return centre;
    centre = p;
  }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_INSCRIBED_BALLS_H
