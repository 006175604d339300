// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_VOXEL_FRAME_H
#define CGAL_GEODESIC_SKELETON_VOXEL_FRAME_H

/// \file Voxel_frame.h
/// The mapping between voxel keys and points of the mesh's own coordinates.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/nearest_integer.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// A voxel grid placed in space: an origin, three orthonormal right-handed axes and a voxel
/// size (world units). The grid coordinates `g` of a world point `p` are
/// `g_i = ((p - origin) . axis_i) / voxel_size`; voxel `(x, y, z)` covers the grid cube
/// `[x, x+1) x [y, y+1) x [z, z+1)`.
///
/// `voxelize()` builds a frame aligned with the principal axes of the mesh, so that the
/// voxel keys do not depend on how the mesh is rotated or translated; a default-constructed
/// frame is the identity (origin 0, world axes, unit voxels).
class Voxel_frame
{
public:
  /// A point or vector of three `double`s (world or grid coordinates).
  using Vector = std::array<double, 3>;

  Voxel_frame() = default;

  /// \pre the axes are orthonormal and right-handed (checked to 1e-6), `voxel_size` is
  ///      finite and positive.
  /// \throws std::invalid_argument when a precondition does not hold.
  Voxel_frame(const Vector& origin, const std::array<Vector, 3>& axes, double voxel_size)
    : m_origin(origin), m_axes(axes), m_voxel_size(voxel_size), m_quanta_per_unit(1 / (grid_quantum * voxel_size))
  {
    if(!(voxel_size > 0) || !std::isfinite(voxel_size))
      throw std::invalid_argument("Voxel_frame: the voxel size must be finite and positive");
    for(int i = 0; i < 3; ++i)
    {
      if(!std::isfinite(origin[i]))
        throw std::invalid_argument("Voxel_frame: the origin must be finite");
      for(int j = 0; j < 3; ++j)
        if(std::abs(internal::dot3(axes[i], axes[j]) - (i == j ? 1. : 0.)) > 1e-6)
          throw std::invalid_argument("Voxel_frame: the axes must be orthonormal");
    }
    if(internal::dot3(internal::cross3(axes[0], axes[1]), axes[2]) < 0)
      throw std::invalid_argument("Voxel_frame: the axes must be right-handed");
  }

  /// The world point of grid coordinates (0, 0, 0), a corner of voxel (0, 0, 0).
  const Vector& origin() const { return m_origin; }
  /// Axis `i` (0, 1 or 2), a unit vector in world coordinates.
  const Vector& axis(int i) const { return m_axes[i]; }
  /// The edge length of a voxel, in world units.
  double voxel_size() const { return m_voxel_size; }

  /// The world point of grid coordinates `g` (unit: voxels).
  Vector to_world(const Vector& g) const
  {
    Vector p = m_origin;
    for(int i = 0; i < 3; ++i)
      for(int c = 0; c < 3; ++c)
        p[c] += m_voxel_size * g[i] * m_axes[i][c];
    return p;
  }
  /// The grid coordinates (unit: voxels) of the world point `p`, rounded to the nearest
  /// multiple of `grid_quantum`.
  ///
  /// The rounding makes the grid coordinates of a mesh the same whatever its scale and
  /// placement: scaled by 0.01 or 1000, its points' grid coordinates differ from the
  /// original's by a few units in the last place, which would otherwise move the odd
  /// vertex or triangle corner across a voxel's face; rounded, they are equal (unless one
  /// lies within that difference of a rounding boundary, about once in 10^8 coordinates),
  /// and so is everything computed from them.
  Vector to_grid(const Vector& p) const
  {
    const Vector d{p[0] - m_origin[0], p[1] - m_origin[1], p[2] - m_origin[2]};
    return Vector{quantized(internal::dot3(d, m_axes[0])), quantized(internal::dot3(d, m_axes[1])),
                  quantized(internal::dot3(d, m_axes[2]))};
  }
  /// The step to which to_grid() rounds grid coordinates, 2^-20 voxels: far below any
  /// distance the stages tell apart, far above the rounding errors of a scaling.
  static constexpr double grid_quantum = 1. / (1 << 20);
  /// The world point at the centre of voxel `k`.
  Vector centre(const Voxel_key& k) const
  {
    return to_world(Vector{k.x + 0.5, k.y + 0.5, k.z + 0.5});
  }
  /// The voxel containing the world point `p`.
  /// \pre `p` is finite and its grid coordinates fit in an `int`.
  Voxel_key voxel_of(const Vector& p) const
  {
    const Vector g = to_grid(p);
    return Voxel_key{int(std::floor(g[0])), int(std::floor(g[1])), int(std::floor(g[2]))};
  }

  /// `centre(k)` as a point type constructible from three coordinates (e.g. a CGAL
  /// `Point_3`).
  template <typename Point>
  Point centre_point(const Voxel_key& k) const
  {
    const Vector c = centre(k);
    return Point(c[0], c[1], c[2]);
  }

  /// Whether two frames are the same: equal origins, axes and voxel sizes.
  friend bool operator==(const Voxel_frame& a, const Voxel_frame& b)
  {
    return a.m_origin == b.m_origin && a.m_axes == b.m_axes && a.m_voxel_size == b.m_voxel_size;
  }

private:
  // The world length `w` along an axis in voxels, rounded to grid_quantum (a product, not
  // a division, per coordinate).
  double quantized(double w) const { return internal::nearest_integer(w * m_quanta_per_unit) * grid_quantum; }

  Vector m_origin{0., 0., 0.};
  std::array<Vector, 3> m_axes{Vector{1., 0., 0.}, Vector{0., 1., 0.}, Vector{0., 0., 1.}};
  double m_voxel_size = 1.;
  double m_quanta_per_unit = 1. / grid_quantum;
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_VOXEL_FRAME_H
