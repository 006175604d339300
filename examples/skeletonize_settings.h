// The settings of the chain and of the skin weights that skeletonize takes as options and
// the Python module (python/) as keyword arguments: their values, the one table of the
// numeric ones (the option, the named parameter with its library range, what it is for),
// and the calls that hand them to the library as named parameters. Both programs read the
// table, so an option, a keyword and a range cannot drift apart.

#ifndef GEODESIC_SKELETON_EXAMPLES_SKELETONIZE_SETTINGS_H
#define GEODESIC_SKELETON_EXAMPLES_SKELETONIZE_SETTINGS_H

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/reeb_graph.h>
#include <CGAL/Geodesic_skeleton/smooth_skeleton.h>
#include <CGAL/Geodesic_skeleton/thin.h>

#include <cstddef>
#include <optional>
#include <string>

namespace skeletonize_settings {

namespace gs = CGAL::Geodesic_skeleton;
namespace ranges = CGAL::Geodesic_skeleton::parameter_ranges;

// The values; the defaults are the library's (CGAL/Geodesic_skeleton/parameter_ranges.h).
struct Settings
{
  int resolution = gs::default_voxel_resolution;
  double small_piece_fraction = ranges::small_piece_fraction.default_value;
  double spur_length_factor = ranges::spur_length_factor.default_value;
  double limb_protrusion_factor = ranges::limb_protrusion_factor.default_value;
  double sheet_lobe_reach_factor = ranges::sheet_lobe_reach_factor.default_value;
  int level_of_detail_resolution = int(ranges::level_of_detail_resolution.default_value);
  std::optional<int> smoothing_window;    // none: the library's default for the resolution
  std::optional<double> thin_part_radius; // none: the library's default for the resolution
  double bend_threshold = ranges::bend_threshold.default_value;
  double straightness_tolerance = ranges::straightness_tolerance.default_value;
  double minimum_bone_length_factor = ranges::minimum_bone_length_factor.default_value;
  double maximum_bone_length_factor = ranges::maximum_bone_length_factor.default_value;
  double minimum_bone_length_of_piece_factor = ranges::minimum_bone_length_of_piece_factor.default_value;
  double tip_joint_setback = ranges::tip_joint_setback.default_value;
  double joint_spacing_factor = ranges::joint_spacing_factor.default_value;
  std::optional<double> smallest_radius; // world units; none: extract_control_skeleton()'s default
  std::size_t reeb_intervals = static_cast<std::size_t>(ranges::number_of_reeb_intervals.default_value);
  bool fill_holes = true;
  bool keep_surface_voxels = true;
  int max_bones_per_vertex = static_cast<int>(ranges::max_bones_per_vertex.default_value);
  double sharpness = ranges::sharpness.default_value;
  double minimum_weight = ranges::minimum_weight.default_value;
  double influence_ratio = ranges::influence_ratio.default_value;
};

// Which calls read a setting.
enum Use : unsigned
{
  chain = 1,  // extract_control_skeleton()
  weights = 2 // compute_skinning_weights()
};

// A numeric setting: the option of skeletonize, the named parameter and its range (the
// keyword of the Python module is the range's name), the calls that read it, and how a
// checked value is stored.
struct Numeric_setting
{
  const char* option;
  const char* metavar;
  const gs::Parameter_range& range;
  unsigned use;
  void (*set)(Settings&, double);
  const char* help;
  const char* default_text = nullptr; // when the default is not the range's: its words
};

#define GEODESIC_SKELETON_SETTING(MEMBER) \
  [](Settings& s, double v) { s.MEMBER = static_cast<decltype(s.MEMBER)>(v); }

inline const Numeric_setting numeric_settings[] = {
    {"--resolution", "N", ranges::resolution, chain | weights, GEODESIC_SKELETON_SETTING(resolution),
     "the longest principal extent of the mesh, in voxels"},
    {"--small-pieces", "F", ranges::small_piece_fraction, chain, GEODESIC_SKELETON_SETTING(small_piece_fraction),
     "drop detached pieces smaller than F times the largest (0 keeps all)"},
    {"--thin-part-radius", "R", ranges::thin_part_radius, chain, GEODESIC_SKELETON_SETTING(thin_part_radius),
     "thinning: parts of MAT radius up to R voxels are thin and burn from their rim",
     "1.41 at resolution 64 and below, scaled with it: 2.83 at 128"},
    {"--spur-length", "F", ranges::spur_length_factor, chain, GEODESIC_SKELETON_SETTING(spur_length_factor),
     "snip end branches shorter than F MAT radii"},
    {"--limb-protrusion", "F", ranges::limb_protrusion_factor, chain, GEODESIC_SKELETON_SETTING(limb_protrusion_factor),
     "level of detail: snip end branches reaching less than F largest MAT radii out of their junction"},
    {"--sheet-lobe-reach", "F", ranges::sheet_lobe_reach_factor, chain,
     GEODESIC_SKELETON_SETTING(sheet_lobe_reach_factor),
     "a branch into each lobe of a thick plate reaching F largest MAT radii out of the thinned skeleton's balls (0: none)"},
    {"--level-of-detail-resolution", "N", ranges::level_of_detail_resolution, chain,
     GEODESIC_SKELETON_SETTING(level_of_detail_resolution),
     "level of detail: the skeleton's branches are decided at N; a finer resolution routes them on its grid (0: off)"},
    {"--smoothing-window", "W", ranges::smoothing_window, chain, GEODESIC_SKELETON_SETTING(smoothing_window),
     "points averaged along branches", "5 at resolution 64, scaled with it: 9 at 128"},
    {"--bend-threshold", "T", ranges::bend_threshold, chain, GEODESIC_SKELETON_SETTING(bend_threshold),
     "chord-to-point accumulation that makes a joint"},
    {"--straightness", "S", ranges::straightness_tolerance, chain, GEODESIC_SKELETON_SETTING(straightness_tolerance),
     "allowed bone deviation in MAT radii (at least a quarter of the thickest part's)"},
    {"--min-bone-length", "F", ranges::minimum_bone_length_factor, chain,
     GEODESIC_SKELETON_SETTING(minimum_bone_length_factor), "every bone is longer than F MAT radii"},
    {"--max-bone-length", "F", ranges::maximum_bone_length_factor, chain,
     GEODESIC_SKELETON_SETTING(maximum_bone_length_factor),
     "longest straight bone in MAT radii, cut at its narrowings (0: no limit)"},
    {"--min-bone-length-of-piece", "F", ranges::minimum_bone_length_of_piece_factor, chain,
     GEODESIC_SKELETON_SETTING(minimum_bone_length_of_piece_factor),
     "level of detail: every bone is longer than F largest MAT radii of its piece"},
    {"--tip-setback", "F", ranges::tip_joint_setback, chain, GEODESIC_SKELETON_SETTING(tip_joint_setback),
     "a tip's joint sits F lengths of its bone back from the tip, where artists end a chain"},
    {"--joint-spacing", "F", ranges::joint_spacing_factor, chain, GEODESIC_SKELETON_SETTING(joint_spacing_factor),
     "bones are cut into lengths of about F times the mesh's longest extent (0: not cut)"},
    {"--smallest-radius", "R", ranges::smallest_radius, chain, GEODESIC_SKELETON_SETTING(smallest_radius),
     "the split counts radii under R (world units) as R: thin parts get few joints",
     "the longest principal extent / 128"},
    {"--reeb-intervals", "N", ranges::number_of_reeb_intervals, chain, GEODESIC_SKELETON_SETTING(reeb_intervals),
     "intervals of the Reeb graph reported for comparison"},
    {"--max-bones", "K", ranges::max_bones_per_vertex, weights, GEODESIC_SKELETON_SETTING(max_bones_per_vertex),
     "skinning: bones that may influence one vertex"},
    {"--sharpness", "Q", ranges::sharpness, weights, GEODESIC_SKELETON_SETTING(sharpness),
     "skinning: exponent of the diffused weights (larger: sharper transitions at the joints)"},
    {"--min-weight", "W", ranges::minimum_weight, weights, GEODESIC_SKELETON_SETTING(minimum_weight),
     "skinning: weights under W of a vertex's total are dropped"},
    {"--influence-ratio", "S", ranges::influence_ratio, weights, GEODESIC_SKELETON_SETTING(influence_ratio),
     "skinning: bones up to S times as far as the nearest (through the solid) may heat a vertex"},
};

#undef GEODESIC_SKELETON_SETTING

// The setting of an option of skeletonize ("--resolution"), or null.
inline const Numeric_setting* setting_of_option(const std::string& option)
{
  for(const Numeric_setting& s : numeric_settings)
    if(option == s.option)
      return &s;
  return nullptr;
}

// The setting of a named parameter ("resolution"), or null.
inline const Numeric_setting* setting_of_parameter(const std::string& name)
{
  for(const Numeric_setting& s : numeric_settings)
    if(name == s.range.name)
      return &s;
  return nullptr;
}

// What extract_control_skeleton() may also hand back; a null pointer skips that output.
template <typename Mesh, typename Point>
struct Chain_outputs
{
  using Skeleton = gs::Curve_skeleton<Point, typename boost::graph_traits<Mesh>::vertex_descriptor>;
  Skeleton* curve = nullptr;
  Skeleton* thinned = nullptr;
  gs::Reeb_graph<Mesh>* reeb = nullptr;
  gs::Dense_voxel_grid* solid = nullptr; // the voxelized solid, for the weights
};

// gs::extract_control_skeleton() with the settings `s` as its named parameters.
template <typename Mesh, typename Point>
gs::Control_skeleton_report extract_control_skeleton(const Mesh& mesh, gs::Control_skeleton<Point>& control,
                                                     const Settings& s, const Chain_outputs<Mesh, Point>& out)
{
  namespace params = CGAL::Geodesic_skeleton::parameters;
  const auto np = params::combine(
      params::resolution(s.resolution), params::fill_holes(s.fill_holes),
      params::keep_surface_voxels(s.keep_surface_voxels), params::small_piece_fraction(s.small_piece_fraction),
      params::thin_part_radius(s.thin_part_radius.value_or(gs::default_thin_part_radius(s.resolution))),
      params::spur_length_factor(s.spur_length_factor), params::limb_protrusion_factor(s.limb_protrusion_factor),
      params::sheet_lobe_reach_factor(s.sheet_lobe_reach_factor),
      params::level_of_detail_resolution(s.level_of_detail_resolution),
      params::smoothing_window(s.smoothing_window.value_or(gs::default_smoothing_window(s.resolution))),
      params::bend_threshold(s.bend_threshold), params::straightness_tolerance(s.straightness_tolerance),
      params::minimum_bone_length_factor(s.minimum_bone_length_factor),
      params::maximum_bone_length_factor(s.maximum_bone_length_factor),
      params::minimum_bone_length_of_piece_factor(s.minimum_bone_length_of_piece_factor),
      params::tip_joint_setback(s.tip_joint_setback), params::joint_spacing_factor(s.joint_spacing_factor),
      params::number_of_reeb_intervals(s.reeb_intervals), params::curve_skeleton_output(out.curve),
      params::thinned_skeleton_output(out.thinned), params::reeb_graph_output(out.reeb),
      params::voxelized_solid(out.solid));
  // Without a smallest radius, the library's default (it depends on the mesh's extent).
  return s.smallest_radius
             ? gs::extract_control_skeleton(mesh, control, params::combine(params::smallest_radius(*s.smallest_radius), np))
             : gs::extract_control_skeleton(mesh, control, np);
}

// gs::compute_skinning_weights() with the settings `s` as its named parameters; `solid`:
// the chain's voxelization of the mesh at `s.resolution`, or null to voxelize again;
// `parallel`: on all the cores (CGAL::Parallel_tag), else on the caller's thread.
template <typename Mesh, typename Point, typename WeightMap, typename SegmentMap>
gs::Skinning_report compute_skinning_weights(const Mesh& mesh, const gs::Control_skeleton<Point>& control,
                                             const Settings& s, const gs::Dense_voxel_grid* solid,
                                             WeightMap weights, SegmentMap segment, bool parallel)
{
  namespace params = CGAL::Geodesic_skeleton::parameters;
  const auto np =
      params::combine(params::resolution(s.resolution), params::fill_holes(s.fill_holes),
                      params::keep_surface_voxels(s.keep_surface_voxels), params::voxelized_solid(solid),
                      params::max_bones_per_vertex(s.max_bones_per_vertex), params::sharpness(s.sharpness),
                      params::minimum_weight(s.minimum_weight), params::influence_ratio(s.influence_ratio),
                      params::bone_segmentation_map(segment));
  return parallel ? gs::compute_skinning_weights<CGAL::Parallel_tag>(mesh, control, weights, np)
                  : gs::compute_skinning_weights<CGAL::Sequential_tag>(mesh, control, weights, np);
}

} // namespace skeletonize_settings

#endif // GEODESIC_SKELETON_EXAMPLES_SKELETONIZE_SETTINGS_H
