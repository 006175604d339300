// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_VOXEL_SKELETON_H
#define CGAL_GEODESIC_SKELETON_VOXEL_SKELETON_H

/// \file Voxel_skeleton.h
/// The voxel skeleton that the voxel stages pass on: its voxels and what thinning measured
/// at each of them.

#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <unordered_map>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// A radius per voxel, in voxels (a voxel without an entry has radius 0).
using Sheet_radii = std::unordered_map<Voxel_key, double, Voxel_key_hash>;

namespace internal {

// The radius of `k` in `radii`, 0 when it has none.
inline double radius_in(const Sheet_radii& radii, const Voxel_key& k)
{
  const auto found = radii.find(k);
  return found == radii.end() ? 0.0 : found->second;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// For each voxel of a skeleton on a finer grid, the voxel of the coarser grid's skeleton
/// it stands for (`route_skeleton_on_finer_grid()`).
using Coarser_voxel_map = std::unordered_map<Voxel_key, Voxel_key, Voxel_key_hash>;

/// \ingroup PkgGeodesicSkeletonRef
/// A one-voxel-thick skeleton with the radii that thinning measured at its voxels: what
/// `thin()` makes of a solid, and what the later voxel stages read and update
/// (`prune_skeleton()`, `route_skeleton_on_finer_grid()`, `to_graph()`). The MAT radius is
/// not kept here: it is the solid's distance field (`Voxel_distance_field`), which every
/// stage is given.
///
/// All radii are in voxels of the grid that `thin()` ran on, whose voxel size is
/// `radius_voxel_size`; after `route_skeleton_on_finer_grid()` the voxels are those of the
/// finer grid, and `coarser_voxel` gives for each the voxel of the thinned grid whose radii
/// it reads.
struct Voxel_skeleton
{
  /// The skeleton's voxels (their frame is the grid's).
  Sparse_voxel_set voxels;
  /// The <i>sheet radius</i> of each voxel that thinning kept: the number of rounds that its
  /// level of distance burnt around it. Inside a thin sheet (a wing, a fin, an ear, a plate)
  /// the distance to the outside is flat, a level is the whole sheet and its rounds burn it
  /// from the rim inwards, so on the sheet's middle line this is its half width, which the
  /// MAT radius (its half thickness) does not tell. Elsewhere it is 0 or about 1.
  Sheet_radii sheet_radii;
  /// The sheet radius read across close levels: the latest round in which a 26-neighbour
  /// was deleted whose distance to the outside is within `slanted_sheet_depth_band` of the
  /// voxel's. The middle of a thick sheet slanted in the grid falls on several levels less
  /// than half a voxel apart, each burning its own strips: `sheet_radii` measures a strip
  /// there, this the sheet.
  Sheet_radii slanted_sheet_radii;
  /// The widest sheet of each voxel's 26-connected piece, the largest of the
  /// `slanted_sheet_radii` over the piece, as `prune_skeleton()` took it before pruning: a
  /// chain that pruning keeps beside a sheet still belongs to a piece that wide.
  Sheet_radii piece_sheet_radii;
  /// Set by `route_skeleton_on_finer_grid()`: the voxel of the thinned grid that each voxel
  /// of the finer grid stands for (empty before: each voxel stands for itself).
  Coarser_voxel_map coarser_voxel;
  /// The edge length of a voxel of the grid the radii were measured on (world units).
  double radius_voxel_size = 0;

  /// The voxel whose radii `k` reads: `coarser_voxel[k]`, or `k` itself.
  Voxel_key radius_voxel(const Voxel_key& k) const
  {
    const auto coarser = coarser_voxel.find(k);
    return coarser == coarser_voxel.end() ? k : coarser->second;
  }
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_VOXEL_SKELETON_H
