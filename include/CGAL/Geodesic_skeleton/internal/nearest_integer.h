// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_NEAREST_INTEGER_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_NEAREST_INTEGER_H

// Rounding of coordinates to a fixed step, which makes the voxels and the frame of a mesh
// the same whatever its scale (Voxel_frame::to_grid(), principal_frame()).

#include <cmath>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// `x` rounded to the nearest integer, ties to even, as std::rint() does in the default
// rounding mode; `x` itself from 2^51 in magnitude on (where a double holds no fraction
// finer than a half). Adding and subtracting 1.5 * 2^52 leaves no bit under the units:
// two additions, where std::rint() is a library call without SSE 4.1 (it was most of the
// cost of rounding a mesh's coordinates). Compilers fold the two additions away under
// -ffast-math, which then gets std::rint().
inline double nearest_integer(double x)
{
#ifdef __FAST_MATH__
  return std::rint(x);
#else
  constexpr double shifter = 0x1.8p52;
  return std::abs(x) < 0x1p51 ? (x + shifter) - shifter : x;
#endif
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_NEAREST_INTEGER_H
