// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_THIN_H
#define CGAL_GEODESIC_SKELETON_THIN_H

/// \file thin.h
/// Distance-ordered homotopic thinning (the grassfire): a solid to a one-voxel-thick curve
/// skeleton with the same topology.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/thin/grassfire.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// How far apart, in voxels, two levels of distance to the outside may be for
/// `Voxel_skeleton::slanted_sheet_radii` to read their rounds together: half a voxel. The middle of
/// a slanted plate about eight voxels thick (anchor.off's at the default resolution) lies
/// on levels 3.61, 3.74, 4.00 and 4.12 voxels deep, each next to one within the band.
inline constexpr double slanted_sheet_depth_band = 0.5;

/// \ingroup PkgGeodesicSkeletonRef
/// The `thin_part_radius` that `extract_control_skeleton()` gives `thin()`: sqrt(2) voxels
/// (a part about two voxels thick) at the default resolution (`default_voxel_resolution`)
/// and below, and in proportion to the resolution above it, so that a part counts as thin
/// at every resolution when it does at the default one: sqrt(2) max(1, `resolution` / 64)
/// voxels, 2 sqrt(2) at 128. On a grid twice as fine a wing is twice as many voxels thick;
/// with a thin-part radius in voxels its middle layer is left the stair steps of the grid
/// and thins to a comb of chains, not to the wing's own middle curve.
/// \param resolution the resolution of the voxel grid (`resolution` named parameter).
///
/// \b Complexity: O(1).
inline double default_thin_part_radius(int resolution)
{
  const double default_radius = parameter_ranges::thin_part_radius.default_value;
  return default_radius * (std::max)(1.0, double(resolution) / double(default_voxel_resolution));
}

namespace internal {

// thin(), and the radii of the voxels kept written to `skeleton` when it is not null.
template <typename VoxelSet, typename VoxelDistanceField, typename NamedParameters>
std::size_t thin_recording(VoxelSet& voxels, const VoxelDistanceField& distances, const NamedParameters& np,
                           Voxel_skeleton* skeleton)
{
  const char* caller = "thin";
  const double thin_part_radius = checked_parameter(
      parameter_ranges::thin_part_radius,
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::thin_part_radius_tag),
                                         parameter_ranges::thin_part_radius.default_value),
      caller);
  const Voxel_box box = require_nonempty_box(voxels, 2, caller);
  const Grid_layout layout(box);
  const bool records_sheet_radii = skeleton != nullptr;
  const double bytes_per_box_voxel = records_sheet_radii ? 7. : 5.; // + the 16-bit rounds of sheet_radius()
  // Per voxel of the set, at most: its place in the order, a round's queue and candidates
  // (4 bytes each), and the work lists of the parallel deletions (16).
  require_memory(bytes_per_box_voxel * double(layout.volume()) + 28. * double(voxels.size()), memory_limit(np),
                 layout, caller, "thinning a box");

  const std::vector<std::uint32_t> copied_d2 = distances_over(distances, layout);
  const std::uint32_t* d2 = copied_d2.data();

  std::vector<std::uint8_t> state = to_bytes(voxels, layout);
  const std::uint32_t largest_thin_d2 = thin_part_d2(thin_part_radius);
  const std::vector<std::uint32_t> order = sorted_by_burning_level(state, d2, layout, largest_thin_d2);
  Grassfire fire(layout, std::move(state), d2, largest_thin_d2, records_sheet_radii);
  const std::size_t removed = fire.run(order);
  for_each_cell(layout, [&](std::size_t i, const Voxel_key& k) {
    if(fire.deleted(i))
      voxels.erase(k);
  });
  if(skeleton != nullptr)
  {
    *skeleton = Voxel_skeleton();
    skeleton->voxels.reset(voxels.frame(), voxels.bounding_box());
    skeleton->radius_voxel_size = voxels.frame().voxel_size();
    skeleton->sheet_radii.reserve(voxels.size());
    skeleton->slanted_sheet_radii.reserve(voxels.size());
    voxels.for_each([&](const Voxel_key& k) {
      const std::size_t i = layout.index(k);
      skeleton->voxels.insert(k);
      skeleton->sheet_radii.emplace(k, fire.sheet_radius(i));
      skeleton->slanted_sheet_radii.emplace(k, fire.sheet_radius(i, slanted_sheet_depth_band));
    });
  }
  return removed;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Thins `voxels` to a one-voxel-thick curve skeleton by distance-ordered homotopic
