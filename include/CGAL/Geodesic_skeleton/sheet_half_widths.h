// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_SHEET_HALF_WIDTHS_H
#define CGAL_GEODESIC_SKELETON_SHEET_HALF_WIDTHS_H

/// \file sheet_half_widths.h
/// The half width of the thin sheet that each vertex of a curve skeleton runs through, in
/// world units, from the sheet radii that `thin()` records, and the widest sheet of each
/// piece of a skeleton.

#include <CGAL/Geodesic_skeleton/Skeleton_radius_in_voxels_map.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The rounds in which a level that is not a sheet can burn: a shell around a limb or a body
// burns in one or two (thin()'s sheet radius is 0, 1 or 2 there), so only the rounds beyond
// these measure a sheet's width.
constexpr double shell_rounds = 2;

// The half width (world units) of a sheet of sheet radius `rounds` on a grid of voxels
// `voxel_size` long: (rounds - shell_rounds) voxels, at least 0.
inline double sheet_half_width(double rounds, double voxel_size)
{
  return (std::max)(0.0, rounds - shell_rounds) * voxel_size;
}

// sheet_half_widths() with each vertex's sheet radius read at the voxel `voxel_of(k)` for
// its own voxel `k` (a voxel of the grid the radii were measured on).
template <typename CurveSkeleton, typename VoxelOf>
std::vector<double> sheet_half_widths_at(const CurveSkeleton& curve, const Sheet_radii& sheet_radii,
                                         double voxel_size, const VoxelOf& voxel_of)
{
  std::vector<double> widths(num_vertices(curve), 0.0);
  for(std::size_t v = 0; v < widths.size(); ++v)
  {
    const auto sheet = sheet_radii.find(voxel_of(curve[v].voxel));
    if(sheet != sheet_radii.end())
      widths[v] = sheet_half_width(sheet->second, voxel_size);
  }
  return widths;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// The half width, in world units, of the thin sheet (a wing, a fin, a cape) that each
/// vertex of a curve skeleton runs through, 0 where it runs through none: the
/// `Curve_skeleton_vertex::sheet_half_width` that `extract_control_skeleton()` sets before
/// `split_into_bones()`, so that a sheet's chain is split in lengths of its width rather
/// than of its thickness.
///
/// A vertex's sheet radius r (the rounds in which `thin()` burnt its level around it,
/// 0 when `sheet_radii` has no entry for its voxel) gives (r - 2) voxels, at least 0: any
/// level, a limb's shell too, burns in up to two rounds, which say nothing of a sheet.
///
/// \tparam CurveSkeleton an undirected `boost::adjacency_list` with `vecS` vertex storage
///         whose vertex bundle has a `voxel` member (`Voxel_key`), e.g. the
///         `Curve_skeleton<Point, MeshVertex>` that `to_graph()` writes.
/// \param curve the curve skeleton, made by `to_graph()` from the voxels that `thin()` kept.
/// \param sheet_radii the sheet radii that `thin()` recorded through its `sheet_radius_map`.
/// \param voxel_size the edge length of a voxel of the grid `thin()` ran on (world units).
/// \returns one width per vertex, indexed by vertex descriptor (0 to N-1): for example
///          `curve[v].sheet_half_width = widths[v]`.
/// \pre every voxel of `curve` is in the grid whose voxels are `voxel_size` long.
/// \throws std::invalid_argument when `voxel_size` is not finite and positive.
///
/// \b Complexity: O(N) expected for N vertices (one hash lookup each).
template <typename CurveSkeleton>
std::vector<double> sheet_half_widths(const CurveSkeleton& curve, const Sheet_radii& sheet_radii, double voxel_size)
{
  if(!(voxel_size > 0) || !std::isfinite(voxel_size))
    throw std::invalid_argument("sheet_half_widths: the voxel size must be finite and positive");
  return internal::sheet_half_widths_at(curve, sheet_radii, voxel_size, [](const Voxel_key& k) { return k; });
}

/// \ingroup PkgGeodesicSkeletonRef
/// The widest thin sheet of each piece of a skeleton: for each voxel of `skeleton`, the
/// largest sheet radius over the 26-connected piece it is in (0 for a piece without any).
///
/// Taken before pruning, it keeps the width of the sheets that pruning then thins away: a
/// chain that pruning keeps beside a sheet (a bar beside a plate, a bone beside a fin) still
/// belongs to a piece that wide. `extract_control_skeleton()` reads it at the vertices of the
/// pruned curve skeleton (`sheet_half_widths()`) and sets it as each vertex's
/// `Curve_skeleton_vertex::piece_radius` before `split_into_bones()`, so that the rig's level of detail of a piece is the one that pruning
/// judged its twigs by, whichever path through the sheet pruning kept.
///
/// \tparam VoxelSet a voxel set with `for_each(f)` (f called with each `Voxel_key`) and
///         `contains(k)`, e.g. `Sparse_voxel_set`.
/// \param skeleton the voxels that `thin()` kept, before `prune_skeleton()`.
/// \param sheet_radii the sheet radii that `thin()` recorded through its `sheet_radius_map`
///        (a voxel without one counts as 0).
/// \returns a sheet radius (in voxels) for every voxel of `skeleton`, the same for all the
///          voxels of a piece: for example `sheet_half_widths(curve, widest, voxel_size)` at
///          the vertices of a curve skeleton made from some of these voxels.
///
/// \b Complexity: O(K log K) for K voxels (the pieces), plus O(K) expected hash lookups.
template <typename VoxelSet>
Sheet_radii widest_sheet_radius_of_pieces(const VoxelSet& skeleton, const Sheet_radii& sheet_radii)
{
  return internal::largest_radius_of_pieces(skeleton, [&](const Voxel_key& k) {
    const auto sheet = sheet_radii.find(k);
    return sheet == sheet_radii.end() ? 0.0 : sheet->second;
  });
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_SHEET_HALF_WIDTHS_H
