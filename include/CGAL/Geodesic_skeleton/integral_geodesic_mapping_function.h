// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTEGRAL_GEODESIC_MAPPING_FUNCTION_H
#define CGAL_GEODESIC_SKELETON_INTEGRAL_GEODESIC_MAPPING_FUNCTION_H

/// \file integral_geodesic_mapping_function.h
/// The mapping function of the Multiresolution Reeb Graph (Hilaga et al. 2001): the
/// integral of the geodesic distance over the surface, normalised to [0, 1].

#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/distance_fields.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/vertex_components.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A third of the area of the faces around each vertex, by index: the area of a triangle by
// PMP::face_area(), that of another polygon as the sum of the triangles of a fan from its
// first corner.
template <typename FaceGraph, typename VertexPointMap, typename GeomTraits, typename VertexIndexMap>
std::vector<double> vertex_areas(const FaceGraph& g, VertexPointMap vpm, const GeomTraits& traits,
                                 VertexIndexMap vim)
{
  std::vector<double> area(static_cast<std::size_t>(num_vertices(g)), 0.0);
  const auto squared_area = traits.compute_squared_area_3_object();
  std::vector<std::size_t> ids;
  for(auto f : faces(g))
  {
    double face_area = 0;
    if(CGAL::is_triangle(halfedge(f, g), g))
      face_area = CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(
          f, g, CGAL::parameters::vertex_point_map(vpm).geom_traits(traits)));
    else
    {
      const auto h = halfedge(f, g);
      const auto& corner = get(vpm, target(h, g));
      for(auto k = next(h, g); target(next(k, g), g) != target(h, g); k = next(k, g))
        face_area += CGAL::to_double(CGAL::approximate_sqrt(
            squared_area(corner, get(vpm, target(k, g)), get(vpm, target(next(k, g), g)))));
    }
    ids.clear();
    for(auto v : CGAL::vertices_around_face(halfedge(f, g), g))
      ids.push_back(static_cast<std::size_t>(get(vim, v)));
    for(std::size_t i : ids)
      area[i] += face_area / static_cast<double>(ids.size());
  }
  return area;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Writes to `field` the normalised integral of the geodesic distance of Hilaga et al.
/// ("Topology matching for fully automatic similarity estimation of 3D shapes", 2001):
/// mu(v) = sum over base vertices b of area(b) * g(v, b), then
/// (mu - min mu) / (max mu - min mu) within each connected component. It is smallest at
/// the middle of the shape and largest at the tips of its limbs, does not depend on a
/// chosen source, and does not change when the mesh is rotated or moved.
///
/// The base vertices are picked by farthest-point sampling over the geodesic distance
/// (the first one per component by a farthest-point search); area(b) is the surface area
/// of b's geodesic Voronoi cell (the vertices nearer to b than to any other base vertex,
/// each weighing a third of its faces' area).
///
/// \tparam FaceGraph a model of `FaceListGraph`.
/// \tparam VertexScalarMap a writable vertex property map with a floating-point value.
/// \param mesh the mesh.
/// \param field receives the value of the mapping function at every vertex.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_base_vertices}
///     \cgalParamDescription{k, the number of base vertices, in [1, 100000]; raised to the
///                           number of connected components if lower and capped at the
///                           number of vertices (package parameter)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{50}
///     \cgalParamExtra{More is smoother and costs more.}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, geom_traits, vertex_index_map, edge_weight_map}
///     \cgalParamDescription{the named parameters of `geodesic_distances()`}
///     \cgalParamType{as for `geodesic_distances()`}
///     \cgalParamDefault{as for `geodesic_distances()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre as `geodesic_distances()`.
/// \throws std::invalid_argument as `geodesic_distances()`, or when k is out of range.
///
/// \b Complexity: O(k (V + E) log V) time (k + 1 Dijkstra runs) and O(k V) memory.
template <typename FaceGraph, typename VertexScalarMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void integral_geodesic_mapping_function(const FaceGraph& mesh, VertexScalarMap field,
                                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  const std::size_t requested = internal::checked_parameter(
      parameter_ranges::number_of_base_vertices,
      choose_parameter(get_parameter(np, internal_np::number_of_base_vertices_tag),
                       static_cast<std::size_t>(parameter_ranges::number_of_base_vertices.default_value)),
      "integral_geodesic_mapping_function");
  if(num_vertices(mesh) == 0)
    throw std::invalid_argument("integral_geodesic_mapping_function: the mesh has no vertices");

  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  auto index = [&](vertex_descriptor v) { return static_cast<std::size_t>(get(vim, v)); };
  const internal::Vertex_components components = internal::vertex_components(mesh, vim);
  const std::size_t n = static_cast<std::size_t>(num_vertices(mesh));

  // Farthest-point sampling: each new base vertex is the vertex farthest from all others.
  std::vector<std::vector<double>> base_fields;
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> nearest_base(n, 0);
  auto add_base = [&](vertex_descriptor b) {
    base_fields.push_back(internal::distance_field(mesh, vim, b, np));
    const std::vector<double>& d = base_fields.back();
    for(vertex_descriptor v : vertices(mesh))
      if(d[index(v)] < nearest[index(v)])
      {
        nearest[index(v)] = d[index(v)];
        nearest_base[index(v)] = base_fields.size() - 1;
      }
  };
  for(vertex_descriptor b : internal::diameter_end_per_component(mesh, vim, components, np))
    add_base(b);
  const std::size_t k = std::min(std::max(requested, components.count), n);
  while(base_fields.size() < k)
  {
    vertex_descriptor next = *vertices(mesh).begin();
    double farthest = -1;
    for(vertex_descriptor v : vertices(mesh))
      if(nearest[index(v)] > farthest)
      {
        farthest = nearest[index(v)];
        next = v;
      }
    if(farthest <= 0) // every vertex is a base vertex already
      break;
    add_base(next);
  }

  // Voronoi areas of the base vertices, then the integral.
  const std::vector<double> area = internal::vertex_areas(
      mesh, vpm, choose_parameter<typename GetGeomTraits<FaceGraph, NamedParameters>::type>(
                     get_parameter(np, CGAL::internal_np::geom_traits)),
      vim);
  std::vector<double> cell_area(base_fields.size(), 0.0);
  for(vertex_descriptor v : vertices(mesh))
    cell_area[nearest_base[index(v)]] += area[index(v)];
  std::vector<double> mu(n, 0.0);
  for(std::size_t b = 0; b < base_fields.size(); ++b)
    for(vertex_descriptor v : vertices(mesh))
      if(std::isfinite(base_fields[b][index(v)]))
        mu[index(v)] += cell_area[b] * base_fields[b][index(v)];

  // Normalised per component.
  std::vector<double> low(components.count, std::numeric_limits<double>::infinity());
  std::vector<double> high(components.count, -std::numeric_limits<double>::infinity());
  for(vertex_descriptor v : vertices(mesh))
  {
    const std::size_t c = components.component_of[index(v)];
    low[c] = std::min(low[c], mu[index(v)]);
    high[c] = std::max(high[c], mu[index(v)]);
  }
  for(vertex_descriptor v : vertices(mesh))
  {
    const std::size_t c = components.component_of[index(v)];
    put(field, v, high[c] > low[c] ? (mu[index(v)] - low[c]) / (high[c] - low[c]) : 0.0);
  }
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTEGRAL_GEODESIC_MAPPING_FUNCTION_H