/// thinning (the grassfire of Blum, in the discrete form of Pudney 1998): the voxels are
/// visited by increasing distance to the outside, and a voxel is deleted when it is
/// <i>simple</i> (its deletion changes no component, cavity or tunnel) and is not the end
/// of a curve on the medial axis. The result has as many 26-components, tunnels and
/// cavities as the input, and lies on the ridge of the distance field, within about a
/// voxel. In a thin part (a wing, a fin, a thin tube: about two voxels thick, or up to
/// `thin_part_radius`) the distance is flat, and the voxels there burn by face direction
/// from the part's rim, so that a thin sheet keeps its middle curve, not one along its rim
/// or its stair steps in the grid. The method (the protection of curve ends, the rounds of
/// a level, thin parts, the guarantees, the simple-point test) is described in the manual,
/// section \ref manual_thin.
///
/// \tparam VoxelSet a model of `VoxelSet`. Whatever the model, the set is copied into a
///         dense array of bytes over its bounding box grown by two voxels, thinned there,
///         and the deleted voxels are then erased from the set.
/// \tparam VoxelDistanceField a model of `VoxelDistanceField` (`Voxel_distance_field`);
///         its values over that box are copied into a dense array too.
/// \param voxels the solid, thinned in place (voxels are only erased).
/// \param distances its distance field, from `distance_transform(voxels)` (a voxel outside
///        the field's box has distance 0 and burns first).
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{memory_limit}
///     \cgalParamDescription{the most memory the function may allocate, in bytes (package
///                           parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_voxel_memory_limit`, 2 GiB}
///     \cgalParamExtra{The need, about 5 bytes per voxel of the set's bounding box (grown
///                     by two voxels; 7 when a `Voxel_skeleton` receives the sheet radii)
///                     plus at most 28 per voxel of the set, is checked before allocating.}
///   \cgalParamNEnd
///   \cgalParamNBegin{thin_part_radius}
///     \cgalParamDescription{the largest MAT radius of a thin part, in voxels, in [0, 1000]:
///                           a voxel is in a thin part when it and its 26 neighbours are
///                           within this distance of the outside; there the voxels burn by
///                           face direction, and the middle voxels of a slanted sheet's
///                           stair steps (no deeper neighbour, less than half a voxel deeper
///                           than a neighbour) burn with the sheet (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{sqrt(2), a part about two voxels thick; `extract_control_skeleton()`
///                       gives `default_thin_part_radius()`, in proportion to the resolution}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of voxels erased.
/// \pre `voxels` is not empty.
/// \throws std::invalid_argument when `voxels` is empty or `thin_part_radius` is out of range.
/// \throws std::length_error when the work arrays would need more than `memory_limit`.
///
/// \b Complexity: O(B + N) time and memory for B voxels in the set's bounding box and N in
///    the set (each deletion re-queues at most 26 neighbours; the distances are sorted by
///    counting).
template <typename VoxelSet, typename VoxelDistanceField,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t thin(VoxelSet& voxels, const VoxelDistanceField& distances,
                 const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::thin_recording(voxels, distances, np, nullptr);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Thins `voxels` as `thin(voxels, distances, np)` does and sets `skeleton` to the voxels
/// kept with their radii (`Voxel_skeleton::sheet_radii` and `slanted_sheet_radii`, in
/// voxels of this grid, whose voxel size becomes `radius_voxel_size`); the skeleton's other
/// members are cleared. This is the skeleton that the later voxel stages read.
///
/// \tparam VoxelSet,VoxelDistanceField,NamedParameters as for the other overload.
/// \param voxels the solid, thinned in place (voxels are only erased).
/// \param distances its distance field, from `distance_transform(voxels)`.
/// \param skeleton receives the voxels kept and their radii.
/// \param np the named parameters of the other overload.
/// \returns the number of voxels erased.
/// \pre `voxels` is not empty.
/// \throws as the other overload does.
///
/// \b Complexity: that of the other overload, plus two expected O(1) hash insertions and one
///    insertion into `skeleton.voxels` per voxel kept.
template <typename VoxelSet, typename VoxelDistanceField,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t thin(VoxelSet& voxels, const VoxelDistanceField& distances, Voxel_skeleton& skeleton,
                 const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::thin_recording(voxels, distances, np, &skeleton);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_THIN_H
