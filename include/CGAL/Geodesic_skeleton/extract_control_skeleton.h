// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_EXTRACT_CONTROL_SKELETON_H
#define CGAL_GEODESIC_SKELETON_EXTRACT_CONTROL_SKELETON_H

/// \file extract_control_skeleton.h
/// The whole chain of the package, mesh to control skeleton, with good defaults.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Skeleton_radius_in_voxels_map.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/coarse_skeleton_end_points.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/graft_coarse_end_branches.h>
#include <CGAL/Geodesic_skeleton/route_lone_paths_through_the_middle.h>
#include <CGAL/Geodesic_skeleton/join_pieces_joined_on_coarser_grid.h>
#include <CGAL/Geodesic_skeleton/move_skeleton_inside.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/reeb_graph.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/sheet_half_widths.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>
#include <CGAL/Geodesic_skeleton/smooth_skeleton.h>
#include <CGAL/Geodesic_skeleton/split_into_bones.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
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
  std::size_t solid_voxels = 0;    ///< voxels of the solid interior, with the links of `pieces_joined`
  std::size_t pieces_joined = 0;   ///< links between pieces that the grid of the level of detail joins (`join_pieces_joined_on_coarser_grid()`)
  Small_pieces_report small_pieces; ///< the skeleton's pieces, and the small detached ones removed
  Skeleton_statistics thinned;     ///< the curve skeleton after thinning
  std::size_t spurious_cycles_cut = 0; ///< cycles the mesh has no handle for, opened (`cut_spurious_cycles()`)
  Skeleton_statistics pruned;      ///< after pruning (Algorithm 1 and snipping)
  Pruning_report pruning;          ///< what pruning removed
  std::size_t coarse_end_branches_grafted = 0; ///< end branches of the level of detail's skeleton that pruning's result lacked, grafted (`graft_coarse_end_branches()`)
  std::size_t lone_paths_routed = 0; ///< pieces of the pruned skeleton that are a lone path, routed through the middle of the solid (`route_lone_paths_through_the_middle()`)
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
  /// "level_of_detail" (the skeleton at `level_of_detail_resolution`, when finer),
  /// "join_pieces" (when finer), "distance_transform", "thin", "thinned_graph" (the graph
  /// and counts of the thinned skeleton), "remove_small_pieces", "cut_spurious_cycles",
  /// "prune", "to_graph", "smooth", "curve_points_inside", "split_into_bones", and
  /// "reeb_graph" when asked for.
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

namespace internal {

// What an output named parameter (`curve_skeleton_output`, ...) points to, or null when it
// is not given or is a null pointer: that output is then not made.
template <typename Output, typename NamedParameters, typename Tag>
Output* output_pointer(const NamedParameters& np, Tag tag)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, tag), static_cast<Output*>(nullptr));
}

// Times stages, reports them to the visitor and records them.
template <typename Visitor>
class Stage_clock
{
public:
  Stage_clock(Visitor& visitor, Control_skeleton_report& report)
    : m_visitor(visitor), m_report(report), m_start(Clock::now()), m_stage_start(m_start)
  {}
  void finished(const char* stage)
  {
    const auto now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - m_stage_start).count();
    m_report.timings_ms.emplace_back(stage, ms);
    m_visitor.stage_finished(stage, ms);
    m_stage_start = now;
    m_report.total_ms = std::chrono::duration<double, std::milli>(now - m_start).count();
  }

private:
  using Clock = std::chrono::steady_clock;
  Visitor& m_visitor;
  Control_skeleton_report& m_report;
  Clock::time_point m_start, m_stage_start;
};

