// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_VOXEL_KEY_H
#define CGAL_GEODESIC_SKELETON_VOXEL_KEY_H

/// \file Voxel_key.h
/// The integer coordinates of a voxel, an axis-aligned box of voxels and the
/// 26-neighbourhood: the vocabulary shared by every model of the `VoxelSet` concept and
/// every voxel algorithm of the package.

#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <ostream>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// A voxel: its integer coordinates `(x, y, z)` in the grid of a `Voxel_frame` (unit:
/// voxels). Voxel `(x, y, z)` is the cube `[x, x+1) x [y, y+1) x [z, z+1)` of the frame's
/// grid coordinates; its centre is `(x + 1/2, y + 1/2, z + 1/2)`.
struct Voxel_key
{
  int x = 0; ///< first grid coordinate (along the frame's first axis)
  int y = 0; ///< second grid coordinate
  int z = 0; ///< third grid coordinate

  /// Equality of the three coordinates.

  friend bool operator==(const Voxel_key& a, const Voxel_key& b)
  {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  }
  /// Inequality.
  friend bool operator!=(const Voxel_key& a, const Voxel_key& b) { return !(a == b); }
  /// Lexicographic order on `(z, y, x)`, the memory order of `Dense_voxel_grid`.
  friend bool operator<(const Voxel_key& a, const Voxel_key& b)
  {
    if(a.z != b.z) return a.z < b.z;
    if(a.y != b.y) return a.y < b.y;
    return a.x < b.x;
  }
  /// Coordinate-wise sum (a key plus a neighbour offset).
  friend Voxel_key operator+(const Voxel_key& a, const Voxel_key& b)
  {
    return Voxel_key{a.x + b.x, a.y + b.y, a.z + b.z};
  }
  /// Writes `(x, y, z)`.
  friend std::ostream& operator<<(std::ostream& os, const Voxel_key& k)
  {
    return os << '(' << k.x << ", " << k.y << ", " << k.z << ')';
  }
};

/// \ingroup PkgGeodesicSkeletonRef
/// Hash of a `Voxel_key`, for unordered containers.
struct Voxel_key_hash
{
  /// The hash value of `k`.
  std::size_t operator()(const Voxel_key& k) const
  {
    // Multiplicative mixing of the three coordinates (large odd constants).
    std::uint64_t h = static_cast<std::uint32_t>(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint32_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint32_t>(k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

/// \ingroup PkgGeodesicSkeletonRef
/// An axis-aligned box of voxels: the keys `k` with `min.x <= k.x < max.x` (and the same
/// for `y` and `z`). A box with `max.c <= min.c` along any axis is empty.
struct Voxel_box
{
  Voxel_key min; ///< the smallest key of the box (inclusive)
  Voxel_key max; ///< one past the largest key along each axis (exclusive)

  /// Whether the box has no voxel.

  bool empty() const { return max.x <= min.x || max.y <= min.y || max.z <= min.z; }
  /// Voxels along each axis (0 when empty).
  std::array<std::size_t, 3> extent() const
  {
    if(empty()) return {0, 0, 0};
    return {std::size_t(max.x - min.x), std::size_t(max.y - min.y), std::size_t(max.z - min.z)};
  }
  /// Number of voxels in the box.
  std::size_t volume() const
  {
    const auto e = extent();
    return e[0] * e[1] * e[2];
  }
  /// Whether `k` is in the box.
  bool contains(const Voxel_key& k) const
  {
    return k.x >= min.x && k.x < max.x && k.y >= min.y && k.y < max.y && k.z >= min.z &&
           k.z < max.z;
  }
  /// The smallest box containing this box and `k`.
  void extend(const Voxel_key& k)
  {
    if(empty())
    {
      min = k;
      max = Voxel_key{k.x + 1, k.y + 1, k.z + 1};
      return;
    }
    min = Voxel_key{(std::min)(min.x, k.x), (std::min)(min.y, k.y), (std::min)(min.z, k.z)};
    max = Voxel_key{(std::max)(max.x, k.x + 1), (std::max)(max.y, k.y + 1),
                    (std::max)(max.z, k.z + 1)};
  }
  /// This box grown by `margin` voxels on every side.
  Voxel_box grown(int margin) const
  {
    return Voxel_box{Voxel_key{min.x - margin, min.y - margin, min.z - margin},
                     Voxel_key{max.x + margin, max.y + margin, max.z + margin}};
  }
};

namespace internal {

// Grid coordinates are moved up this far before they are rounded down to a voxel: a point
// on a cell boundary (a voxel centre of a grid twice as coarse or fine, a skeleton point on
// a voxel face) then falls in the same cell however its world coordinates round, so that
// results do not change when the mesh is scaled, rotated or moved.
constexpr double cell_boundary_bias = 1e-6;

// The voxel whose cell holds the grid point `g`, a point on a cell boundary in the cell above.
inline Voxel_key cell_of(const Vec3& g)
{
  return Voxel_key{int(std::floor(g[0] + cell_boundary_bias)), int(std::floor(g[1] + cell_boundary_bias)),
                   int(std::floor(g[2] + cell_boundary_bias))};
}

// The squared Euclidean distance between the centres of two voxels, in voxels.
inline std::int64_t squared_distance_between(const Voxel_key& a, const Voxel_key& b)
{
  const std::int64_t dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return dx * dx + dy * dy + dz * dz;
}

// Length of a step to a 26-neighbour: 1, sqrt 2 or sqrt 3 (voxels).
inline double step_length(const Voxel_key& a, const Voxel_key& b)
{
  static const double length[4] = {0.0, 1.0, std::sqrt(2.0), std::sqrt(3.0)};
  return length[(a.x != b.x) + (a.y != b.y) + (a.z != b.z)];
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// The 26 offsets of the 26-neighbourhood (the voxels sharing a face, an edge or a
/// corner), in `(z, y, x)` lexicographic order from `(-1, -1, -1)` to `(1, 1, 1)`,
/// skipping `(0, 0, 0)`. The 6 face neighbours are the offsets with one non-zero
/// coordinate, the 18-neighbourhood those with at most two.
inline const std::array<Voxel_key, 26>& neighbourhood_26()
{
  static const std::array<Voxel_key, 26> offsets = [] {
    std::array<Voxel_key, 26> o{};
    std::size_t n = 0;
    for(int dz = -1; dz <= 1; ++dz)
      for(int dy = -1; dy <= 1; ++dy)
        for(int dx = -1; dx <= 1; ++dx)
          if(dx != 0 || dy != 0 || dz != 0)
            o[n++] = Voxel_key{dx, dy, dz};
    return o;
  }();
  return offsets;
}

/// \ingroup PkgGeodesicSkeletonRef
/// The number of non-zero coordinates of a neighbour offset: 1 for a face neighbour
/// (distance 1), 2 for an edge neighbour (sqrt 2), 3 for a corner neighbour (sqrt 3).
inline int offset_order(const Voxel_key& offset)
{
  return (offset.x != 0) + (offset.y != 0) + (offset.z != 0);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Whether `a` and `b` are distinct and 26-adjacent (share a face, an edge or a corner).
inline bool are_26_adjacent(const Voxel_key& a, const Voxel_key& b)
{
  const int dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return a != b && dx >= -1 && dx <= 1 && dy >= -1 && dy <= 1 && dz >= -1 && dz <= 1;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

namespace std {
template <>
struct hash<CGAL::Geodesic_skeleton::Voxel_key> : CGAL::Geodesic_skeleton::Voxel_key_hash
{
};
} // namespace std

#endif // CGAL_GEODESIC_SKELETON_VOXEL_KEY_H
