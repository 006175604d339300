// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_REACH_SHEET_LOBES_H
#define CGAL_GEODESIC_SKELETON_REACH_SHEET_LOBES_H

/// \file reach_sheet_lobes.h
/// Extends a thinned voxel skeleton into the lobes of a thick plate that thinning burns
/// away: a starfish, a cushion, a flat body with stubby limbs, whose medial sheet burns
/// from its rim inwards and leaves a point or a short line.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/reach_sheet_lobes/sheet_lobes.h>
#include <CGAL/Geodesic_skeleton/internal/thin/grassfire.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// What `reach_sheet_lobes()` did.
struct Sheet_lobes_report
{
  std::size_t sheet_voxels = 0;  ///< thick medial-sheet voxels joined to the skeleton through the sheet
  std::size_t lobes_reached = 0; ///< paths added, one per lobe tip
  std::size_t voxels_added = 0;  ///< skeleton voxels the paths added
};

/// \ingroup PkgGeodesicSkeletonRef
/// Adds to a thinned voxel skeleton a path into every lobe of the solid's thick medial
/// sheet that the skeleton's medial balls leave out by more than `sheet_lobe_reach_factor`
/// times the largest MAT radius of its piece.
///
/// Distance-ordered thinning burns a thick plate whose thickness tapers towards its rim (a
/// starfish, a cushion, a lens-shaped body with stubby limbs) from the rim inwards, level by
/// level of distance: no curve ever forms in the plate's lobes, and the plate thins to a
/// point or a short line, which the balls of the skeleton do not reach the lobes from. The
/// *medial sheet* here is the set of solid voxels outside thin parts (squared distance above
/// that of `thin_part_radius`) whose medial ball is maximal as the thinning judges a curve's
/// end (no voxel one or two steps away along the 26 directions has a radius larger by 0.6
/// per unit step, `tip_growth_when_choosing`), joined to the skeleton through such voxels
/// (26-adjacency). A sheet voxel `s` is out of reach by `min over skeleton voxels t of
/// |s - t| - r(t)` (r the MAT radius, in voxels). While some sheet voxel is out of reach by
/// at least `sheet_lobe_reach_factor` times the largest MAT radius R of the skeleton piece
/// it is joined to, the one farthest in units of R (ties: smallest key) becomes a lobe tip:
/// the path of least `sum of step / r^2` through the solid from it to the skeleton (a path
/// along the middle of the plate) joins the skeleton, and the reach of the other sheet
/// voxels is measured again with it. Thin sheets (wings, capes) are not searched: thinning
/// burns them by direction and keeps their middle curves already, and their MAT radius,
/// their half thickness, does not say how far their balls reach.
///
/// In `extract_control_skeleton()` this runs after `thin()`, on the same grid (that of the
/// level of detail), before `remove_small_pieces()`; pruning then judges the new branches as
/// any other. The paths are 26-paths; where one meets the skeleton it may leave the little
/// triangles of voxels that thinning leaves at junctions, which `to_graph()` removes.
///
/// \tparam VoxelSet a model of `VoxelSet` with `insert()` (`Dense_voxel_grid`,
///         `Sparse_voxel_set`).
/// \tparam VoxelDistanceField a model of `VoxelDistanceField` (`Voxel_distance_field`).
/// \param skeleton a voxel skeleton thinned from the solid of `distances` (`thin()`); the
///        paths are added to it.
/// \param distances the distance field of the solid (`distance_transform()`): its non-zero
///        voxels are the solid.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{sheet_lobe_reach_factor}
///     \cgalParamDescription{how far out of the skeleton's balls a lobe of the medial sheet
///                           reaches, in largest MAT radii of its piece, for a path into it;
///                           in [0, 100], 0 adds none (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{thin_part_radius}
///     \cgalParamDescription{the MAT radius (voxels) up to which a voxel is in a thin part
///                           and not searched, as in `thin()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{sqrt 2}
///   \cgalParamNEnd
///   \cgalParamNBegin{memory_limit}
///     \cgalParamDescription{the most memory (MiB) the search may use}
///     \cgalParamType{`double`}
///     \cgalParamDefault{see section \ref manual_named_parameters}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the sheet searched and the paths added.
/// \throws std::invalid_argument when a parameter is out of range, `std::length_error`
///         when the search's arrays would exceed `memory_limit`.
///
/// \b Complexity: for B voxels in the field's box, M sheet voxels, S skeleton voxels and L
///    lobes: O(B) memory and time to set up, O(M (1 + S) + L (M P + B log B)) for P voxels
///    per path (each path's search visits at most the box).
template <typename VoxelSet, typename VoxelDistanceField,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Sheet_lobes_report reach_sheet_lobes(VoxelSet& skeleton, const VoxelDistanceField& distances,
                                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const char* caller = "reach_sheet_lobes";
  const double reach_factor = internal::checked_parameter(
      parameter_ranges::sheet_lobe_reach_factor,
      choose_parameter(get_parameter(np, internal_np::sheet_lobe_reach_factor_tag),
                       parameter_ranges::sheet_lobe_reach_factor.default_value),
      caller);
  const double thin_part_radius = internal::checked_parameter(
      parameter_ranges::thin_part_radius,
      choose_parameter(get_parameter(np, internal_np::thin_part_radius_tag),
                       parameter_ranges::thin_part_radius.default_value),
      caller);
  Sheet_lobes_report report;
  if(reach_factor == 0 || skeleton.size() == 0)
    return report;
  const internal::Grid_layout layout(distances.box());
  // The ridge test reads the distances up to ridge_reach_in_steps beyond the box.
  const internal::Grid_layout padded(distances.box().grown(int(internal::ridge_reach_in_steps)));
  // Per box voxel: its label and piece (4 bytes each), and a path search's cost and
  // predecessor (12); per voxel of the padded box, its squared distance (4).
  internal::require_memory(20. * double(layout.volume()) + 4. * double(padded.volume()), internal::memory_limit(np),
                           padded, caller, "searching the medial sheet");
  internal::Sheet_lobe_search<VoxelDistanceField> search(distances, layout, padded,
                                                         internal::thin_part_d2(thin_part_radius));
  search.run(skeleton, reach_factor, report.sheet_voxels, report.lobes_reached, report.voxels_added);
  return report;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_REACH_SHEET_LOBES_H