// The settings of extract_control_skeleton(), read from its named parameters; an empty
// optional is a parameter not given, whose default depends on the grid.
struct Control_skeleton_settings
{
  int resolution = default_voxel_resolution;
  bool fill_holes = true;
  bool keep_surface_voxels = true;
  double memory_limit = 0;
  std::optional<double> thin_part_radius;
  double small_piece_fraction = 0;
  double spur_length_factor = 0;
  double limb_protrusion_factor = 0;
  double lone_path_detour_factor = 0;
  int level_of_detail_resolution = default_voxel_resolution;
  std::optional<int> smoothing_window;
  std::optional<double> smallest_radius;
  double tip_joint_setback = 0;
  std::optional<double> joint_spacing;
  double joint_spacing_factor = 0;
  Bone_splitting_settings split; // bend threshold, straightness, bone lengths, chords
};

template <typename NamedParameters, typename Tag, typename T>
std::optional<T> given_parameter(const NamedParameters& np, Tag tag, T)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value)
    return std::nullopt;
  else
    return static_cast<T>(CGAL::parameters::get_parameter(np, tag));
}

// Reads every parameter of the chain and checks it (given or default) against its range
// (parameter_ranges.h), so that a bad value fails at once, before any voxel work, with a
// message that names `caller`, the parameter and its range.
template <typename NamedParameters>
Control_skeleton_settings control_skeleton_settings(const NamedParameters& np, const std::string& caller)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace ranges = parameter_ranges;
  auto checked = [&](const Parameter_range& range, auto tag, auto default_value) {
    return checked_parameter(range, choose_parameter(get_parameter(np, tag), default_value), caller);
  };
  Control_skeleton_settings s;
  s.resolution = checked(ranges::resolution, internal_np::resolution_tag, default_voxel_resolution);
  s.fill_holes = choose_parameter(get_parameter(np, internal_np::fill_holes_tag), true);
  s.keep_surface_voxels = choose_parameter(get_parameter(np, internal_np::keep_surface_voxels_tag), true);
  s.memory_limit = memory_limit(np, caller);
  s.small_piece_fraction = checked(ranges::small_piece_fraction, internal_np::small_piece_fraction_tag,
                                   ranges::small_piece_fraction.default_value);
  s.spur_length_factor = checked(ranges::spur_length_factor, internal_np::spur_length_factor_tag,
                                 ranges::spur_length_factor.default_value);
  s.limb_protrusion_factor = checked(ranges::limb_protrusion_factor, internal_np::limb_protrusion_factor_tag,
                                     ranges::limb_protrusion_factor.default_value);
  s.lone_path_detour_factor = checked(ranges::lone_path_detour_factor, internal_np::lone_path_detour_factor_tag,
                                      ranges::lone_path_detour_factor.default_value);
  checked(ranges::thin_part_radius, internal_np::thin_part_radius_tag, ranges::thin_part_radius.default_value);
  s.thin_part_radius = given_parameter(np, internal_np::thin_part_radius_tag, double());
  checked(ranges::smoothing_window, internal_np::smoothing_window_tag,
          static_cast<int>(ranges::smoothing_window.default_value));
  s.smoothing_window = given_parameter(np, internal_np::smoothing_window_tag, int());
  s.split = bone_splitting_settings(np, caller); // checks tip_joint_setback and joint_spacing too, when given
  s.joint_spacing_factor = checked(ranges::joint_spacing_factor, internal_np::joint_spacing_factor_tag,
                                   ranges::joint_spacing_factor.default_value);
  s.level_of_detail_resolution = checked(ranges::level_of_detail_resolution,
                                         internal_np::level_of_detail_resolution_tag, default_voxel_resolution);
  checked(ranges::number_of_reeb_intervals, internal_np::number_of_reeb_intervals_tag,
          static_cast<std::size_t>(ranges::number_of_reeb_intervals.default_value)); // read with the Reeb graph
  s.smallest_radius = given_parameter(np, internal_np::smallest_radius_tag, double());
  s.tip_joint_setback = choose_parameter(get_parameter(np, internal_np::tip_joint_setback_tag),
                                         ranges::tip_joint_setback.default_value);
  s.joint_spacing = given_parameter(np, internal_np::joint_spacing_tag, double());
  return s;
}

