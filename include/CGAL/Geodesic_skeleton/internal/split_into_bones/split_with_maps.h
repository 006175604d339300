// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SPLIT_INTO_BONES_SPLIT_WITH_MAPS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SPLIT_INTO_BONES_SPLIT_WITH_MAPS_H

// The body of split_into_bones(): its settings read from the named parameters and checked,
// and Algorithm 2 on a curve skeleton read through its point, radius and length maps.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/split_into_bones/bone_splitting.h>
#include <CGAL/Geodesic_skeleton/internal/split_into_bones/chain_joints.h>
#include <CGAL/Geodesic_skeleton/internal/split_into_bones/control_tree.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_branches.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_vertex_maps.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/number_utils.h>

#include <boost/graph/connected_components.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The settings of split_into_bones(), checked; `caller` names the function in the errors.
template <typename NamedParameters>
Bone_splitting_settings bone_splitting_settings(const NamedParameters& np,
                                                const std::string& caller = "split_into_bones")
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace ranges = parameter_ranges;
  Bone_splitting_settings s{
      choose_parameter(get_parameter(np, internal_np::bend_threshold_tag), ranges::bend_threshold.default_value),
      choose_parameter(get_parameter(np, internal_np::straightness_tolerance_tag),
                       ranges::straightness_tolerance.default_value),
      choose_parameter(get_parameter(np, internal_np::minimum_bone_length_factor_tag),
                       ranges::minimum_bone_length_factor.default_value),
      choose_parameter(get_parameter(np, internal_np::maximum_bone_length_factor_tag),
                       ranges::maximum_bone_length_factor.default_value),
      choose_parameter(get_parameter(np, internal_np::chord_length_factors_tag),
                       std::vector<double>{ranges::chord_length_factor.default_value,
                                           2 * ranges::chord_length_factor.default_value}),
      choose_parameter(get_parameter(np, internal_np::smallest_radius_tag), ranges::smallest_radius.default_value),
      choose_parameter(get_parameter(np, internal_np::minimum_bone_length_of_piece_factor_tag),
                       ranges::minimum_bone_length_of_piece_factor.default_value),
      choose_parameter(get_parameter(np, internal_np::tip_joint_setback_tag),
                       ranges::tip_joint_setback.default_value),
      choose_parameter(get_parameter(np, internal_np::joint_spacing_tag), ranges::joint_spacing.default_value)};
  checked_parameter(ranges::bend_threshold, s.bend_threshold, caller);
  checked_parameter(ranges::straightness_tolerance, s.straightness_tolerance, caller);
  checked_parameter(ranges::minimum_bone_length_factor, s.minimum_bone_length_factor, caller);
  checked_parameter(ranges::maximum_bone_length_factor, s.maximum_bone_length_factor, caller);
  checked_parameter(ranges::smallest_radius, s.smallest_radius, caller);
  checked_parameter(ranges::minimum_bone_length_of_piece_factor, s.minimum_bone_length_of_piece_factor, caller);
  checked_parameter(ranges::tip_joint_setback, s.tip_joint_setback, caller);
  checked_parameter(ranges::joint_spacing, s.joint_spacing, caller);
  if(s.chord_length_factors.empty())
    throw std::invalid_argument(caller + ": chord_length_factors must not be empty");
  for(double f : s.chord_length_factors)
    checked_parameter(ranges::chord_length_factor, f, caller, "each of chord_length_factors");
  return s;
}

// Per vertex of `skeleton` (vertices numbered 0 to n-1): the largest of `radii` over its
// connected component.
template <typename CurveSkeleton>
std::vector<double> largest_radius_of_pieces(const CurveSkeleton& skeleton, const std::vector<double>& radii)
{
  const std::size_t n = radii.size();
  std::vector<std::size_t> piece(n);
  const std::size_t pieces = n == 0 ? 0 : boost::connected_components(
      skeleton, boost::make_iterator_property_map(piece.begin(), get(boost::vertex_index, skeleton)));
  std::vector<double> largest(pieces, 0.0);
  for(std::size_t v = 0; v < n; ++v)
    largest[piece[v]] = std::max(largest[piece[v]], radii[v]);
  std::vector<double> of_vertex(n);
  for(std::size_t v = 0; v < n; ++v)
    of_vertex[v] = largest[piece[v]];
  return of_vertex;
}

// The lengths that `map` gives at vertices 0 to n-1; throws, with `error` as the message,
// when one is negative or not finite.
template <typename LengthMap>
std::vector<double> checked_lengths(const LengthMap& map, std::size_t n, const char* error)
{
  std::vector<double> lengths(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    lengths[v] = static_cast<double>(get(map, v));
    if(!(lengths[v] >= 0) || !std::isfinite(lengths[v]))
      throw std::invalid_argument(error);
  }
  return lengths;
}

// Per-vertex lengths that a split reads besides the MAT radii; each empty when the vertex
// bundle has none.
struct Split_length_maps
{
  std::vector<double> sheet_half_widths; // the vertices' `sheet_half_width`
  std::vector<double> piece_radii;       // the vertices' `piece_radius`
};

// The `sheet_half_width` and `piece_radius` members of the vertices of `skeleton` (vertices
// numbered 0 to n-1), empty when its vertex bundle has none; throws when one is negative or
// not finite.
template <typename CurveSkeleton>
Split_length_maps split_length_maps(const CurveSkeleton& skeleton)
{
  using Bundle = vertex_bundle_t<CurveSkeleton>;
  if constexpr(has_sheet_members<Bundle>::value)
    return {checked_lengths(get(&Bundle::sheet_half_width, skeleton), num_vertices(skeleton),
                            "split_into_bones: a vertex's sheet_half_width is negative or not finite"),
            checked_lengths(get(&Bundle::piece_radius, skeleton), num_vertices(skeleton),
                            "split_into_bones: a vertex's piece_radius is negative or not finite")};
  else
    return {};
}

