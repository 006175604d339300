// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_VOXEL_DISTANCE_FIELD_H
#define CGAL_GEODESIC_SKELETON_VOXEL_DISTANCE_FIELD_H

/// \file Voxel_distance_field.h
/// The result of `distance_transform()`: the radius function of the voxel medial axis.

#include <boost/property_map/property_map.hpp>

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The squared Euclidean distance (unit: squared voxels) from every voxel of a solid to
/// the nearest voxel outside it, stored densely over a box that contains the solid and one
/// layer of outside voxels around it. A voxel outside the box or outside the solid has
/// distance 0. Built by `distance_transform()`; copyable, O(1) queries.
///
/// \cgalModels `VoxelDistanceField`
class Voxel_distance_field
{
public:
  Voxel_distance_field() = default;

  /// Takes the squared distances `values` over `box` (x fastest, then y, then z).
  /// \pre `values.size() == box.volume()`.
  Voxel_distance_field(const Voxel_frame& frame, const Voxel_box& box,
                       std::vector<std::uint32_t> values)
    : m_frame(frame), m_layout(box), m_values(std::move(values))
  {
    if(m_values.size() != m_layout.volume())
      throw std::invalid_argument("Voxel_distance_field: values.size() != box.volume()");
  }

  /// The frame of the voxel set it was computed from.
  const Voxel_frame& frame() const { return m_frame; }
  /// The box over which the distances are stored.
  const Voxel_box& box() const { return m_layout.box; }

  /// The squared distance (squared voxels) from the centre of `k` to the centre of the
  /// nearest voxel outside the solid; 0 when `k` is not in the solid.
  std::uint32_t squared_distance(const Voxel_key& k) const
  {
    return m_layout.box.contains(k) ? m_values[m_layout.index(k)] : 0u;
  }
  /// Whether `k` is in the solid (its distance is positive).
  bool inside(const Voxel_key& k) const { return squared_distance(k) != 0; }

  /// The radius of the medial ball at `k`, in world units: an estimate of the distance from
  /// the centre of `k` to the surface, `voxel_size * (sqrt(squared_distance(k)) - 1/2)`
  /// (the boundary lies between the last solid voxel and the first outside one); 0 when
  /// `k` is not in the solid.
  double radius(const Voxel_key& k) const
  {
    const std::uint32_t d2 = squared_distance(k);
    return d2 == 0 ? 0. : m_frame.voxel_size() * (std::sqrt(double(d2)) - 0.5);
  }

  /// The largest squared distance of the field.
  std::uint32_t max_squared_distance() const
  {
    return m_values.empty() ? 0u : *std::max_element(m_values.begin(), m_values.end());
  }

  /// The raw values, x fastest, then y, then z over `box()`.
  const std::vector<std::uint32_t>& values() const { return m_values; }

private:
  Voxel_frame m_frame;
  internal::Grid_layout m_layout;
  std::vector<std::uint32_t> m_values;
};

/// \ingroup PkgGeodesicSkeletonRef
/// A readable property map from `Voxel_key` to the MAT radius of a voxel in voxels,
/// `Voxel_distance_field::radius()` divided by the voxel size (`sqrt(squared_distance) -
/// 1/2`, 0 outside the solid): the `mat_radius_map` that `extract_control_skeleton()`
/// gives `prune_skeleton()`. It refers to the field, which must outlive it.
struct Mat_radius_in_voxels_map
{
  using key_type = Voxel_key;                        ///< a voxel
  using value_type = double;                         ///< its radius, in voxels
  using reference = double;                          ///< returned by value
  using category = boost::readable_property_map_tag; ///< readable only

  const Voxel_distance_field* field = nullptr; ///< the distance field read

  /// The radius of `k` in voxels.
  friend double get(const Mat_radius_in_voxels_map& map, const Voxel_key& k)
  {
    return map.field->radius(k) / map.field->frame().voxel_size();
  }
};

/// \ingroup PkgGeodesicSkeletonRef
/// The MAT radii of `field`'s voxels in voxels, as a property map (see
/// `Mat_radius_in_voxels_map`).
inline Mat_radius_in_voxels_map mat_radius_in_voxels_map(const Voxel_distance_field& field)
{
  return Mat_radius_in_voxels_map{&field};
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_VOXEL_DISTANCE_FIELD_H
