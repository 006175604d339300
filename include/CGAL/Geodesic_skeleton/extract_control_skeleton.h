// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_EXTRACT_CONTROL_SKELETON_H
#define CGAL_GEODESIC_SKELETON_EXTRACT_CONTROL_SKELETON_H

/// \file extract_control_skeleton.h
/// The whole chain of the package, mesh to control skeleton, with good defaults.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton_report.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/internal/extract_control_skeleton/voxel_chain.h>
#include <CGAL/Geodesic_skeleton/reeb_graph.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Extracts the animation control skeleton of a mesh: the whole chain of the package with
/// good defaults, a composition of its public stages and nothing else (the manual's data flow
/// shows the same calls made by hand, which give the same result).
///
/// On the grid of the level of detail: `voxelize()` (the solid interior, on a grid aligned
/// with the principal axes), `distance_transform()` (the MAT radius), `thin()` (grassfire, a
/// one-voxel-thick `Voxel_skeleton`, with the sheet radii of its voxels),
/// `reach_sheet_lobes()` (a branch into each lobe of a thick plate that thinning burnt to a
/// point), `remove_small_pieces()` (loose eyes, teeth), `cut_spurious_cycles()` (loops the mesh has
/// no handle for), `prune_skeleton()` (the paper's Algorithm 1 and the snipping of spurious
/// branches, judged by the MAT radius or a thin sheet's width, and by the widest sheet of
/// each piece, `Voxel_skeleton::piece_sheet_radii`).
///
/// The level of detail is one step. Which branches, junctions and pieces the rig has is a
/// modelling choice made at one feature size; the resolution only sets how precisely the
/// shape is sampled. So the stages above run at `level_of_detail_resolution` (default 64)
/// when `resolution` is finer, at `resolution` otherwise. On a finer grid, `voxelize()` and
/// `distance_transform()` run again, `add_skeleton_to_solid()` keeps the pruned skeleton's
/// links in the finer solid, and `route_skeleton_on_finer_grid()` routes each of its
/// branches through the middle of it.
///
/// Then, on the finest grid: `to_graph()` (the curve skeleton, with the mesh vertices mapped
/// to it and the skeleton's sheet widths), `smooth_skeleton()` (5-point moving average),
/// `move_skeleton_inside()` (points that smoothing took out of a closed mesh go back in)
/// and `split_into_bones()` (joints and bones, rooted at the most central junction; chains
/// end short of the tips and long bones are cut at a spacing, as artists place joints),
/// which splits a sheet's chain in lengths of its width and a piece at the level of detail
/// its pruning judged by (the sheet radii of the grid of the level of detail). `voxelize()`
/// hands the mesh as it rasterised it (`Voxelized_surface`) to the stages that test inside
/// and outside.
///
/// The result is in the mesh's own coordinates and does not change (beyond the rounding
/// of coordinates) when the mesh is rotated or moved, since the grid follows the mesh's
/// principal axes.
///
/// \tparam FaceGraph a model of `FaceListGraph`: any CGAL mesh, open or closed, in one
///         piece or many, self-intersecting or not.
/// \tparam Point the point type of the output.
/// \param mesh the mesh.
/// \param out receives the control skeleton (cleared first).
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below: every parameter of the stages, passed on to them (the
///        `vertex_point_map` is the mesh's: the curve-skeleton stages read the curve
///        skeleton's own points and radii, and a `mat_radius_map` is not passed on), and
///        the outputs and visitor of the chain.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map, resolution, fill_holes, memory_limit}
///     \cgalParamDescription{the settings of the voxel stages (`voxelize()`,
///                           `distance_transform()`, `thin()`, `to_graph()`,
///                           `cut_spurious_cycles()`)}
///     \cgalParamType{as for `voxelize()`}
///     \cgalParamDefault{as for `voxelize()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{thin_part_radius}
///     \cgalParamDescription{the setting of `thin()`: the largest MAT radius of a thin part,
///                           in voxels of `resolution` (scaled to the grid that thins), in
///                           [0, 1000]}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_thin_part_radius(resolution)`: sqrt(2) voxels at the
///                       default resolution and below, in proportion to the resolution above
///                       it (2 sqrt(2) at 128), so that the same parts of the shape are thin}
///   \cgalParamNEnd
///   \cgalParamNBegin{small_piece_fraction}
///     \cgalParamDescription{the setting of `remove_small_pieces()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.05}
///   \cgalParamNEnd
///   \cgalParamNBegin{spur_length_factor}
///     \cgalParamDescription{the setting of `prune_skeleton()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.2}
///   \cgalParamNEnd
///   \cgalParamNBegin{limb_protrusion_factor}
///     \cgalParamDescription{the setting of `prune_skeleton()`: the rig's level of detail}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.75}
///   \cgalParamNEnd
///   \cgalParamNBegin{sheet_lobe_reach_factor}
///     \cgalParamDescription{the setting of `reach_sheet_lobes()`: how far out of the thinned
///                           skeleton's balls a lobe of a thick plate reaches, in largest MAT
///                           radii of its piece, for a branch into it; in [0, 100], 0 adds none}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1 (calibrated on the artists' rigs, manual section
///                       \ref manual_sheet_lobes)}
///   \cgalParamNEnd
///   \cgalParamNBegin{level_of_detail_resolution}
///     \cgalParamDescription{the resolution of the grid that decides which branches the rig
///                           has (the stages up to pruning run there); a finer `resolution`
///                           routes them on its grid (`route_skeleton_on_finer_grid()`), an
///                           integer in [0, 8192]; 0, or a value not below `resolution`,
///                           runs every stage at `resolution`}
///     \cgalParamType{`int`}
///     \cgalParamDefault{64, the default resolution}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_window}
///     \cgalParamDescription{the setting of `smooth_skeleton()`: the number of consecutive
///                           points averaged, an odd number in [1, 1001]}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`default_smoothing_window(resolution)`: the paper's 5 at the
///                       default resolution, in proportion to the resolution elsewhere (7 at
///                       96, 9 at 128), so that the window spans the same length of the shape}
///   \cgalParamNEnd
///   \cgalParamNBegin{bend_threshold, straightness_tolerance, minimum_bone_length_factor, maximum_bone_length_factor, minimum_bone_length_of_piece_factor, chord_length_factors}
///     \cgalParamDescription{the settings of `split_into_bones()`}
///     \cgalParamType{as for `split_into_bones()`}
///     \cgalParamDefault{as for `split_into_bones()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{tip_joint_setback}
///     \cgalParamDescription{the setting of `split_into_bones()`: a tip's joint sits this share
///                           of its bone's length back from the tip, where artists end a chain}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.3 (calibrated on the artists' rigs, manual section
///                       \ref manual_split_into_bones)}
///   \cgalParamNEnd
///   \cgalParamNBegin{joint_spacing_factor}
///     \cgalParamDescription{the `joint_spacing` of `split_into_bones()`, in longest principal
///                           extents of the mesh, in [0, 1]: long bones are cut into lengths of
///                           about this share of the shape; 0 turns it off. A `joint_spacing`
///                           given in world units takes its place}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.1 (calibrated on the artists' rigs, manual section
///                       \ref manual_split_into_bones)}
///   \cgalParamNEnd
///   \cgalParamNBegin{smallest_radius}
///     \cgalParamDescription{the setting of `split_into_bones()`: the smallest radius its
///                           lengths are measured in, world units, in [0, inf]}
///     \cgalParamType{`double`}
///     \cgalParamDefault{half a voxel of the default grid: the mesh's longest principal
///                       extent / (2 `default_voxel_resolution`), the smallest MAT radius at
///                       the default resolution, so that the joints of thin parts do not
///                       multiply at a finer resolution (`default_smallest_radius()`); 0
///                       gives the MAT radius as it is}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{an object with `stage_finished(stage, milliseconds)`, called
///                           after each stage}
///     \cgalParamType{a class with that member function}
///     \cgalParamDefault{`Default_pipeline_visitor`}
///     \cgalParamExtra{It is copied: keep its state behind a pointer or a reference.}
///   \cgalParamNEnd
///   \cgalParamNBegin{curve_skeleton_output}
///     \cgalParamDescription{receives the pruned, smoothed curve skeleton (its points moved
///                           inside a closed mesh, as above), with the mesh vertices mapped
///                           to its vertices (package parameter)}
///     \cgalParamType{a pointer to a `Curve_skeleton<Point, vertex_descriptor>`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{For this output and the next three, a null pointer is the same as
///                     none.}
///   \cgalParamNEnd
///   \cgalParamNBegin{thinned_skeleton_output}
///     \cgalParamDescription{receives the skeleton straight after thinning, before pruning
///                           (package parameter)}
///     \cgalParamType{a pointer to a `Curve_skeleton<Point, vertex_descriptor>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxelized_solid}
///     \cgalParamDescription{receives the solid as `voxelize()` gives it for the mesh at
///                           `resolution` (with `fill_holes`, `keep_surface_voxels`,
///                           `memory_limit` and `vertex_point_map`), before any stage changes
///                           it: `compute_skinning_weights()` reads it through the same name
///                           instead of voxelizing the mesh again (package parameter)}
///     \cgalParamType{a pointer to a `Dense_voxel_grid`}
///     \cgalParamDefault{none}
///     \cgalParamExtra{A copy of the grid: O(V_box) more time and memory.}
///   \cgalParamNEnd
///   \cgalParamNBegin{reeb_graph_output}
///     \cgalParamDescription{receives the Reeb graph of the geodesic mapping function
///                           (`geodesic_mapping_function()`), the skeleton the paper
///                           compares with (package parameter)}
///     \cgalParamType{a pointer to a `Reeb_graph<FaceGraph>`}
///     \cgalParamDefault{none, and no Reeb graph is computed}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_reeb_intervals}
///     \cgalParamDescription{the intervals of that Reeb graph (package parameter)}
///     \cgalParamType{`std::size_t`}
///     \cgalParamDefault{30}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the sizes and timings of the stages.
/// \throws std::invalid_argument for bad input or parameters, with a message naming the
///         stage and the problem (see each stage): an empty mesh, non-finite coordinates,
///         a mesh that encloses no volume at the resolution, coordinates beyond 1e150 or a
///         mesh under 1e-150 across, a parameter out of range. Every numeric parameter is
///         checked first, before any voxel work, against its range in
///         `parameter_ranges` (the message names it, its range and the value).
/// \throws std::length_error when the voxel grid would need more than `memory_limit`.
///
/// \b Complexity: linear in the number of voxels of the grid and the faces and vertices
/// of the mesh, in practice (see each stage); the Reeb graph adds O((V + E) log V). Above
/// `level_of_detail_resolution`, the finer grid costs its voxelization, distance transform
/// and routing (not its thinning and pruning: those run on the coarser grid).
template <typename FaceGraph, typename Point,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Control_skeleton_report extract_control_skeleton(const FaceGraph& mesh, Control_skeleton<Point>& out,
                                                 const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Skeleton = Curve_skeleton<Point, vertex_descriptor>;

  Default_pipeline_visitor default_visitor;
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor), default_visitor);
  internal::Stage_visitor stage_visitor{[visitor](const std::string& stage, double ms) mutable {
    visitor.stage_finished(stage, ms);
  }};
  Control_skeleton_report report;
  internal::Stage_clock clock(stage_visitor, report);
  out = Control_skeleton<Point>();
  const internal::Control_skeleton_settings settings =
      internal::control_skeleton_settings(np, "extract_control_skeleton");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  internal::extract_control_skeleton_with(
      mesh, vpm, out, settings, internal::written_output<Skeleton>(np, internal_np::curve_skeleton_output_tag),
      internal::written_output<Skeleton>(np, internal_np::thinned_skeleton_output_tag),
      internal::written_output<Dense_voxel_grid>(np, internal_np::voxelized_solid_tag), clock, report);
  if(Reeb_graph<FaceGraph>* reeb = internal::written_output<Reeb_graph<FaceGraph>>(np, internal_np::reeb_graph_output_tag))
  {
    const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    std::vector<double> field(static_cast<std::size_t>(num_vertices(mesh)));
    auto field_map = boost::make_iterator_property_map(field.begin(), vim);
    geodesic_mapping_function(mesh, field_map, np);
    reeb_graph(mesh, field_map, settings.number_of_reeb_intervals, *reeb, np);
    report.reeb_nodes = num_vertices(*reeb);
    report.reeb_edges = num_edges(*reeb);
    clock.finished("reeb_graph");
  }
  return report;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_EXTRACT_CONTROL_SKELETON_H
