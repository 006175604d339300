// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_VEC3_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_VEC3_H

// Plain double 3-vectors for the package's inner loops (voxel grids, polylines), where a
// kernel's exact types would cost for nothing.

#include <algorithm>
#include <array>
#include <cmath>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross3(const Vec3& a, const Vec3& b)
{
  return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm3(const Vec3& a) { return std::sqrt(dot3(a, a)); }
inline double squared_distance3(const Vec3& a, const Vec3& b) { return dot3(sub(a, b), sub(a, b)); }

// `a` > `b` by more than rounding (one part in 10^9). Values computed from a mesh in world
// coordinates (a bend, a distance) that are equal in exact arithmetic differ by the rounding
// of the mesh's placement: a choice between them made with this test, ties to the first in
// an order that the voxels fix, does not change with a rigid motion.
inline bool clearly_greater(double a, double b) { return a > b + 1e-9 * (std::abs(a) + std::abs(b)); }

// The point of the segment [a, b] nearest to p.
inline Vec3 closest_point_on_segment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 ab = sub(b, a);
  const double l2 = dot3(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot3(sub(p, a), ab) / l2, 0.0, 1.0) : 0.0;
  return Vec3{a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]};
}

// Distance from p to the segment [a, b].
inline double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b)
{
  return norm3(sub(p, closest_point_on_segment(p, a, b)));
}

// floor() for coordinates of a grid (finite, far below 2^62), without a library call.
inline long floor_to_long(double x)
{
  const long i = long(x);
  return i - long(x < double(i));
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_VEC3_H