// Algorithm 2 on a skeleton read through its point and radius maps: the body of
// split_into_bones(), with the settings checked and `control` cleared; throws when a
// radius is negative or not finite, or a point not finite. Each of `lengths` is empty or has one value per vertex.
template <typename CurveSkeleton, typename VertexPointMap, typename RadiusMap, typename Point>
void split_into_bones_with_maps(const CurveSkeleton& skeleton, const VertexPointMap& point_map,
                                const RadiusMap& radius_map, const Split_length_maps& lengths,
                                const Bone_splitting_settings& settings, Control_skeleton<Point>& control)
{
  const std::size_t n = num_vertices(skeleton);
  if(n == 0)
    return;

  const std::vector<double> radii_of =
      checked_lengths(radius_map, n, "split_into_bones: the MAT radius map gives a negative or non-finite radius");
  auto radius = [&](std::size_t v) { return radii_of[v]; };
  // The radius that the lengths of the split are measured in: at least `smallest_radius`,
  // so that parts thinner than it (which a finer grid measures thinner) get no more joints;
  // in a thin sheet, its half width, so that a wing's chain gets the joints of a limb as
  // wide, not of one as thin.
  std::vector<double> length_unit_of(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    length_unit_of[v] = (std::max)(radii_of[v], settings.smallest_radius);
    if(!lengths.sheet_half_widths.empty())
      length_unit_of[v] = (std::max)(length_unit_of[v], lengths.sheet_half_widths[v]);
  }
  Joint_graph<Point> graph;
  std::vector<long> joint_of(n, -1);
  auto position = [&](std::size_t v) {
    const auto p = get(point_map, v);
    return Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  for(std::size_t v = 0; v < n; ++v)
    for(double c : position(v))
      if(!std::isfinite(c))
        throw std::invalid_argument("split_into_bones: a vertex's point has a non-finite coordinate");
  auto add_joint = [&](std::size_t v, Joint_kind kind) {
    if(joint_of[v] < 0)
    {
      const Vec3 p = position(v);
      Control_joint<Point> joint;
      joint.point = Point(p[0], p[1], p[2]);
      joint.radius = radius(v);
      joint.kind = kind;
      joint.skeleton_vertex = v;
      joint_of[v] = static_cast<long>(add_vertex(joint, graph));
    }
    return static_cast<std::size_t>(joint_of[v]);
  };
  // The junctions, and the points of a piece of one point; the joints of the tips are placed
  // with the branches that end there (set back from the tip when asked).
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::size_t d = boost::degree(v, skeleton);
    if(d >= 3 || d == 0)
      add_joint(v, d >= 3 ? Joint_kind::junction : Joint_kind::end);
  }

  // The level of detail of a piece: its largest length unit, or the vertices' `piece_radius`
  // over the piece (the widest sheet before pruning) where larger.
  std::vector<double> piece_scale_of = length_unit_of;
  if(!lengths.piece_radii.empty())
    for(std::size_t v = 0; v < n; ++v)
      piece_scale_of[v] = (std::max)(piece_scale_of[v], lengths.piece_radii[v]);
  const std::vector<double> largest_radius_of_piece = largest_radius_of_pieces(skeleton, piece_scale_of);
  for(Skeleton_branch branch : skeleton_branches(skeleton))
  {
    std::vector<std::size_t>& b = branch.vertices;
    if(branch.closed) // start and end the loop at its thickest vertex, a joint
    {
      std::size_t thickest = 0;
      for(std::size_t k = 1; k < b.size(); ++k)
        if(radius(b[k]) > radius(b[thickest]))
          thickest = k;
      std::rotate(b.begin(), b.begin() + static_cast<long>(thickest), b.end());
      b.push_back(b.front());
      add_joint(b.front(), Joint_kind::bend);
    }
    std::vector<Vec3> points;
    std::vector<double> radii;
    for(std::size_t v : b)
    {
      points.push_back(position(v));
      radii.push_back(length_unit_of[v]);
    }
    Branch_splitter splitter(points, radii, settings, largest_radius_of_piece[b.front()]);
    std::vector<std::size_t> cuts = splitter.joints();
    const std::vector<double>& arc = splitter.arc_lengths();
    const bool front_is_tip = !branch.closed && boost::degree(b.front(), skeleton) == 1;
    const bool back_is_tip = !branch.closed && boost::degree(b.back(), skeleton) == 1;
    set_back_tip_joints(arc, front_is_tip, back_is_tip, settings.tip_joint_setback, cuts);
    // A tie goes towards the body: the end that is not a tip (mirror-image limbs alike).
    space_joints(arc, settings.joint_spacing, cuts, front_is_tip && !back_is_tip);
    for(std::size_t c = 0; c + 1 < cuts.size(); ++c)
    {
      Control_bone<Point> bone;
      const std::size_t first = add_joint(b[cuts[c]], c == 0 && front_is_tip ? Joint_kind::end : Joint_kind::bend);
      const std::size_t last =
          add_joint(b[cuts[c + 1]], c + 2 == cuts.size() && back_is_tip ? Joint_kind::end : Joint_kind::bend);
      for(std::size_t k = cuts[c]; k <= cuts[c + 1]; ++k)
      {
        bone.points.emplace_back(points[k][0], points[k][1], points[k][2]);
        if(k > cuts[c])
          bone.length += norm3(sub(points[k], points[k - 1]));
      }
      add_bone(first, last, std::move(bone), graph);
    }
  }
  control = root_joint_graph(graph);
}

} // namespace internal

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SPLIT_INTO_BONES_SPLIT_WITH_MAPS_H
