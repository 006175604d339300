// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_REPORT_H
#define CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_REPORT_H

/// \file Control_skeleton_report.h
/// What `extract_control_skeleton()` did, and the visitor it reports its stages to.

#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/reach_sheet_lobes.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// What `extract_control_skeleton()` did: the sizes of its stages and their times.
struct Control_skeleton_report
{
  int resolution = 0;              ///< the longest principal extent of the mesh, in voxels
  double voxel_size = 0;           ///< edge of a voxel, in world units
  std::size_t solid_voxels = 0;    ///< voxels of the solid interior (of the finer grid, with `voxels_joining_pieces`)
  std::size_t voxels_joining_pieces = 0; ///< voxels added to the finer grid's solid along the skeleton of the level of detail (`add_skeleton_to_solid()`)
  Small_pieces_report small_pieces; ///< the skeleton's pieces, and the small detached ones removed
  Skeleton_statistics thinned;     ///< the curve skeleton after thinning
  Sheet_lobes_report sheet_lobes;  ///< the paths into the lobes of thick plates (`reach_sheet_lobes()`)
  std::size_t spurious_cycles_cut = 0; ///< cycles the mesh has no handle for, opened (`cut_spurious_cycles()`)
  Skeleton_statistics pruned;      ///< after pruning (Algorithm 1 and snipping)
  Pruning_report pruning;          ///< what pruning removed
  std::size_t branches_along_level_of_detail = 0; ///< branches that `route_skeleton_on_finer_grid()` found no path for on the finer grid, laid along the coarser skeleton's voxels
  std::size_t curve_points_moved_inside = 0; ///< curve-skeleton points that lay outside the (closed) mesh and were moved in
  std::size_t joints_moved_inside = 0; ///< joints on those points: they moved in with them
  double smallest_radius = 0;      ///< the `smallest_radius` the split used, given or default (world units)
  double thin_part_radius = 0;     ///< the `thin_part_radius` the thinning used, given or default (voxels)
  int smoothing_window = 0;        ///< the `smoothing_window` the smoothing used, given or default (points)
  double tip_joint_setback = 0;    ///< the `tip_joint_setback` the split used, given or default (lengths of the tip's bone)
  double joint_spacing = 0;        ///< the `joint_spacing` the split used, given or default (world units)
  int level_of_detail_resolution = 0; ///< the `level_of_detail_resolution` the pruning used, given or default
  std::size_t reeb_nodes = 0;      ///< nodes of the Reeb graph, when one was asked for
  std::size_t reeb_edges = 0;      ///< arcs of the Reeb graph, when one was asked for
  /// Wall-clock time of each stage in milliseconds, in the order they ran: "voxelize",
  /// "distance_transform", "thin", "thinned_graph" (the graph and counts of the thinned
  /// skeleton), "reach_sheet_lobes", "remove_small_pieces", "cut_spurious_cycles", "prune" (these on the grid of
  /// the level of detail), "voxelize_finer" and "distance_transform_finer" (above
  /// `level_of_detail_resolution`), "route_on_finer_grid", "to_graph", "smooth",
  /// "curve_points_inside", "split_into_bones", and "reeb_graph" when asked for.
  std::vector<std::pair<std::string, double>> timings_ms;
  double total_ms = 0;             ///< the whole call, in milliseconds
};

/// \ingroup PkgGeodesicSkeletonRef
/// The default visitor of `extract_control_skeleton()`: ignores every event. A visitor is
/// any object with the member function
/// `void stage_finished(const std::string& stage, double milliseconds)`, called after each
/// stage (names as in `Control_skeleton_report::timings_ms`), for progress display or
/// logging.
struct Default_pipeline_visitor
{
  /// Called after each stage.
  void stage_finished(const std::string&, double) {}
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_REPORT_H
