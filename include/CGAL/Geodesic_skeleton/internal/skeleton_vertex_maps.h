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
#include <boost/property_map/property_map.hpp>

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

// Whether a vertex bundle has a data member `vertices` (the mesh vertices mapped to it).
template <typename Bundle, typename = void>
struct has_vertices_member : std::false_type
{};
template <typename Bundle>
struct has_vertices_member<Bundle, std::void_t<decltype(std::declval<Bundle&>().vertices)>> : std::true_type
{};

// Whether a vertex bundle has a data member `voxel`.
template <typename Bundle, typename = void>
struct has_voxel_member : std::false_type
{};
template <typename Bundle>
struct has_voxel_member<Bundle, std::void_t<decltype(std::declval<Bundle&>().voxel)>> : std::true_type
{};

// Whether a vertex bundle has the data members `sheet_half_width` and `piece_radius`.
template <typename Bundle, typename = void>
struct has_sheet_members : std::false_type
{};
template <typename Bundle>
struct has_sheet_members<Bundle, std::void_t<decltype(std::declval<Bundle&>().sheet_half_width),
                                             decltype(std::declval<Bundle&>().piece_radius)>> : std::true_type
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

// What skeleton_radius_map() gives for a skeleton without radius: nothing to read (and
// what the output_*_map() functions give for a map to leave unwritten).
struct No_map
{};

// The `mat_radius_map` of `np`, else get(&Bundle::radius, skeleton), else No_map
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
    return No_map{};
}

// The maps that to_graph() writes: the vertex bundle's `point` (required), `vertices` and
// `voxel` members, and its `radius` member or the `mat_radius_map` named parameter (CGAL's
// MCF skeleton has `point` and `vertices` members, no `radius`: its radius goes to a map
// that smooth_skeleton() and split_into_bones() read as well). A quantity with no member
// and no map is No_map (nothing written).
template <typename Graph>
auto output_point_map(Graph& skeleton)
{
  using Bundle = vertex_bundle_t<Graph>;
  static_assert(has_point_member<Bundle>::value, "to_graph(): the graph's vertex bundle has no `point` member");
  return get(&Bundle::point, skeleton);
}

template <typename Graph>
auto output_mesh_vertices_map(Graph& skeleton)
{
  using Bundle = vertex_bundle_t<Graph>;
  if constexpr(has_vertices_member<Bundle>::value)
    return get(&Bundle::vertices, skeleton);
  else
    return No_map{};
}

template <typename Graph>
auto output_voxel_map(Graph& skeleton)
{
  using Bundle = vertex_bundle_t<Graph>;
  if constexpr(has_voxel_member<Bundle>::value)
    return get(&Bundle::voxel, skeleton);
  else
    return No_map{};
}

// The four maps to_graph() writes a curve skeleton's vertices through.
template <typename PointMap, typename RadiusMap, typename MeshVerticesMap, typename VoxelMap>
struct Curve_skeleton_output_maps
{
  using Point_map = PointMap;
  using Mesh_vertices_map = MeshVerticesMap;
  PointMap points;
  RadiusMap radii;
  MeshVerticesMap mesh_vertices;
  VoxelMap voxels;
};

template <typename Graph, typename NamedParameters>
auto curve_skeleton_output_maps(Graph& skeleton, const NamedParameters& np)
{
  auto points = output_point_map(skeleton);
  auto radii = skeleton_radius_map(skeleton, np);
  auto mesh_vertices = output_mesh_vertices_map(skeleton);
  auto voxels = output_voxel_map(skeleton);
  return Curve_skeleton_output_maps<decltype(points), decltype(radii), decltype(mesh_vertices), decltype(voxels)>{
      points, radii, mesh_vertices, voxels};
}

// put(map, key, value), or nothing for a map that is not there.
template <typename Map, typename Key, typename Value>
void put_if_mapped(const Map& map, const Key& key, Value&& value)
{
  if constexpr(!std::is_same_v<Map, No_map>)
    put(map, key, std::forward<Value>(value));
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_VERTEX_MAPS_H
