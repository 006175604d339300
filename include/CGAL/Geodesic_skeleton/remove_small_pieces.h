// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_REMOVE_SMALL_PIECES_H
#define CGAL_GEODESIC_SKELETON_REMOVE_SMALL_PIECES_H

/// \file remove_small_pieces.h
/// Removes the skeletons of the small detached pieces of a solid (a character's loose eyes,
/// teeth, buttons), so that the skeleton has one tree per body.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>
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
  std::size_t pieces = 0;         ///< 26-connected pieces of the skeleton
  std::size_t removed_pieces = 0; ///< the small ones, removed
  std::size_t removed_voxels = 0; ///< their skeleton voxels
};

namespace internal {

// The number of voxels of the solid of `distances` (its non-zero voxels) in the
// 26-connected component of each seed, by a search from each seed not yet reached.
template <typename VoxelDistanceField>
std::vector<std::size_t> solid_piece_sizes(const VoxelDistanceField& distances, const std::vector<Voxel_key>& seeds)
{
  const Grid_layout layout(distances.box());
  std::vector<std::int32_t> piece(layout.volume(), -1);
  std::vector<std::size_t> sizes(seeds.size(), 0), size_of_piece;
  std::vector<std::uint32_t> stack;
  for(std::size_t s = 0; s < seeds.size(); ++s)
  {
    if(!distances.inside(seeds[s]))
      continue;
    const std::size_t start = layout.index(seeds[s]);
    if(piece[start] < 0)
    {
      const std::int32_t label = std::int32_t(size_of_piece.size());
      size_of_piece.push_back(0);
      piece[start] = label;
      stack.push_back(std::uint32_t(start));
      while(!stack.empty())
      {
        const Voxel_key k = layout.key(stack.back());
        stack.pop_back();
        ++size_of_piece.back();
        for(const Voxel_key& o : neighbourhood_26())
        {
          const Voxel_key n = k + o;
          if(!distances.inside(n)) // false outside the box too
            continue;
          const std::size_t j = layout.index(n);
          if(piece[j] < 0)
          {
            piece[j] = label;
            stack.push_back(std::uint32_t(j));
          }
        }
      }
    }
    sizes[s] = size_of_piece[std::size_t(piece[start])];
  }
  return sizes;
}

} // namespace internal

namespace internal {

// remove_small_pieces() once its parameter is read: compiled once per voxel set and field
// type, whatever the parameter pack.
template <typename VoxelSet, typename VoxelDistanceField>
Small_pieces_report remove_small_pieces_with(VoxelSet& skeleton, const VoxelDistanceField& distances, double fraction)
{
  Small_pieces_report report;
  std::vector<Voxel_key> keys;
  keys.reserve(skeleton.size());
  skeleton.for_each([&](const Voxel_key& k) { keys.push_back(k); });
  std::vector<std::size_t> piece_of;
  report.pieces = internal::voxel_components(keys, [&](const Voxel_key& k) { return skeleton.contains(k); }, piece_of);
  if(report.pieces <= 1 || fraction == 0)
    return report;

  // One seed per piece: its first voxel.
  std::vector<Voxel_key> seeds(report.pieces);
  std::vector<bool> seeded(report.pieces, false);
  for(std::size_t i = 0; i < keys.size(); ++i)
    if(!seeded[piece_of[i]])
    {
      seeded[piece_of[i]] = true;
      seeds[piece_of[i]] = keys[i];
    }
  const std::vector<std::size_t> sizes = internal::solid_piece_sizes(distances, seeds);
  const std::size_t largest = *std::max_element(sizes.begin(), sizes.end());
  std::vector<bool> small(report.pieces);
  for(std::size_t p = 0; p < report.pieces; ++p)
  {
    small[p] = double(sizes[p]) < fraction * double(largest);
    report.removed_pieces += small[p];
  }
  for(std::size_t i = 0; i < keys.size(); ++i)
    if(small[piece_of[i]])
    {
      skeleton.erase(keys[i]);
      ++report.removed_voxels;
    }
  return report;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Removes from a voxel skeleton its small detached pieces: the 26-connected pieces whose
/// solid (the voxels of the distance field's solid connected to them) has fewer than
/// `small_piece_fraction` times the voxels of the largest piece's solid. A character as
/// artists make it has parts that float free of the body (eyes, teeth, a buckle, strands of
/// hair); each would otherwise get its own little skeleton tree. Pieces that overlap or
/// touch the body (within a voxel) are part of its solid already and stay. In
/// `extract_control_skeleton()` (between `thin()` and `cut_spurious_cycles()`), the mesh
/// vertices of a removed piece then map to the nearest point of the body's skeleton, so that
/// the piece follows the body it belongs to.
///
/// \tparam VoxelSet a model of `VoxelSet`; read through `for_each()` and `contains()` only
///         (no dense copy).
/// \tparam VoxelDistanceField a model of `VoxelDistanceField` (`Voxel_distance_field`);
///         when there are several pieces, its solid is searched through a dense array of
///         labels over its box.
/// \param skeleton a voxel skeleton (`thin()`); the small pieces leave it.
/// \param distances the distance field of the solid it was thinned from
///        (`distance_transform()`): its non-zero voxels are the solid.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{small_piece_fraction}
///     \cgalParamDescription{the size, relative to the largest piece, under which a piece is
///                           removed, in [0, 1]; 0 keeps every piece (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.05}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of pieces and what was removed.
/// \throws std::invalid_argument when `small_piece_fraction` is out of range.
///
/// \b Complexity: O(S log S) for S skeleton voxels when the skeleton is in one piece;
///    otherwise O(S log S + B) for B voxels in the field's box.
template <typename VoxelSet, typename VoxelDistanceField,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Small_pieces_report remove_small_pieces(VoxelSet& skeleton, const VoxelDistanceField& distances,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double fraction = internal::checked_parameter(
      parameter_ranges::small_piece_fraction,
      choose_parameter(get_parameter(np, internal_np::small_piece_fraction_tag),
                       parameter_ranges::small_piece_fraction.default_value),
      "remove_small_pieces");
  return internal::remove_small_pieces_with(skeleton, distances, fraction);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_REMOVE_SMALL_PIECES_H
