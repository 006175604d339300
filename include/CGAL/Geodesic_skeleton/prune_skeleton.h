// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_PRUNE_SKELETON_H
#define CGAL_GEODESIC_SKELETON_PRUNE_SKELETON_H

/// \file prune_skeleton.h
/// The paper's pruning of a one-voxel-thick skeleton (Algorithm 1), followed by the
/// iterative snipping of spurious end branches, which is the package's addition to
/// Algorithm 1 (not in the paper).

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/prune/branched_regions.h>
#include <CGAL/Geodesic_skeleton/internal/prune/spurious_branches.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/property_map.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// What `prune_skeleton()` did.
struct Pruning_report
{
  std::size_t branched_regions = 0;          ///< branched regions found (step 3)
  std::size_t removed_branched_points = 0;   ///< branched connection points on no path (step 8)
  std::size_t snipped_branches = 0;          ///< spurious end branches snipped
  std::size_t snipped_points = 0;            ///< voxels of those branches
  std::size_t rounds = 0;                    ///< rounds of pruning and snipping that changed something
};

namespace internal {

// The radii reach the stages as std::function: those are then compiled once per voxel set
// type, not once per type of named-parameter pack and maps (a call of the chain with one
// more parameter would otherwise compile the whole of pruning again).
using Radius_of_voxel = std::function<double(const Voxel_key&)>;

inline double checked_radius(double r)
{
  if(!(r >= 0) || !std::isfinite(r))
    throw std::invalid_argument("prune_skeleton: the MAT radius map gives a negative or non-finite radius");
  return r;
}

template <typename NamedParameters>
Spur_thresholds pruning_thresholds(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double factor = checked_parameter(parameter_ranges::spur_length_factor,
                                          choose_parameter(get_parameter(np, internal_np::spur_length_factor_tag),
                                                           parameter_ranges::spur_length_factor.default_value),
                                          "prune_skeleton");
  const double protrusion_factor = checked_parameter(
      parameter_ranges::limb_protrusion_factor,
      choose_parameter(get_parameter(np, internal_np::limb_protrusion_factor_tag),
                       parameter_ranges::limb_protrusion_factor.default_value),
      "prune_skeleton");
  return Spur_thresholds{factor, protrusion_factor, {}};
}

// prune_skeleton() with its thresholds and radii: `radius` judges twigs, `mat_radius` gives
// the balls, `piece_radius` the unit of a piece's level of detail (at least its largest).
template <typename VoxelSet>
Pruning_report prune_skeleton_by(VoxelSet& skeleton, Spur_thresholds thresholds, const Radius_of_voxel& radius,
                                 const Radius_of_voxel& mat_radius, const Radius_of_voxel& piece_radius)
{
  const auto radii = snipping_radii(radius, mat_radius);
  if(thresholds.limb_protrusion_factor > 0)
    thresholds.largest_radius_of_piece = largest_radius_of_pieces(skeleton, piece_radius);
  // Snipping a twig can leave a small cluster of branched points where it hung, and
  // Algorithm 1 can turn a junction into a plain end branch: alternate the two until
  // neither changes anything.
  Pruning_report report;
  for(bool first = true;; first = false)
  {
    const Branched_region_pruning pruned = prune_branched_regions(skeleton, radius);
    if(first)
      report.branched_regions = pruned.regions;
    report.removed_branched_points += pruned.removed_points;
    Snipping snipped;
    if(thresholds.spur_length_factor > 0 || thresholds.limb_protrusion_factor > 0)
    {
      snipped = snip_spurious_branches_once(skeleton, radii, thresholds);
      if(snipped.branches == 0) // what is left that the graph, not the voxels, shows as ends
        snipped = snip_spurious_graph_branches_once(skeleton, radii, thresholds);
    }
    report.snipped_branches += snipped.branches;
    report.snipped_points += snipped.points;
    if(pruned.removed_points == 0 && snipped.branches == 0)
      break;
    ++report.rounds;
  }
  return report;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Prunes a one-voxel-thick curve skeleton in place: the paper's Algorithm 1, then the
/// snipping of spurious end branches (the package's addition to Algorithm 1, not in the
/// paper), the two repeated until nothing changes.
///
/// Algorithm 1 keeps, in each branched region (a 26-connected group of branched connection
/// points), only the voxels on the shortest paths inside the skeleton from the region's
/// centroid to its terminators. The snipping removes an end branch that is shorter than
/// `spur_length_factor` times the radius at its junction, or whose balls reach out of the
/// balls that hold them by less than `limb_protrusion_factor` times the largest radius of
/// its piece of the skeleton: out of its junction's ball (a bump, a hoof's cleft, a
/// sheet's rim) or, voxel by voxel, out of the maximal balls of the rest of the skeleton
/// that contain the voxel (a tooth of the comb of parallel curves that thinning leaves in
/// a thick sheet, a knuckle inside a fist): detail smaller than the level of detail of the
/// rig. Branches are snipped most spurious first, each while the skeleton goes on past its
/// junction and while it is still a spur once the branches before it are gone (of two
/// parallel teeth, one stays). An end branch is traced through any lump of branched points
/// that only two branches leave. When the voxels show no spur left, the same tests run on the
/// end branches of the skeleton's graph as `to_graph()` makes it, which also has ends that
/// voxel degrees hide (a voxel hanging on a lump, a tip that is a little triangle).
///
/// Both thresholds are ratios of lengths of the shape, so that the same features are kept at
/// every resolution that resolves them. The radius that judges a voxel is its MAT radius
/// (the overload for a `Voxel_skeleton` also reads the sheet radii); the balls are the MAT
/// balls. The steps are described in the manual, section \ref manual_prune_method.
///
/// The result is deterministic (it does not depend on the set's iteration order).
/// Pruning never disconnects a component (every terminator stays linked to its
/// region's centroid and a snipped branch hangs by one junction), never opens a cycle
/// that passes through a region (the cycle's two terminators stay linked through the
/// centroid) and never snips a path component (no junction).
///
/// \tparam VoxelSet a model of `VoxelSet`; read through `for_each()` and `contains()`
///         (no dense copy: the classes and the regions are kept in hash maps by key).
/// \param skeleton a one-voxel-thick skeleton, e.g. from thinning; modified in place.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{mat_radius_map}
///     \cgalParamDescription{the radius of the medial axis transform at each skeleton voxel,
///                           in voxels, e.g. the square root of the squared distance
///                           transform (`mat_radius_in_voxels_map()`): the radius of the
///                           largest ball centred there inside the shape (package parameter)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `Voxel_key` as key type and a
///                    number as value type}
///     \cgalParamDefault{1 voxel everywhere, which makes the snipping threshold an absolute
///                       length in voxels}
///   \cgalParamNEnd
///   \cgalParamNBegin{spur_length_factor}
///     \cgalParamDescription{the threshold of the snipping, in MAT radii at the junction, in
///                           [0, 100]; 0 turns snipping off (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.2}
///   \cgalParamNEnd
///   \cgalParamNBegin{limb_protrusion_factor}
///     \cgalParamDescription{the level of detail of the snipping: how far, in units of the
///                           largest radius of its piece of the skeleton, the balls of an end
///                           branch must reach out of its junction's ball and out of the MAT
///                           balls of the rest of the skeleton for the branch to stay, in
///                           [0, 100]; 0 turns this test off (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.75}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was removed, and how many rounds of snipping were made.
/// \throws std::invalid_argument when `spur_length_factor` or `limb_protrusion_factor` is
///         out of range, or a radius is negative or not finite.
///
/// \b Complexity: O(N log N + V M) for N skeleton voxels per round of snipping (one Dijkstra
/// per region, over the region; each end branch traced once), where the protrusions of the
/// end branches read V voxels (from the tip inwards, until the branch is known to stay) and
/// each compares M balls, those whose centre is within the largest MAT radius of it along
/// the third axis (O(N) at worst; a small part of the skeleton in practice); a few rounds
/// in practice; O(N) extra memory.
template <typename VoxelSet, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Pruning_report prune_skeleton(VoxelSet& skeleton,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto mat_radius_map =
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::mat_radius_map_tag),
                                         CGAL::Constant_property_map<Voxel_key, double>(1.0));
  const internal::Radius_of_voxel mat_radius = [&](const Voxel_key& k) {
    return internal::checked_radius(static_cast<double>(get(mat_radius_map, k)));
  };
  return internal::prune_skeleton_by(skeleton, internal::pruning_thresholds(np), mat_radius, mat_radius, mat_radius);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Prunes the voxels of a `Voxel_skeleton` as `prune_skeleton(skeleton.voxels, np)` does,
/// with the MAT radius of `distances` and the radii that thinning measured: a voxel's twigs
/// are judged by the larger of its MAT radius and its sheet radius (in a thin sheet, the
/// sheet's width rather than its thickness), and the largest radius of a piece, the unit of
/// `limb_protrusion_factor`, is at least the widest sheet of the piece read across close
/// levels. That widest sheet is taken first, before anything is pruned, and kept as
/// `skeleton.piece_sheet_radii`.
///
/// \param skeleton the skeleton, as `thin()` made it (its voxels pruned in place).
/// \param distances the distance field of the solid that was thinned.
/// \param np the named parameters `spur_length_factor` and `limb_protrusion_factor`, as for
///        the other overload (a `mat_radius_map` is not read: `distances` gives it).
/// \pre the radii of `skeleton` are in voxels of the grid of `distances`.
///
/// \b Complexity: that of the other overload, plus O(K log K) for the K voxels (the pieces)
///    and O(K) expected hash operations.
template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
Pruning_report prune_skeleton(Voxel_skeleton& skeleton, const Voxel_distance_field& distances,
                              const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Spur_thresholds thresholds = internal::pruning_thresholds(np); // checked before any work
  skeleton.piece_sheet_radii = internal::largest_radius_of_pieces(
      skeleton.voxels, [&](const Voxel_key& k) { return internal::radius_in(skeleton.slanted_sheet_radii, k); });
  const Mat_radius_in_voxels_map mat_radius_map = mat_radius_in_voxels_map(distances);
  const internal::Radius_of_voxel mat_radius = [&](const Voxel_key& k) { return get(mat_radius_map, k); };
  // A twig is judged by the larger of the two radii: in a thin sheet, its width.
  const internal::Radius_of_voxel radius = [&](const Voxel_key& k) {
    return (std::max)(mat_radius(k), internal::radius_in(skeleton.sheet_radii, k));
  };
  const internal::Radius_of_voxel piece_radius = [&](const Voxel_key& k) {
    return (std::max)(radius(k), internal::radius_in(skeleton.piece_sheet_radii, k));
  };
  return internal::prune_skeleton_by(skeleton.voxels, thresholds, radius, mat_radius, piece_radius);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_PRUNE_SKELETON_H
