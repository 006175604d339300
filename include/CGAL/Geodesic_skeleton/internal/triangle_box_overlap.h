// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_TRIANGLE_BOX_OVERLAP_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_TRIANGLE_BOX_OVERLAP_H

#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Whether the triangle (a, b, c) meets the axis-aligned cube of centre `centre` and half
// edge `half`: the separating axis theorem with the 13 candidate axes (3 cube normals, the
// triangle normal, 9 cross products of cube and triangle edges), as in Akenine-Moller's
// "Fast 3D triangle-box overlap testing" (2001). Touching counts as overlapping.
inline bool triangle_meets_cube(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& centre,
                                double half)
{
  const Vec3 v[3] = {sub(a, centre), sub(b, centre), sub(c, centre)};
  // The cube's face normals: the triangle's bounding box against the cube.
  for(int i = 0; i < 3; ++i)
  {
    const double lo = (std::min)({v[0][i], v[1][i], v[2][i]});
    const double hi = (std::max)({v[0][i], v[1][i], v[2][i]});
    if(lo > half || hi < -half)
      return false;
  }
  const Vec3 e[3] = {sub(v[1], v[0]), sub(v[2], v[1]), sub(v[0], v[2])};
  // The triangle's plane against the cube.
  const Vec3 n = cross3(e[0], e[1]);
  const double radius_n = half * (std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]));
  if(std::abs(dot3(n, v[0])) > radius_n)
    return false;
  // The nine cross products of a cube axis with a triangle edge.
  for(int i = 0; i < 3; ++i)
    for(int axis = 0; axis < 3; ++axis)
    {
      Vec3 u{0., 0., 0.};
      u[axis] = 1.;
      const Vec3 l = cross3(u, e[i]);
      const double p0 = dot3(l, v[0]), p1 = dot3(l, v[1]), p2 = dot3(l, v[2]);
      const double r = half * (std::abs(l[0]) + std::abs(l[1]) + std::abs(l[2]));
      if((std::min)({p0, p1, p2}) > r || (std::max)({p0, p1, p2}) < -r)
        return false;
    }
  return true;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_TRIANGLE_BOX_OVERLAP_H
