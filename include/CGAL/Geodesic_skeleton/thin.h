// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_THIN_H
#define CGAL_GEODESIC_SKELETON_THIN_H

/// \file thin.h
/// Distance-ordered homotopic thinning (the grassfire): a solid to a one-voxel-thick curve
/// skeleton with the same topology.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/thin/grassfire.h>
#include <CGAL/Geodesic_skeleton/internal/thin/simple_point.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// How far apart, in voxels, two levels of distance to the outside may be for `thin()`'s
/// `slanted_sheet_radius_map` to read their rounds together: half a voxel. The middle of
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
///                     by two voxels; 7 with a `sheet_radius_map` or a
///                     `slanted_sheet_radius_map`) plus at most 28 per
///                     voxel of the set, is checked before allocating.}
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
///   \cgalParamNBegin{sheet_radius_map}
///     \cgalParamDescription{receives the <i>sheet radius</i> of every voxel that the thinning
///                           keeps, in voxels: the number of rounds that its level of
///                           distance burnt around it. Where the distance to the outside is
///                           flat, as inside a thin sheet (a wing, a fin, an ear, a plate),
///                           a level is the whole sheet and its rounds burn it from the rim
///                           inwards, one voxel step each, so this is the distance to the
///                           sheet's rim measured in the sheet: on the sheet's middle line,
///                           its half width, which the MAT radius (its half thickness) does
///                           not tell. Elsewhere it is 0 or about 1. `extract_control_skeleton()`
///                           gives `prune_skeleton()` the larger of the two radii as its
///                           `mat_radius_map` (`skeleton_radius_in_voxels_map()`), so that the
///                           twigs of a sheet are judged by its width, not its thickness
///                           (package parameter)}
///     \cgalParamType{a model of `WritablePropertyMap` with key `Voxel_key` and value
///                    `double`, such as `boost::associative_property_map<Sheet_radii>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{slanted_sheet_radius_map}
///     \cgalParamDescription{receives, for every voxel that the thinning keeps, its sheet
///                           radius read across close levels: the latest round in which a
///                           26-neighbour was deleted whose distance to the outside is within
///                           `slanted_sheet_depth_band` (half a voxel) of the voxel's, in
///                           voxels. The middle of a thick sheet slanted in the grid (a
///                           plate a few voxels thick) falls on several levels of distance
///                           less than half a voxel apart, side by side in strips, and each
///                           level burns its own strips: the `sheet_radius_map` measures a
///                           strip there, this reading the sheet. `extract_control_skeleton()`
///                           reads a piece's widest sheet from it on the grid of its level of
///                           detail (`widest_sheet_radius_of_pieces()`); on a finer grid the
///                           levels are denser and the band reaches across a thick block's
///                           flat levels, so there it keeps the `sheet_radius_map`.}
///     \cgalParamType{a model of `WritablePropertyMap` with key `Voxel_key` and value
///                    `double`, such as `boost::associative_property_map<Sheet_radii>`}
///     \cgalParamDefault{none}
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
///    counting), plus one write to the `sheet_radius_map` and one to the
///    `slanted_sheet_radius_map` per voxel kept.
template <typename VoxelSet, typename VoxelDistanceField,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t thin(VoxelSet& voxels, const VoxelDistanceField& distances,
                 const NamedParameters& np = CGAL::parameters::default_values())
{
  const char* caller = "thin";
  const double thin_part_radius = internal::checked_parameter(
      parameter_ranges::thin_part_radius,
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::thin_part_radius_tag),
                                         parameter_ranges::thin_part_radius.default_value),
      caller);
  const Voxel_box box = internal::require_nonempty_box(voxels, 2, caller);
  const internal::Grid_layout layout(box);
  constexpr bool writes_sheet_radii =
      !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::sheet_radius_map_t>::value;
  constexpr bool writes_slanted_sheet_radii =
      !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::slanted_sheet_radius_map_t>::value;
  constexpr bool records_sheet_radii = writes_sheet_radii || writes_slanted_sheet_radii;
  const double bytes_per_box_voxel = records_sheet_radii ? 7. : 5.; // + the 16-bit rounds of sheet_radius()
  // Per voxel of the set, at most: its place in the order, a round's queue and candidates
  // (4 bytes each), and the work lists of the parallel deletions (16).
  internal::require_memory(bytes_per_box_voxel * double(layout.volume()) + 28. * double(voxels.size()),
                           internal::memory_limit(np), layout, caller, "thinning a box");

  const std::vector<std::uint32_t> copied_d2 = internal::distances_over(distances, layout);
  const std::uint32_t* d2 = copied_d2.data();

  std::vector<std::uint8_t> state = internal::to_bytes(voxels, layout);
  const std::uint32_t largest_thin_d2 = internal::thin_part_d2(thin_part_radius);
  const std::vector<std::uint32_t> order = internal::sorted_by_burning_level(state, d2, layout, largest_thin_d2);
  internal::Grassfire fire(layout, std::move(state), d2, largest_thin_d2, records_sheet_radii);
  const std::size_t removed = fire.run(order);
  internal::for_each_cell(layout, [&](std::size_t i, const Voxel_key& k) {
    if(fire.deleted(i))
      voxels.erase(k);
  });
  if constexpr(writes_sheet_radii)
  {
    auto sheet_radii = CGAL::parameters::get_parameter(np, internal_np::sheet_radius_map_tag);
    voxels.for_each([&](const Voxel_key& k) { put(sheet_radii, k, fire.sheet_radius(layout.index(k))); });
  }
  if constexpr(writes_slanted_sheet_radii)
  {
    auto slanted_sheet_radii = CGAL::parameters::get_parameter(np, internal_np::slanted_sheet_radius_map_tag);
    voxels.for_each([&](const Voxel_key& k) {
      put(slanted_sheet_radii, k, fire.sheet_radius(layout.index(k), slanted_sheet_depth_band));
    });
  }
  return removed;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_THIN_H
