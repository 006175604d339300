// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_SKELETON_RADIUS_IN_VOXELS_MAP_H
#define CGAL_GEODESIC_SKELETON_SKELETON_RADIUS_IN_VOXELS_MAP_H

/// \file Skeleton_radius_in_voxels_map.h
/// The radii of a thinned skeleton's voxels beside their MAT radius, as property maps: the
/// sheet radius that `thin()` records, and the radius by which pruning judges a voxel
/// skeleton, the MAT radius or in a thin sheet the sheet's half width.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <unordered_map>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The sheet radii that `thin()` records through its `sheet_radius_map` (voxels kept by
/// the thinning to their sheet radius, in voxels).
using Sheet_radii = std::unordered_map<Voxel_key, double, Voxel_key_hash>;

/// \ingroup PkgGeodesicSkeletonRef
/// A readable property map from a skeleton voxel to its sheet radius in `Sheet_radii`, 0
/// for a voxel that has none: the `sheet_radius_map` that `extract_control_skeleton()`
/// gives `prune_skeleton()`. It refers to the radii, which must outlive it.
struct Sheet_radius_in_voxels_map
{
  using key_type = Voxel_key;                        ///< a skeleton voxel
  using value_type = double;                         ///< its sheet radius, in voxels
  using reference = double;                          ///< returned by value
  using category = boost::readable_property_map_tag; ///< readable only

  const Sheet_radii* sheet_radii = nullptr; ///< the sheet radii read (none when null)

  /// The sheet radius of `k` in voxels, 0 when it has none.
  friend double get(const Sheet_radius_in_voxels_map& map, const Voxel_key& k)
  {
    if(map.sheet_radii == nullptr)
      return 0.;
    const auto sheet = map.sheet_radii->find(k);
    return sheet == map.sheet_radii->end() ? 0. : sheet->second;
  }
};

/// \ingroup PkgGeodesicSkeletonRef
/// The sheet radii of `sheet_radii` as a property map (see `Sheet_radius_in_voxels_map`).
/// \param sheet_radii the sheet radii of thinned voxels, from `thin()`'s `sheet_radius_map`.
/// \pre `sheet_radii` outlives the map (it refers to them).
///
/// \b Complexity: O(1) to make; each `get()` is one expected O(1) hash lookup.
inline Sheet_radius_in_voxels_map sheet_radius_in_voxels_map(const Sheet_radii& sheet_radii)
{
  return Sheet_radius_in_voxels_map{&sheet_radii};
}

/// \ingroup PkgGeodesicSkeletonRef
/// A readable property map from a skeleton voxel to the larger of its MAT radius in voxels
/// (`Mat_radius_in_voxels_map`) and its sheet radius (`Sheet_radii`, 0 for a voxel that
/// has none): the radius by which `prune_skeleton()` judges a twig when it is given both
/// maps (its `mat_radius_map` and `sheet_radius_map`). Inside a thin sheet the MAT radius is the sheet's half thickness,
/// about a voxel, which every twig of the sheet outgrows; the sheet radius is its half
/// width, so that pruning judges a sheet's twigs by the sheet's width. In a limb or a body,
/// where the sheet radius is about 1, this is the MAT radius. It is not the radius of a
/// ball: give `prune_skeleton()` the two maps apart, so that it also knows the MAT balls.
/// It refers to the field and the radii, which must outlive it.
struct Skeleton_radius_in_voxels_map
{
  using key_type = Voxel_key;                        ///< a skeleton voxel
  using value_type = double;                         ///< its radius, in voxels
  using reference = double;                          ///< returned by value
  using category = boost::readable_property_map_tag; ///< readable only

  const Voxel_distance_field* field = nullptr; ///< the distance field read
  const Sheet_radii* sheet_radii = nullptr;    ///< the sheet radii read (none when null)

  /// The radius of `k` in voxels.
  friend double get(const Skeleton_radius_in_voxels_map& map, const Voxel_key& k)
  {
    return (std::max)(get(Mat_radius_in_voxels_map{map.field}, k),
                      get(Sheet_radius_in_voxels_map{map.sheet_radii}, k));
  }
};

/// \ingroup PkgGeodesicSkeletonRef
/// The larger of the MAT radius of `field` and the sheet radius of `sheet_radii` at each
/// voxel, as a property map (see `Skeleton_radius_in_voxels_map`).
/// \param field the distance field of the solid, from `distance_transform()`.
/// \param sheet_radii the sheet radii of its thinned voxels, from `thin()`'s
///        `sheet_radius_map` (a voxel without one reads its MAT radius).
/// \pre `field` and `sheet_radii` outlive the map (it refers to them).
///
/// \b Complexity: O(1) to make; each `get()` is one read of the field and one expected
///    O(1) hash lookup.
inline Skeleton_radius_in_voxels_map skeleton_radius_in_voxels_map(const Voxel_distance_field& field,
                                                                   const Sheet_radii& sheet_radii)
{
  return Skeleton_radius_in_voxels_map{&field, &sheet_radii};
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_SKELETON_RADIUS_IN_VOXELS_MAP_H
