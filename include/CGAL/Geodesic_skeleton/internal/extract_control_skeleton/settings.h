// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_EXTRACT_CONTROL_SKELETON_SETTINGS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_EXTRACT_CONTROL_SKELETON_SETTINGS_H

// The settings, stage clock and visitor of extract_control_skeleton(): not part of the API.

#include <CGAL/Geodesic_skeleton/Control_skeleton_report.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/split_into_bones.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A visitor of any type, behind one type.
struct Stage_visitor
{
  std::function<void(const std::string&, double)> stage_finished_function;
  void stage_finished(const std::string& stage, double milliseconds) { stage_finished_function(stage, milliseconds); }
};

// Times stages, reports them to the visitor and records them.
class Stage_clock
{
public:
  Stage_clock(Stage_visitor& visitor, Control_skeleton_report& report)
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
  Stage_visitor& m_visitor;
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
  double sheet_lobe_reach_factor = 0;
  int level_of_detail_resolution = default_voxel_resolution;
  std::optional<int> smoothing_window;
  std::optional<double> smallest_radius;
  std::optional<double> joint_spacing;
  double joint_spacing_factor = 0;
  std::size_t number_of_reeb_intervals = 0;
  Bone_splitting_settings split; // bend threshold, straightness, bone lengths, chords
};

// The parameter when given, converted to T.
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
  // A parameter whose default depends on the resolution: checked as given (before any
  // conversion to T), and left unset when not given.
  auto checked_when_given = [&](const Parameter_range& range, auto tag, auto type) {
    checked(range, tag, decltype(type)(range.default_value));
    return given_parameter(np, tag, type);
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
  s.sheet_lobe_reach_factor = checked(ranges::sheet_lobe_reach_factor, internal_np::sheet_lobe_reach_factor_tag,
                                      ranges::sheet_lobe_reach_factor.default_value);
  s.thin_part_radius = checked_when_given(ranges::thin_part_radius, internal_np::thin_part_radius_tag, double());
  s.smoothing_window = checked_when_given(ranges::smoothing_window, internal_np::smoothing_window_tag, int());
  s.split = bone_splitting_settings(np, caller); // tip_joint_setback too; joint_spacing when given
  s.joint_spacing_factor = checked(ranges::joint_spacing_factor, internal_np::joint_spacing_factor_tag,
                                   ranges::joint_spacing_factor.default_value);
  s.level_of_detail_resolution = checked(ranges::level_of_detail_resolution,
                                         internal_np::level_of_detail_resolution_tag, default_voxel_resolution);
  s.number_of_reeb_intervals = checked(ranges::number_of_reeb_intervals, internal_np::number_of_reeb_intervals_tag,
                                       static_cast<std::size_t>(ranges::number_of_reeb_intervals.default_value));
  s.smallest_radius = given_parameter(np, internal_np::smallest_radius_tag, double());
  s.joint_spacing = given_parameter(np, internal_np::joint_spacing_tag, double());
  return s;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_EXTRACT_CONTROL_SKELETON_SETTINGS_H
