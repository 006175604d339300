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
/// Thins `voxels` to a one-voxel-thick curve skeleton by distance-ordered homotopic
/// thinning (the grassfire of Blum, in the discrete form of Pudney 1998): the voxels are
/// visited by increasing distance to the outside, and a voxel is deleted when it is
/// <i>simple</i> (26-connectivity for the set, 6-connectivity for the background: its
/// deletion changes no component, cavity or tunnel) and is not the end of a curve on the
/// medial axis (a voxel with exactly one neighbour, whose medial ball no nearby ball
/// swallows: no voxel `q` one or two steps away along the 26 directions has
/// `r(q) >= r(p) + 0.6 |q - p|`, so a branch ends about a radius before a rounded tip, and
/// the medial sheets of blunt edges, whose radius grows by 0.71 per unit step, burn away).
/// Each level of distance burns in rounds: the candidates of a round are the voxels simple
/// (and not protected) at its start, deleted one by one if they still are simple, unless
/// they have become an end point whose radius no nearby voxel exceeds by 0.3 per unit step:
/// so the order of deletions inside a level leaves no hair at the corners of the shape. A
/// deletion puts the neighbours back into the current level's queue, so the fire burns
/// until nothing simple is left.
///
/// Guarantees: the result has as many 26-components, tunnels (independent cycles) and
/// cavities as the input (only simple voxels are deleted, one at a time); every remaining
/// voxel is either not simple or a curve end point (exactly one 26-neighbour) whose medial
/// ball is maximal among its neighbours', so the result is thin; since deep voxels burn
/// last, the skeleton lies on the ridge of the distance field, within about a voxel. A
/// shape without tunnels or cavities thins to a tree, a ball to a single voxel.
///
/// The simple-point test grows components on the 27-bit mask of the 3 x 3 x 3 cube, each
/// growth step a handful of shifts, at most a few dozen steps whatever the neighbourhood
/// (see the benchmark for its measured time): constant time.
///
/// \tparam VoxelSet a model of `VoxelSet`. Whatever the model, the set is copied into a
///         dense array of bytes over its bounding box grown by two voxels, thinned there,
///         and the deleted voxels are then erased from the set.
/// \tparam VoxelDistanceField a model of `VoxelDistanceField` (`Voxel_distance_field`);
///         its values over that box are copied into a dense array too.
/// \param voxels the solid, thinned in place (voxels are only erased).
/// \param distances its distance field, from `distance_transform(voxels)` (a voxel outside
///        the field's box has distance 0 and burns first).
/// \param np optional named parameters among:
///   - `memory_limit` (package parameter, `double`, bytes): the most memory the function
///     may allocate (default: `default_voxel_memory_limit`, 2 GiB); the need, about
///     5 bytes per voxel of the set's bounding box (grown by two voxels) plus 12 per voxel
///     of the set, is
///     checked before allocating.
///
/// \returns the number of voxels erased.
/// \pre `voxels` is not empty.
/// \throws std::invalid_argument when `voxels` is empty.
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
  const char* caller = "thin";
  const Voxel_box box = internal::require_nonempty_box(voxels, 2, caller);
  const internal::Grid_layout layout(box);
  internal::require_memory(5. * double(layout.volume()) + 12. * double(voxels.size()),
                           internal::memory_limit(np), layout, caller, "thinning a box");

  const std::vector<std::uint32_t> copied_d2 = internal::distances_over(distances, layout);
  const std::uint32_t* d2 = copied_d2.data();

  std::vector<std::uint8_t> state = internal::to_bytes(voxels, layout);
  const std::vector<std::uint32_t> order = internal::sorted_by_distance(state, d2);
  internal::Grassfire fire(layout, std::move(state), d2);
  const std::size_t removed = fire.run(order);
  internal::for_each_cell(layout, [&](std::size_t i, const Voxel_key& k) {
    if(fire.deleted(i))
      voxels.erase(k);
  });
  return removed;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_THIN_H
