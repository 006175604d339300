// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_EXTRACT_CONTROL_SKELETON_VOXEL_CHAIN_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_EXTRACT_CONTROL_SKELETON_VOXEL_CHAIN_H

// The stages of extract_control_skeleton() (all but the Reeb graph), called in order: not
// part of the API.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton_report.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/internal/extract_control_skeleton/settings.h>
#include <CGAL/Geodesic_skeleton/move_skeleton_inside.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/reach_sheet_lobes.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/route_skeleton_on_finer_grid.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>
#include <CGAL/Geodesic_skeleton/smooth_skeleton.h>
#include <CGAL/Geodesic_skeleton/split_into_bones.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The voxel chain of extract_control_skeleton() (all but the Reeb graph), once its
// parameters are read: compiled once per mesh, point map and point type, whatever the
// parameter pack.
template <typename FaceGraph, typename VertexPointMap, typename Point>
void extract_control_skeleton_with(
    const FaceGraph& mesh, const VertexPointMap& vpm, Control_skeleton<Point>& out,
    const Control_skeleton_settings& settings,
    Curve_skeleton<Point, typename boost::graph_traits<FaceGraph>::vertex_descriptor>* curve_output,
    Curve_skeleton<Point, typename boost::graph_traits<FaceGraph>::vertex_descriptor>* thinned_output,
    Dense_voxel_grid* solid_output, Stage_clock& clock, Control_skeleton_report& report)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Skeleton = Curve_skeleton<Point, vertex_descriptor>;
  // Which branches the rig has is decided at one feature size, the grid of the level of
  // detail; a finer grid only samples the geometry more precisely (route_on_finer_grid below).
  report.resolution = settings.resolution;
  report.level_of_detail_resolution = settings.level_of_detail_resolution;
  const bool finer_than_level_of_detail =
      settings.level_of_detail_resolution > 0 && settings.level_of_detail_resolution < settings.resolution;
  const int pruning_resolution = finer_than_level_of_detail ? settings.level_of_detail_resolution : settings.resolution;
  // The parameters that the stages read, of one type.
  auto stage_parameters = [&](int resolution) {
    return parameters::combine(
        parameters::vertex_point_map(vpm), parameters::resolution(resolution),
        parameters::fill_holes(settings.fill_holes), parameters::keep_surface_voxels(settings.keep_surface_voxels),
        parameters::memory_limit(settings.memory_limit), parameters::small_piece_fraction(settings.small_piece_fraction),
        parameters::spur_length_factor(settings.spur_length_factor),
        parameters::limb_protrusion_factor(settings.limb_protrusion_factor));
  };
  const auto np = stage_parameters(pruning_resolution);
  // Each stage is a public function; the mesh as voxelize() rasterised it is shared with
  // the stages that test inside and outside, so that none reads the mesh again.
  Dense_voxel_grid solid;
  Voxelized_surface surface;
  report.solid_voxels = voxelize(mesh, solid, parameters::combine(parameters::voxelized_surface(&surface), np));
  if(solid_output != nullptr && !finer_than_level_of_detail)
    *solid_output = solid;
  clock.finished("voxelize");
  const auto with_surface = parameters::combine(parameters::voxelized_surface(&std::as_const(surface)), np);

  Voxel_distance_field distances = distance_transform(solid, np);
  clock.finished("distance_transform");

  // The sheet radii let pruning judge the twigs of a thin sheet by its width; the parts
  // thin at the default resolution are thin at any other (a given radius is in voxels of
  // `resolution`).
  report.thin_part_radius = settings.thin_part_radius.value_or(default_thin_part_radius(report.resolution));
  // In voxels of the grid that thins, that of the level of detail.
  const double thin_part_radius_of_grid = report.thin_part_radius * pruning_resolution / report.resolution;
  Voxel_skeleton skeleton;
  thin(solid, distances, skeleton,
       parameters::combine(parameters::thin_part_radius(thin_part_radius_of_grid), np));
  solid = Dense_voxel_grid();
  clock.finished("thin");

  if(thinned_output != nullptr)
  {
    Skeleton thinned;
    to_graph(skeleton.voxels, distances, mesh, thinned, with_surface);
    report.thinned = skeleton_statistics(thinned);
    *thinned_output = std::move(thinned);
  }
  else
    report.thinned = skeleton_statistics_of_voxels(skeleton.voxels);
  clock.finished("thinned_graph");

  // A thick plate that thinning burnt to a point or a short line gets a branch into each lobe.
  report.sheet_lobes = reach_sheet_lobes(
      skeleton.voxels, distances,
      parameters::combine(parameters::sheet_lobe_reach_factor(settings.sheet_lobe_reach_factor),
                          parameters::thin_part_radius(thin_part_radius_of_grid),
                          np));
  clock.finished("reach_sheet_lobes");

  report.small_pieces = remove_small_pieces(skeleton.voxels, distances, np);
  clock.finished("remove_small_pieces");

  report.spurious_cycles_cut = cut_spurious_cycles(skeleton.voxels, mesh, with_surface);
  clock.finished("cut_spurious_cycles");
  // Pruning judges a twig by the sheet it is in and a piece by its widest sheet, read
  // across close levels: the middle of a thick plate slanted in the grid lies on several
  // levels of distance, whose rounds each measure a strip of it, not the plate.
  report.pruning = prune_skeleton(skeleton, distances, np);
  clock.finished("prune");

  // On a finer grid, the same branches, routed through the middle of its solid; each of
  // its voxels stands for a voxel of the pruned skeleton, whose sheet widths it takes.
  if(finer_than_level_of_detail)
  {
    const auto fine_np = stage_parameters(settings.resolution);
    Dense_voxel_grid fine_solid;
    surface = Voxelized_surface();
    voxelize(mesh, fine_solid, parameters::combine(parameters::voxelized_surface(&surface), fine_np));
    if(solid_output != nullptr)
      *solid_output = fine_solid;
    report.voxels_joining_pieces = add_skeleton_to_solid(skeleton.voxels, fine_solid);
    report.solid_voxels = fine_solid.size();
    clock.finished("voxelize_finer");
    Voxel_distance_field fine_distances = distance_transform(fine_solid, fine_np);
    clock.finished("distance_transform_finer");
    report.branches_along_level_of_detail = route_skeleton_on_finer_grid(skeleton, distances, fine_distances);
    distances = std::move(fine_distances);
  }
  report.voxel_size = distances.frame().voxel_size();
  clock.finished("route_on_finer_grid");

  Skeleton curve;
  to_graph(skeleton, distances, mesh, curve, with_surface);
  report.pruned = skeleton_statistics(curve);
  clock.finished("to_graph");

  // The curve skeleton's own maps, ahead of np: a vertex_point_map in np is the mesh's.
  using Curve_vertex = Curve_skeleton_vertex<Point, vertex_descriptor>;
  const auto curve_np = parameters::combine(parameters::vertex_point_map(get(&Curve_vertex::point, curve)),
                                            parameters::mat_radius_map(get(&Curve_vertex::radius, curve)), np);
  // The paper's 5 points at the default resolution span the same length at any other.
  report.smoothing_window = settings.smoothing_window.value_or(default_smoothing_window(report.resolution));
  smooth_skeleton(curve, parameters::combine(parameters::smoothing_window(report.smoothing_window), curve_np));
  clock.finished("smooth");

  const std::vector<std::size_t> moved_inside = move_skeleton_inside(mesh, curve, with_surface);
  report.curve_points_moved_inside = moved_inside.size();
  surface = Voxelized_surface(); // as large as the mesh
  clock.finished("curve_points_inside");

  // Parts thinner than half a voxel of the default grid get the joints of parts that thick,
  // whatever the resolution: a finer grid measures them thinner, and the rig's joints should
  // not multiply with it (at the default resolution no MAT radius is smaller).
  report.smallest_radius =
      settings.smallest_radius.value_or(default_smallest_radius(report.voxel_size, report.resolution));
  // Chains end short of the tips and long bones get joints in between, as artists place them;
  // the spacing is a share of the whole shape, so a character gets as many joints at any size.
  report.tip_joint_setback = settings.split.tip_joint_setback;
  report.joint_spacing = settings.joint_spacing.value_or(
      default_joint_spacing(report.voxel_size, report.resolution, settings.joint_spacing_factor));
  split_into_bones(curve, out,
                   parameters::combine(parameters::smallest_radius(report.smallest_radius),
                                       parameters::tip_joint_setback(report.tip_joint_setback),
                                       parameters::joint_spacing(report.joint_spacing),
                                       parameters::bend_threshold(settings.split.bend_threshold),
                                       parameters::straightness_tolerance(settings.split.straightness_tolerance),
                                       parameters::minimum_bone_length_factor(settings.split.minimum_bone_length_factor),
                                       parameters::maximum_bone_length_factor(settings.split.maximum_bone_length_factor),
                                       parameters::chord_length_factors(settings.split.chord_length_factors),
                                       parameters::minimum_bone_length_of_piece_factor(
                                           settings.split.minimum_bone_length_of_piece_factor),
                                       curve_np));
  report.joints_moved_inside = joints_on_vertices(out, moved_inside);
  clock.finished("split_into_bones");
  if(curve_output != nullptr)
    *curve_output = std::move(curve);
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_EXTRACT_CONTROL_SKELETON_VOXEL_CHAIN_H
