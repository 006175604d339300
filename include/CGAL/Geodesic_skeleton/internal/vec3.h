// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_VEC3_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_VEC3_H

// Plain double 3-vectors for the package's inner loops (voxel grids, polylines), where a
// kernel's exact types would cost for nothing.

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