// A visitor of any type, behind one type.
struct Stage_visitor
{
  std::function<void(const std::string&, double)> stage_finished_function;
  void stage_finished(const std::string& stage, double milliseconds) { stage_finished_function(stage, milliseconds); }
};

// The voxel chain of extract_control_skeleton() (all but the Reeb graph), once its
// parameters are read: compiled once per mesh, point map and point type, whatever the
// parameter pack.
template <typename FaceGraph, typename VertexPointMap, typename Point>
void extract_control_skeleton_with(
    const FaceGraph& mesh, const VertexPointMap& vpm, Control_skeleton<Point>& out,
    const Control_skeleton_settings& settings,
    Curve_skeleton<Point, typename boost::graph_traits<FaceGraph>::vertex_descriptor>* curve_output,
    Curve_skeleton<Point, typename boost::graph_traits<FaceGraph>::vertex_descriptor>* thinned_output,
    Stage_clock<Stage_visitor>& clock, Control_skeleton_report& report)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Skeleton = Curve_skeleton<Point, vertex_descriptor>;
  // The parameters that the stages read, of one type.
  const auto np = parameters::combine(
      parameters::vertex_point_map(vpm), parameters::resolution(settings.resolution),
      parameters::fill_holes(settings.fill_holes), parameters::keep_surface_voxels(settings.keep_surface_voxels),
      parameters::memory_limit(settings.memory_limit), parameters::small_piece_fraction(settings.small_piece_fraction),
      parameters::spur_length_factor(settings.spur_length_factor),
      parameters::limb_protrusion_factor(settings.limb_protrusion_factor),
      parameters::lone_path_detour_factor(settings.lone_path_detour_factor));
  // Each stage is a public function; the mesh as voxelize() rasterised it is shared with
  // the stages that test inside and outside, so that none reads the mesh again.
  Dense_voxel_grid solid;
  Voxelized_surface surface;
  report.solid_voxels = voxelize(mesh, solid, parameters::combine(parameters::voxelized_surface_output(&surface), np));
  report.resolution = settings.resolution;
  report.voxel_size = solid.frame().voxel_size();
  clock.finished("voxelize");
  const auto with_surface = parameters::combine(parameters::voxelized_surface(&std::as_const(surface)), np);

  // A finer grid than the level of detail's takes from it which branches and which pieces
  // the rig has (the resolution is a sampling choice, not a modelling one).
  report.level_of_detail_resolution = settings.level_of_detail_resolution;
  const bool finer_than_level_of_detail =
      report.level_of_detail_resolution > 0 && report.level_of_detail_resolution < report.resolution;
  std::optional<Coarse_skeleton_level_of_detail> coarse;
  if(finer_than_level_of_detail)
    coarse = coarse_skeleton_level_of_detail(mesh, report.level_of_detail_resolution, solid.frame(), np);
  clock.finished("level_of_detail");
  if(coarse)
  {
    report.pieces_joined = join_pieces_joined_on_coarser_grid(solid, coarse->solid);
    report.solid_voxels = solid.size();
    coarse->solid = Dense_voxel_grid(); // not needed further
  }
  clock.finished("join_pieces");

  const Voxel_distance_field distances = distance_transform(solid, np);
  clock.finished("distance_transform");

  // The sheet radii let pruning judge the twigs of a thin sheet by its width; the parts
  // thin at the default resolution are thin at any other.
  report.thin_part_radius = settings.thin_part_radius.value_or(default_thin_part_radius(report.resolution));
  Sheet_radii sheet_radii, slanted_sheet_radii;
  thin(solid, distances,
       parameters::combine(
           parameters::sheet_radius_map(boost::associative_property_map<Sheet_radii>(sheet_radii)),
           parameters::slanted_sheet_radius_map(boost::associative_property_map<Sheet_radii>(slanted_sheet_radii)),
           parameters::thin_part_radius(report.thin_part_radius), np));
  Sparse_voxel_set skeleton;
  skeleton.reset(solid.frame(), solid.bounding_box());
  solid.for_each([&](const Voxel_key& k) { skeleton.insert(k); });
  clock.finished("thin");

  if(thinned_output != nullptr)
  {
    Skeleton thinned;
    to_graph(skeleton, distances, mesh, thinned, with_surface);
    report.thinned = skeleton_statistics(thinned);
    *thinned_output = std::move(thinned);
  }
  else
    report.thinned = skeleton_statistics_of_voxels(skeleton);
  clock.finished("thinned_graph");

  report.small_pieces = remove_small_pieces(skeleton, distances, np);
  clock.finished("remove_small_pieces");

  report.spurious_cycles_cut = cut_spurious_cycles(skeleton, mesh, with_surface);
  clock.finished("cut_spurious_cycles");
  // Pruning judges a piece's twigs by its widest sheet, and may keep a chain beside it. On
  // the grid of the level of detail, the widest sheet is read across close levels, which
  // measures a thick slanted plate; a finer grid gets it from that grid (`coarse` above).
  const Sheet_radii widest_sheet_of_piece =
      widest_sheet_radius_of_pieces(skeleton, finer_than_level_of_detail ? sheet_radii : slanted_sheet_radii);

  // The end branches that a finer grid resolves beyond the level of detail of the default
  // one are snipped as long as the skeleton has more end points than it has there.
  const double coarse_tolerance =
      coarse ? default_coarse_end_point_tolerance(report.resolution, report.level_of_detail_resolution)
             : parameter_ranges::coarse_end_point_tolerance.default_value;
  report.pruning = prune_skeleton(
      skeleton,
      parameters::combine(
          parameters::mat_radius_map(mat_radius_in_voxels_map(distances)),
          parameters::sheet_radius_map(sheet_radius_in_voxels_map(sheet_radii)),
          parameters::piece_radius_map(sheet_radius_in_voxels_map(widest_sheet_of_piece)),
          parameters::coarse_end_points(coarse ? &std::as_const(coarse->end_points) : nullptr),
          parameters::coarse_end_point_tolerance(coarse_tolerance), np));
  // And the limbs that the finer grid's thinning did not make are grafted back.
  if(coarse)
    report.coarse_end_branches_grafted = graft_coarse_end_branches(
        skeleton, distances, coarse->end_points, parameters::coarse_end_point_tolerance(coarse_tolerance));
  // And a lone path keeps its ends but not a detour that thinning took between them.
  report.lone_paths_routed = route_lone_paths_through_the_middle(skeleton, distances, np);
  clock.finished("prune");

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
  // A thin sheet's chain is split in lengths of the sheet's width, and a piece at the level
  // of detail of its widest sheet, as pruning judged them, and at least as wide as the
  // coarser grid measures it.
  const std::vector<double> sheet_widths = sheet_half_widths(curve, sheet_radii, report.voxel_size);
  std::vector<double> piece_widths = sheet_half_widths(curve, widest_sheet_of_piece, report.voxel_size);
  if(coarse)
  {
    const std::vector<double> coarse_widths = coarse_piece_half_widths(curve, *coarse);
    for(std::size_t v = 0; v < piece_widths.size(); ++v)
      piece_widths[v] = (std::max)(piece_widths[v], coarse_widths[v]);
  }
  // Chains end short of the tips and long bones get joints in between, as artists place them;
  // the spacing is a share of the whole shape, so a character gets as many joints at any size.
  report.tip_joint_setback = settings.tip_joint_setback;
  report.joint_spacing = settings.joint_spacing.value_or(
      default_joint_spacing(report.voxel_size, report.resolution, settings.joint_spacing_factor));
  split_into_bones(curve, out,
                   parameters::combine(parameters::smallest_radius(report.smallest_radius),
                                       parameters::tip_joint_setback(report.tip_joint_setback),
                                       parameters::joint_spacing(report.joint_spacing),
                                       parameters::sheet_half_width_map(CGAL::make_property_map(sheet_widths)),
                                       parameters::piece_radius_map(CGAL::make_property_map(piece_widths)),
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

/// \ingroup PkgGeodesicSkeletonRef
/// Extracts the animation control skeleton of a mesh: the whole chain of the package with
/// good defaults. In order: `voxelize()` (solid interior on a grid aligned with the
/// principal axes), `distance_transform()` (the MAT radius), `thin()` (grassfire, a
/// one-voxel-thick curve skeleton), `prune_skeleton()` (the paper's Algorithm 1 and the
/// package's addition to it, the snipping of spurious branches), `to_graph()` (the curve
/// skeleton, with the mesh vertices mapped to it), `smooth_skeleton()` (5-point moving
/// average) and `split_into_bones()` (joints and bones, rooted at the most central
/// junction; its chains end short of the tips and its long bones are cut at a spacing, as
/// artists place joints: `tip_joint_setback`, `joint_spacing_factor`).
///
/// `thin()` also records the sheet radius of the voxels it keeps (its `sheet_radius_map`),
/// and `prune_skeleton()` gets them beside the MAT radii (its `sheet_radius_map` and
/// `mat_radius_map`): it judges each voxel by the larger of the two radii, so that the
/// twigs of a thin sheet (a wing, a fin, a plate) are pruned by the sheet's width, not its
/// thickness, and snips the end branches that lie inside the MAT balls of the rest of the
/// skeleton (the comb of parallel curves that thinning leaves in a thick sheet); `split_into_bones()`
/// gets the same widths in world units (`sheet_half_widths()`, its `sheet_half_width_map`),
/// so that a sheet's chain is split in lengths of its width, and the widest sheet of each
/// piece before pruning (`widest_sheet_radius_of_pieces()`, its `piece_radius_map`), so that
/// a piece's level of detail is the one its pruning judged by, whichever chain the pruning kept.
/// On the grid of the level of detail (at `level_of_detail_resolution` and coarser), that
/// widest sheet is read across close levels (`thin()`'s `slanted_sheet_radius_map`), and
/// pruning gets it too (its `piece_radius_map`): the middle of a thick plate slanted in the
/// grid lies on several levels of distance, whose rounds each measure a strip of it, not the
/// plate. A finer grid reads its own levels, and the split takes the larger of its width
/// and the coarser grid's (below).
///
/// Between `thin()` and `prune_skeleton()`, `remove_small_pieces()` removes the skeletons
/// of the detached pieces whose solid is smaller than `small_piece_fraction` of the largest
/// (a character's loose eyes or teeth): their mesh vertices map to the nearest point of the
/// remaining skeleton, so the result has one tree per body; then `cut_spurious_cycles()`
/// opens the cycles of the skeleton that the mesh has no handle for (where parts come
/// within a voxel of each other, the solid joins them).
///
/// At a resolution finer than `level_of_detail_resolution` (default: the default
/// resolution, 64), `coarse_skeleton_level_of_detail()` first runs the same voxel stages at
/// that resolution, up to `prune_skeleton()`, right after `voxelize()`. The pieces that its
/// solid joins (parts within about a voxel of that grid of each other) are joined on the
/// finer grid too (`join_pieces_joined_on_coarser_grid()`, before `distance_transform()`),
/// so that which parts the rig joins does not depend on the resolution. The end points of
/// that skeleton's graph are given to the finer `prune_skeleton()` (its `coarse_end_points`, with
/// `default_coarse_end_point_tolerance()`, 4 voxels of the coarser grid; none when the mesh
/// encloses no volume there): the finer skeleton then keeps no more end points than the
/// coarser one has, where its extra end branches are detail under 3 times the level of
/// detail (the resolution is a sampling choice; which branches the rig has should not
/// depend on it); after pruning, `graft_coarse_end_branches()` grafts back, along the middle
/// of the solid, the limbs that the coarser skeleton ends in and that thinning on the finer
/// grid left as stubs, while the finer skeleton has fewer end points (its time is part of
/// the stage "prune"). Last in that stage, on every grid,
/// `route_lone_paths_through_the_middle()` routes a piece that is a lone path through the
/// middle of the solid between its two end points where thinning left it a detour (a U
/// across a thick sheet). The widest sheet of each piece of the coarser skeleton is read at
/// the nearest vertices of the curve skeleton (`coarse_piece_half_widths()`): the piece
/// radius that `split_into_bones()` gets is at least that.
///
/// Between `smooth_skeleton()` and `split_into_bones()`, `move_skeleton_inside()`: when the
/// mesh is a closed triangle mesh, a point of the curve skeleton that lies outside it
/// (smoothing averages the points along the bends of the skeleton, which in a limb a few
/// voxels thin can take one out) moves to the nearest point of the surface and a quarter
/// voxel further in, so that every point of the curve skeleton is inside the mesh (by the
/// non-zero winding rule of the voxel stages), and with them every joint and every point of
/// the bones, which are curve-skeleton points. An open mesh has no inside to test, and its
/// points stay where the skeleton puts them.
///
/// The function is a composition of these public stages and nothing else: the same calls
/// made by hand give the same result (the manual's data flow shows them). `voxelize()`
/// hands the mesh as it rasterised it (`Voxelized_surface`) to the stages that test inside
/// and outside, so that the mesh is read and transformed once.
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
///                           in voxels, in [0, 1000]}
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
///   \cgalParamNBegin{lone_path_detour_factor}
///     \cgalParamDescription{the setting of `route_lone_paths_through_the_middle()`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
///   \cgalParamNBegin{level_of_detail_resolution}
///     \cgalParamDescription{the resolution whose skeleton's end points decide how many end
///                           points a finer skeleton keeps and where its branches end
///                           (`prune_skeleton()`'s `coarse_end_points`), an integer in
///                           [0, 8192]; 0, or a value not below `resolution`, turns this off}
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
///     \cgalParamExtra{For this output and the next two, a null pointer is the same as
///                     none.}
///   \cgalParamNEnd
///   \cgalParamNBegin{thinned_skeleton_output}
///     \cgalParamDescription{receives the skeleton straight after thinning, before pruning
///                           (package parameter)}
///     \cgalParamType{a pointer to a `Curve_skeleton<Point, vertex_descriptor>`}
///     \cgalParamDefault{none}
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
/// `level_of_detail_resolution`, the voxel stages at that resolution add their cost, a
/// fraction (that resolution over the resolution, cubed) of the voxel work.
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
  internal::Stage_clock<internal::Stage_visitor> clock(stage_visitor, report);
  out = Control_skeleton<Point>();
  const internal::Control_skeleton_settings settings =
      internal::control_skeleton_settings(np, "extract_control_skeleton");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  internal::extract_control_skeleton_with(
      mesh, vpm, out, settings, internal::output_pointer<Skeleton>(np, internal_np::curve_skeleton_output_tag),
      internal::output_pointer<Skeleton>(np, internal_np::thinned_skeleton_output_tag), clock, report);
  if(Reeb_graph<FaceGraph>* reeb = internal::output_pointer<Reeb_graph<FaceGraph>>(np, internal_np::reeb_graph_output_tag))
  {
    const std::size_t intervals =
        choose_parameter(get_parameter(np, internal_np::number_of_reeb_intervals_tag),
                         static_cast<std::size_t>(parameter_ranges::number_of_reeb_intervals.default_value));
    const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    std::vector<double> field(static_cast<std::size_t>(num_vertices(mesh)));
    auto field_map = boost::make_iterator_property_map(field.begin(), vim);
    geodesic_mapping_function(mesh, field_map, np);
    reeb_graph(mesh, field_map, intervals, *reeb, np);
    report.reeb_nodes = num_vertices(*reeb);
    report.reeb_edges = num_edges(*reeb);
    clock.finished("reeb_graph");
  }
  return report;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_EXTRACT_CONTROL_SKELETON_H
