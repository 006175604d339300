// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_COARSE_SKELETON_END_POINTS_H
#define CGAL_GEODESIC_SKELETON_COARSE_SKELETON_END_POINTS_H

/// \file coarse_skeleton_end_points.h
/// The end points of a mesh's pruned voxel skeleton on a coarser grid, which
/// `prune_skeleton()` reads (its `coarse_end_points`) to keep the level of detail of that
/// grid on a finer one.

#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/No_enclosed_volume.h>
#include <CGAL/Geodesic_skeleton/Skeleton_radius_in_voxels_map.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/internal/prune/coarse_end_points.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The `coarse_end_point_tolerance` that goes with the end points of
/// `coarse_skeleton_end_points()` at `coarse_resolution`, given to `prune_skeleton()` on a
/// grid of `resolution`: the default tolerance (4 voxels) on the coarser grid, in voxels of
/// the finer one, as `extract_control_skeleton()` gives it.
/// \pre `coarse_resolution` > 0.
/// \b Complexity: constant.
inline double default_coarse_end_point_tolerance(int resolution, int coarse_resolution)
{
  return parameter_ranges::coarse_end_point_tolerance.default_value * double(resolution) /
         double(coarse_resolution);
}

/// \ingroup PkgGeodesicSkeletonRef
/// The end points of the pruned voxel skeleton of `mesh` at `resolution`, in the grid
/// coordinates of `frame` (usually a finer grid's): the branches that the level of detail
/// of that resolution keeps, as `prune_skeleton()` reads them (its `coarse_end_points`).
///
/// The voxel stages run as `extract_control_skeleton()` runs them: `voxelize()`,
/// `distance_transform()`, `thin()` (with the sheet radii and
/// `default_thin_part_radius(resolution)`), `remove_small_pieces()`,
/// `cut_spurious_cycles()` and `prune_skeleton()` (with the MAT and sheet radii), with
/// the settings of `np` but the resolution. An end point is the centre of a voxel of degree
/// 1 in the skeleton's graph, the one `to_graph()` makes (26-adjacency without the little
/// triangles of junctions), moved from the coarser grid's frame to `frame`.
///
/// \tparam FaceGraph a model of `FaceListGraph`, as for `voxelize()`.
/// \param mesh the mesh.
/// \param resolution the resolution of the coarser grid, as `voxelize()`'s `resolution`.
/// \param frame the grid whose coordinates the points are given in (a voxel `k` covers
///        [k, k + 1) along each axis), e.g. the finer grid's `Dense_voxel_grid::frame()`.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters": those
///        of the stages above (`vertex_point_map`, `fill_holes`, `memory_limit`,
///        `small_piece_fraction`, `spur_length_factor`, `limb_protrusion_factor`, ...); a
///        `resolution` or `thin_part_radius` in it is not used.
///
/// \returns the end points, or `std::nullopt` when the mesh encloses no volume at
///          `resolution` (a shape thinner than a voxel of that grid).
/// \throws std::invalid_argument for any other bad input or parameter, as the stages do.
///
/// \b Complexity: that of the stages on the grid of `resolution`: linear in its voxels and
/// the mesh's faces, in practice.
template <typename FaceGraph, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::optional<std::vector<std::array<double, 3>>>
coarse_skeleton_end_points(const FaceGraph& mesh, int resolution, const Voxel_frame& frame,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  const auto coarse_np = parameters::combine(parameters::resolution(resolution),
                                             parameters::thin_part_radius(default_thin_part_radius(resolution)), np);
  Dense_voxel_grid solid;
  Voxelized_surface surface;
  try
  {
    voxelize(mesh, solid, parameters::combine(parameters::voxelized_surface_output(&surface), coarse_np));
  }
  catch(const No_enclosed_volume&)
  {
    return std::nullopt;
  }
  const Voxel_distance_field distances = distance_transform(solid, coarse_np);
  Sheet_radii sheet_radii;
  thin(solid, distances,
       parameters::combine(parameters::sheet_radius_map(boost::associative_property_map<Sheet_radii>(sheet_radii)),
                           coarse_np));
  Sparse_voxel_set skeleton;
  skeleton.reset(solid.frame(), solid.bounding_box());
  solid.for_each([&](const Voxel_key& k) { skeleton.insert(k); });
  remove_small_pieces(skeleton, distances, coarse_np);
  cut_spurious_cycles(skeleton, mesh, parameters::combine(parameters::voxelized_surface(&std::as_const(surface)), coarse_np));
  prune_skeleton(skeleton, parameters::combine(parameters::mat_radius_map(mat_radius_in_voxels_map(distances)),
                                               parameters::sheet_radius_map(sheet_radius_in_voxels_map(sheet_radii)),
                                               coarse_np));
  std::vector<std::array<double, 3>> ends;
  for(const Voxel_key& k : internal::graph_end_points(skeleton))
    ends.push_back(frame.to_grid(solid.frame().centre(k)));
  return ends;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_COARSE_SKELETON_END_POINTS_H
