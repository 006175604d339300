// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_JOIN_PIECES_JOINED_ON_COARSER_GRID_H
#define CGAL_GEODESIC_SKELETON_JOIN_PIECES_JOINED_ON_COARSER_GRID_H

/// \file join_pieces_joined_on_coarser_grid.h
/// Joins the pieces of a solid that the solid of the same mesh on a coarser grid joins, so
/// that which parts of a mesh touch does not depend on the resolution.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/join_pieces.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Joins the 26-connected pieces of `solid` that lie in one piece of `coarse_solid`, the
/// solid of the same mesh on a coarser grid, by a line of voxels between their nearest
/// voxels.
///
/// `voxelize()` joins two parts of a mesh that come within about a voxel of each other:
/// their surfaces touch neighbouring voxels. That is a length in voxels, so a finer grid
/// separates parts that the coarser one joins (a gap of one voxel at resolution 64 is two at
/// 128), and the skeleton has more trees the finer the grid. Given the solid on the grid of
/// the level of detail, this function makes the finer solid's pieces those of the coarser
/// one: pieces within one voxel of the coarser grid of each other, a fraction of the
/// shape, are joined at every resolution. Each piece of `solid` belongs to the piece of
/// `coarse_solid` that holds the most of its voxel centres; the pieces that belong to one
/// coarse piece are linked, nearest pair first, by the shortest segments between their
/// boundary voxels whose centres fall in the same or neighbouring voxels of the coarser grid
/// (Kruskal's minimum spanning tree over those links), and the voxels of each segment are
/// inserted. Pieces that no such segment links stay apart.
///
/// \tparam VoxelSet a model of `VoxelSet` (`Dense_voxel_grid`, `Sparse_voxel_set`).
/// \tparam CoarseVoxelSet a model of `VoxelSet`; read through `for_each()`,
///         `bounding_box()` and `frame()`.
/// \param solid the solid on the finer grid (as `voxelize()` made it); receives the links.
/// \param coarse_solid the solid of the same mesh on the coarser grid, e.g.
///        `Coarse_skeleton_level_of_detail::solid`.
/// \returns the number of links inserted (the number of pieces of `solid` goes down by as
///          many).
/// \pre both frames place the same mesh (`voxelize()` of one mesh at two resolutions).
/// \throws std::invalid_argument when the voxels of `coarse_solid` are smaller than those
///         of `solid`: its grid is not the coarser.
///
/// \b Complexity: O(S + R) time and O(R) memory for the S voxels of `solid` in R runs along
/// x (a union-find over the runs counts its pieces); when it has several, also O(S + C) time
/// and 9 C bytes for the C voxels of the box of `coarse_solid` (where each piece lies on the
/// coarser grid), and the pairs of boundary voxels of different pieces in neighbouring
/// coarse voxels.
template <typename VoxelSet, typename CoarseVoxelSet>
std::size_t join_pieces_joined_on_coarser_grid(VoxelSet& solid, const CoarseVoxelSet& coarse_solid)
{
  if(coarse_solid.frame().voxel_size() < solid.frame().voxel_size())
    throw std::invalid_argument("join_pieces_joined_on_coarser_grid: the coarser solid's voxels are smaller than "
                                "the solid's; pass the solid of the coarser grid second");
  const internal::Runs_and_pieces fine = internal::runs_and_pieces(solid);
  if(fine.pieces < 2)
    return 0;
  const internal::Voxel_of_centre cell_of(solid.frame(), coarse_solid.frame());
  const internal::Pieces_on_coarser_grid on = internal::pieces_on_coarser_grid(fine, coarse_solid, cell_of);
  const std::vector<internal::Contact_voxel> contacts = internal::contact_voxels(solid, fine, on, cell_of);

  // Kruskal: the shortest links that join pieces not yet joined.
  boost::disjoint_sets_with_storage<> joined_pieces(fine.pieces);
  std::size_t joined = 0;
  for(const internal::Piece_link& link : internal::shortest_links(contacts, on.coarse_of))
  {
    const std::size_t a = joined_pieces.find_set(contacts[link.from].piece);
    const std::size_t b = joined_pieces.find_set(contacts[link.to].piece);
    if(a == b)
      continue;
    joined_pieces.link(a, b);
    for(const Voxel_key& k : internal::voxels_of_segment(contacts[link.from].key, contacts[link.to].key))
      solid.insert(k);
    ++joined;
  }
  return joined;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_JOIN_PIECES_JOINED_ON_COARSER_GRID_H
