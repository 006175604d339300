// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_JOIN_PIECES_JOINED_ON_COARSER_GRID_H
#define CGAL_GEODESIC_SKELETON_JOIN_PIECES_JOINED_ON_COARSER_GRID_H

/// \file join_pieces_joined_on_coarser_grid.h
/// Joins the pieces of a solid that the solid of the same mesh on a coarser grid joins, so
/// that which parts of a mesh touch does not depend on the resolution.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/join_pieces.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <unordered_map>
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
/// `coarse_solid` that holds the most of its boundary voxels (their centres); the pieces
/// that belong to one coarse piece are linked, nearest pair first, by the shortest segments
/// between their boundary voxels whose centres fall in the same or neighbouring voxels of
/// the coarser grid (Kruskal's minimum spanning tree over those links), and the voxels of
/// each segment are inserted. Pieces that no such segment links stay apart.
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
///
/// \b Complexity: O(S + R) time and O(R) memory for the S voxels of `solid` in R runs
/// along x (a count of its pieces); when it has several, also O(V) time and V bytes for the
/// V voxels of its box (a search of its pieces), O(C) time and 4 C bytes for the C voxels of
/// the box of `coarse_solid`, and the pairs of boundary voxels of different pieces in
/// neighbouring coarse voxels.
template <typename VoxelSet, typename CoarseVoxelSet>
std::size_t join_pieces_joined_on_coarser_grid(VoxelSet& solid, const CoarseVoxelSet& coarse_solid)
{
  if(internal::count_pieces(solid) < 2)
    return 0;
  std::vector<internal::Piece_boundary_voxel> boundary;
  const std::size_t pieces =
      internal::search_pieces(solid, [&](const Voxel_key& k, std::size_t piece, bool on_boundary) {
        if(on_boundary)
          boundary.push_back(internal::Piece_boundary_voxel{k, piece});
      });
  if(pieces < 2)
    return 0;

  // The coarse voxel of each boundary voxel, and the coarse piece of each piece.
  const internal::Voxel_pieces coarse_piece(coarse_solid);
  const std::size_t none = std::size_t(-1);
  std::vector<Voxel_key> cell(boundary.size());
  std::vector<std::map<std::size_t, std::size_t>> votes(pieces);
  for(std::size_t i = 0; i < boundary.size(); ++i)
  {
    cell[i] = coarse_solid.frame().voxel_of(solid.frame().centre(boundary[i].key));
    const std::int32_t coarse = coarse_piece(cell[i]);
    if(coarse >= 0)
      ++votes[boundary[i].piece][std::size_t(coarse)];
  }
  std::vector<std::size_t> coarse_of(pieces, none);
  for(std::size_t p = 0; p < pieces; ++p)
  {
    std::size_t most = 0;
    for(const auto& [coarse, count] : votes[p]) // in coarse piece order: ties go to the first
      if(count > most)
      {
        most = count;
        coarse_of[p] = coarse;
      }
  }

  // The boundary voxels in each coarse voxel, and the piece they all belong to (`none` when
  // several do).
  std::unordered_map<Voxel_key, std::vector<std::size_t>, Voxel_key_hash> in_cell;
  for(std::size_t i = 0; i < boundary.size(); ++i)
    if(coarse_of[boundary[i].piece] != none)
      in_cell[cell[i]].push_back(i);
  std::unordered_map<Voxel_key, std::size_t, Voxel_key_hash> only_piece;
  for(const auto& [c, voxels] : in_cell)
  {
    std::size_t only = boundary[voxels.front()].piece;
    for(std::size_t i : voxels)
      if(boundary[i].piece != only)
        only = none;
    only_piece.emplace(c, only);
  }

  // The shortest link between each two pieces of one coarse piece, through neighbouring
  // coarse voxels.
  std::map<std::pair<std::size_t, std::size_t>, internal::Piece_link> shortest;
  for(const auto& [c, here] : in_cell)
  {
    const std::size_t here_only = only_piece.at(c);
    for(int dz = -1; dz <= 1; ++dz)
      for(int dy = -1; dy <= 1; ++dy)
        for(int dx = -1; dx <= 1; ++dx)
        {
          const Voxel_key n{c.x + dx, c.y + dy, c.z + dz};
          const auto there = in_cell.find(n);
          if(there == in_cell.end() || (here_only != none && here_only == only_piece.at(n)))
            continue;
          for(std::size_t a : here)
            for(std::size_t b : there->second)
            {
              const std::size_t pa = boundary[a].piece, pb = boundary[b].piece;
              if(pa >= pb || coarse_of[pa] != coarse_of[pb])
                continue;
              const Voxel_key& ka = boundary[a].key;
              const Voxel_key& kb = boundary[b].key;
              const double length = std::sqrt(double(ka.x - kb.x) * (ka.x - kb.x) + double(ka.y - kb.y) * (ka.y - kb.y) +
                                              double(ka.z - kb.z) * (ka.z - kb.z));
              const internal::Piece_link link{length, a, b};
              const auto [it, inserted] = shortest.emplace(std::make_pair(pa, pb), link);
              if(!inserted && internal::shorter_link(link, it->second))
                it->second = link;
            }
        }
  }

  // Kruskal: the shortest links that join pieces not yet joined.
  std::vector<internal::Piece_link> links;
  for(const auto& entry : shortest)
    links.push_back(entry.second);
  std::sort(links.begin(), links.end(), internal::shorter_link);
  std::vector<std::size_t> root(pieces);
  std::iota(root.begin(), root.end(), std::size_t(0));
  const auto find_root = [&](std::size_t p) {
    while(root[p] != p)
      p = root[p] = root[root[p]];
    return p;
  };
  std::size_t joined = 0;
  for(const internal::Piece_link& link : links)
  {
    const std::size_t a = find_root(boundary[link.from].piece), b = find_root(boundary[link.to].piece);
    if(a == b)
      continue;
    root[a] = b;
    for(const Voxel_key& k : internal::voxels_of_segment(boundary[link.from].key, boundary[link.to].key))
      solid.insert(k);
    ++joined;
  }
  return joined;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_JOIN_PIECES_JOINED_ON_COARSER_GRID_H
