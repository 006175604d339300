// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_REMOVE_SMALL_PIECES_H
#define CGAL_GEODESIC_SKELETON_REMOVE_SMALL_PIECES_H

/// \file remove_small_pieces.h
/// Removes the small detached pieces of a solid (a character's loose eyes, teeth, buttons)
/// so that the skeleton has one tree per body.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// What `remove_small_pieces()` found.
struct Small_pieces_report
{
  std::size_t pieces = 0;         ///< 26-connected components of the solid
  std::size_t removed_pieces = 0; ///< the small ones, removed
  std::size_t removed_voxels = 0; ///< their voxels
};

/// \ingroup PkgGeodesicSkeletonRef
/// Removes from a solid its small detached pieces: the 26-connected components with fewer
/// than `small_piece_fraction` times the voxels of the largest one. A character as artists
/// make it has parts that float free of the body (eyes, teeth, a buckle, strands of hair);
/// each would otherwise get its own little skeleton tree. Pieces that overlap or touch the
/// body (within a voxel) are part of its component already and stay. In
/// `extract_control_skeleton()`, the mesh vertices of a removed piece map to the nearest
/// point of the body's skeleton, so that the piece follows the body it belongs to.
///
/// \tparam VoxelSet a model of `VoxelSet`.
/// \param voxels the solid (`voxelize()`); the small pieces leave it.
/// \param np optional named parameters among:
///   - `small_piece_fraction` (package parameter, `double`, in [0, 1]): the size, relative
///     to the largest piece, under which a piece is removed (default 0.05; 0 keeps every
///     piece).
///   - `memory_limit` (package parameter, `double`, bytes): the most memory the function
///     may allocate (default: 2 GiB); the need, 4 bytes per voxel of the set's box, is
///     checked before allocating.
///
/// \returns the number of pieces and what was removed.
/// \throws std::invalid_argument when `small_piece_fraction` is out of range.
/// \throws std::length_error when the work array would need more than `memory_limit`.
///
/// \b Complexity: O(N + B) for N voxels in the set and B in its box.
template <typename VoxelSet, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Small_pieces_report remove_small_pieces(VoxelSet& voxels,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const char* caller = "remove_small_pieces";
  const double fraction = internal::checked_parameter(
      parameter_ranges::small_piece_fraction,
      choose_parameter(get_parameter(np, internal_np::small_piece_fraction_tag),
                       parameter_ranges::small_piece_fraction.default_value),
      caller);
  Small_pieces_report report;
  if(voxels.size() == 0)
    return report;
  const internal::Grid_layout layout(internal::require_nonempty_box(voxels, 1, caller));
  internal::require_memory(4. * double(layout.volume()), internal::memory_limit(np, caller), layout, caller,
                           "the pieces of a solid in a box");

  // Label the 26-connected components by a flood from each unlabelled voxel.
  std::vector<std::int32_t> piece(layout.volume(), -1);
  const std::int32_t unlabelled = -2;
  voxels.for_each([&](const Voxel_key& k) { piece[layout.index(k)] = unlabelled; });
  std::vector<std::size_t> sizes;
  std::vector<std::uint32_t> stack;
  const auto offsets = layout.neighbour_offsets();
  voxels.for_each([&](const Voxel_key& k) {
    const std::size_t start = layout.index(k);
    if(piece[start] != unlabelled)
      return;
    const std::int32_t label = std::int32_t(sizes.size());
    sizes.push_back(0);
    piece[start] = label;
    stack.push_back(std::uint32_t(start));
    while(!stack.empty())
    {
      const std::size_t i = stack.back();
      stack.pop_back();
      ++sizes.back();
      for(std::ptrdiff_t o : offsets) // the margin of one voxel keeps neighbours in the box
      {
        const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
        if(piece[j] == unlabelled)
        {
          piece[j] = label;
          stack.push_back(std::uint32_t(j));
        }
      }
    }
  });
  report.pieces = sizes.size();
  const std::size_t largest = *std::max_element(sizes.begin(), sizes.end());
  std::vector<bool> small(sizes.size());
  for(std::size_t p = 0; p < sizes.size(); ++p)
  {
    small[p] = double(sizes[p]) < fraction * double(largest);
    report.removed_pieces += small[p];
  }
  if(report.removed_pieces == 0)
    return report;
  std::vector<Voxel_key> removed;
  voxels.for_each([&](const Voxel_key& k) {
    if(small[std::size_t(piece[layout.index(k)])])
      removed.push_back(k);
  });
  for(const Voxel_key& k : removed)
    voxels.erase(k);
  report.removed_voxels = removed.size();
  return report;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_REMOVE_SMALL_PIECES_H
