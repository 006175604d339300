// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_VERTEX_MAPS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_VERTEX_MAPS_H

// The point and MAT-radius maps of a curve skeleton's vertices (smooth_skeleton(),
// split_into_bones()): the `vertex_point_map` and `mat_radius_map` named parameters when
// given, else the vertex bundle's `point` and `radius` members. The bundle of
// Curve_skeleton has both; the bundle of CGAL::Mean_curvature_flow_skeletonization's
// Skeleton has a `point` and no `radius`.

#include <CGAL/Geodesic_skeleton/parameters.h>

#include <boost/graph/properties.hpp>

#include <type_traits>
#include <utility>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Whether a vertex bundle has a data member `point`.
template <typename Bundle, typename = void>
struct has_point_member : std::false_type
{};
template <typename Bundle>
struct has_point_member<Bundle, std::void_t<decltype(std::declval<Bundle&>().point)>> : std::true_type
{};

// Whether a vertex bundle has a data member `radius`.
template <typename Bundle, typename = void>
struct has_radius_member : std::false_type
{};
template <typename Bundle>
struct has_radius_member<Bundle, std::void_t<decltype(std::declval<Bundle&>().radius)>> : std::true_type
{};

// The vertex bundle of a graph (const or not).
template <typename Graph>
using vertex_bundle_t = typename boost::vertex_bundle_type<std::remove_const_t<Graph>>::type;

// Whether the skeleton has a radius to read: a `mat_radius_map` in `np`, or a `radius`
// member in the bundle.
template <typename Graph, typename NamedParameters>
constexpr bool has_radius_map()
{
  return !CGAL::parameters::is_default_parameter<NamedParameters, internal_np::mat_radius_map_t>::value ||
         has_radius_member<vertex_bundle_t<Graph>>::value;
}

// The `vertex_point_map` of `np`, else get(&Bundle::point, skeleton); a writable map when
// `skeleton` is not const and the bundle's member is used.
template <typename Graph, typename NamedParameters>
auto skeleton_point_map(Graph& skeleton, const NamedParameters& np)
{
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::vertex_point_t>::value)
    return CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point);
  else
  {
    using Bundle = vertex_bundle_t<Graph>;
    static_assert(has_point_member<Bundle>::value,
                  "the skeleton's vertex bundle has no `point` member: give a vertex_point_map");
    return get(&Bundle::point, skeleton);
  }
}

// What skeleton_radius_map() gives for a skeleton without radius: nothing to read.
struct No_radius_map
{};

// The `mat_radius_map` of `np`, else get(&Bundle::radius, skeleton), else No_radius_map
// (exactly when has_radius_map<Graph, NamedParameters>() is false).
template <typename Graph, typename NamedParameters>
auto skeleton_radius_map(Graph& skeleton, const NamedParameters& np)
{
  using Bundle = vertex_bundle_t<Graph>;
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::mat_radius_map_t>::value)
    return CGAL::parameters::get_parameter(np, internal_np::mat_radius_map_tag);
  else if constexpr(has_radius_member<Bundle>::value)
    return get(&Bundle::radius, skeleton);
  else
    return No_radius_map{};
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_VERTEX_MAPS_H
