// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_ROUTE_SKELETON_ON_FINER_GRID_H
#define CGAL_GEODESIC_SKELETON_ROUTE_SKELETON_ON_FINER_GRID_H

/// \file route_skeleton_on_finer_grid.h
/// The level of detail of the chain: a pruned skeleton made on a coarser grid decides which
/// branches the rig has; a finer grid only places them more precisely.

#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/internal/route_skeleton_on_finer_grid/finer_grid_router.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>

#include <cstddef>
#include <utility>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Adds to a solid on a finer grid the voxels along a skeleton made on a coarser grid of
/// the same mesh: for each edge of the skeleton's graph (26-adjacent voxels), the voxels of
/// the finer grid on the straight segment between their centres. Where the finer grid
/// separates parts that the coarser one joins (a hand resting on a thigh, parts within a
/// coarser voxel of each other), the solid keeps the coarser skeleton's link between them,
/// so that `route_skeleton_on_finer_grid()` finds every branch a path.
///
/// \tparam VoxelSet a model of `VoxelSet`, e.g. `Sparse_voxel_set`: the coarser skeleton.
/// \param coarse_skeleton a skeleton on the coarser grid (its `frame()`).
/// \param solid the solid of the finer grid, as `voxelize()` made it; voxels outside its
///        box are not added.
/// \returns the number of voxels added.
///
/// \b Complexity: O(N) for the N voxels of the skeleton, times the ratio of the two voxel
/// sizes.
template <typename VoxelSet>
std::size_t add_skeleton_to_solid(const VoxelSet& coarse_skeleton, Dense_voxel_grid& solid)
{
  const Voxel_frame& coarse = coarse_skeleton.frame();
  const internal::Skeleton_adjacency graph = internal::skeleton_adjacency(coarse_skeleton);
  std::size_t added = 0;
  auto add = [&](const Voxel_key& k) {
    if(solid.bounding_box().contains(k) && solid.insert(k))
      ++added;
  };
  for(const Voxel_key& k : graph.nodes)
    add(internal::voxel_in_frame(coarse, solid.frame(), k));
  for(const auto& [a, b] : graph.edges)
    for(const Voxel_key& k :
        internal::straight_voxel_path(internal::voxel_in_frame(coarse, solid.frame(), graph.nodes[std::size_t(a)]),
                                      internal::voxel_in_frame(coarse, solid.frame(), graph.nodes[std::size_t(b)])))
      add(k);
  return added;
}

/// \ingroup PkgGeodesicSkeletonRef
/// Routes a pruned skeleton made on a coarser grid through the middle of the solid of a
/// finer grid of the same mesh: the result has the coarser skeleton's branches and
/// junctions, placed as precisely as the finer grid samples the shape.
///
/// Which branches a rig has is a modelling choice made at one feature size, the coarser
/// grid's; the resolution only sets how precisely the geometry is sampled. So each branch
/// of the coarser skeleton's graph (the voxel paths between its nodes, the voxels of degree
/// other than 2) is routed between its two nodes on the finer grid: each node goes to the
/// voxel of the finer solid inside its coarser voxel with the largest MAT radius, and each
/// branch to the cheapest path between them whose steps cost their length over the MAT
/// radius of the voxel they enter (a length in MAT radii, the same on any grid). The branches are routed outwards from the node of largest MAT radius of
/// each piece, each from its far node to the part of the finer skeleton already routed
/// around its near node (within the node's MAT radius and 2 voxels), through the voxels of
/// the finer solid whose coarser voxel is nearer to the branch, or to the branches it meets
/// at its nodes, than to any other part of the skeleton, and never next to the skeleton
/// elsewhere: the finer skeleton has the coarser one's junctions, pieces and cycles and no
/// other. A branch without such a path (the finer grid separates what the coarser one joins,
/// and `add_skeleton_to_solid()` was not called) follows the coarser branch's own voxels.
///
/// \tparam VoxelSet a model of `VoxelSet`, e.g. `Sparse_voxel_set`.
/// \param coarse_skeleton the pruned skeleton on the coarser grid (one voxel thick).
/// \param coarse_distances the distance transform of the coarser grid's solid.
/// \param fine_distances the distance transform of the finer grid's solid (after
///        `add_skeleton_to_solid()`).
/// \param fine_skeleton receives the routed skeleton (its voxels are added).
/// \param coarser_voxel receives, for each voxel of `fine_skeleton`, the voxel of
///        `coarse_skeleton` it stands for: along a branch, the voxel at the same share of
///        the branch's length in voxels. Stages that need the coarser grid's measures of
///        the skeleton (its sheet widths) read them through it.
/// \returns the number of branches that followed the coarser branch's voxels.
/// \pre The two grids are of the same mesh (their frames share axes); every voxel of
///      `coarse_skeleton` is inside the solid of `coarse_distances`.
///
/// \b Complexity: for each branch, an A* search through the part of the finer solid near
/// it; O(V log V) over the V voxels of the finer solid, in practice, plus O(C) for the C
/// voxels of the coarser box.
template <typename VoxelSet>
std::size_t route_skeleton_on_finer_grid(const VoxelSet& coarse_skeleton, const Voxel_distance_field& coarse_distances,
                                         const Voxel_distance_field& fine_distances, VoxelSet& fine_skeleton,
                                         Coarser_voxel_map& coarser_voxel)
{
  const internal::Voxel_branches branches = internal::voxel_branches(coarse_skeleton);
  internal::Finer_grid_router router(branches, coarse_distances, fine_distances, coarser_voxel);
  return router.route(fine_skeleton);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Routes the voxels of a `Voxel_skeleton` on a finer grid, as the other overload does:
/// `skeleton.voxels` become the routed voxels of the finer grid and
/// `skeleton.coarser_voxel` the voxel of the coarser grid each stands for, whose radii it
/// keeps reading (`Voxel_skeleton::radius_voxel()`); the radii stay those of the coarser grid.
///
/// \param skeleton the pruned skeleton on the coarser grid, routed in place.
/// \param coarse_distances the distance transform of the coarser grid's solid.
/// \param fine_distances the distance transform of the finer grid's solid.
/// \returns the number of branches that followed the coarser branch's voxels.
/// \pre as for the other overload; `skeleton.coarser_voxel` is empty (a skeleton routed once).
///
/// \b Complexity: that of the other overload.
inline std::size_t route_skeleton_on_finer_grid(Voxel_skeleton& skeleton, const Voxel_distance_field& coarse_distances,
                                                const Voxel_distance_field& fine_distances)
{
  Sparse_voxel_set fine_voxels;
  fine_voxels.reset(fine_distances.frame(), fine_distances.box());
  const std::size_t followed = route_skeleton_on_finer_grid(skeleton.voxels, coarse_distances, fine_distances,
                                                            fine_voxels, skeleton.coarser_voxel);
  skeleton.voxels = std::move(fine_voxels);
  return followed;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_ROUTE_SKELETON_ON_FINER_GRID_H
