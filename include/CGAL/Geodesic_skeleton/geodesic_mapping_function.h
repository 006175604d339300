// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_GEODESIC_MAPPING_FUNCTION_H
#define CGAL_GEODESIC_SKELETON_GEODESIC_MAPPING_FUNCTION_H

/// \file geodesic_mapping_function.h
/// A mapping function for the Reeb graph: the geodesic distance from one source per
/// connected component, which does not change when the mesh is rotated or moved.

#include <CGAL/Geodesic_skeleton/internal/geodesics/distance_fields.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/vertex_components.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Writes to `field` the geodesic distance (`geodesic_distances()`) of every vertex from
/// the source of its connected component, a rotation- and translation-invariant mapping
/// function for `reeb_graph()`.
///
/// By default each component's source is found by a farthest-point search: the vertex
/// farthest from the component's first vertex, which lies at an extremity of the shape
/// (the tip of a limb), so that the levels of the field run along the shape.
///
/// \tparam FaceGraph a model of `FaceListGraph`.
/// \tparam VertexScalarMap a writable vertex property map with a floating-point value.
/// \param mesh the mesh.
/// \param field receives the value of the mapping function at every vertex.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{source_vertices}
///     \cgalParamDescription{the sources; every component must hold one (package
///                           parameter)}
///     \cgalParamType{a range of vertex descriptors}
///     \cgalParamDefault{one per component, found as said above}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, geom_traits, vertex_index_map, edge_weight_map}
///     \cgalParamDescription{the named parameters of `geodesic_distances()`}
///     \cgalParamType{as for `geodesic_distances()`}
///     \cgalParamDefault{as for `geodesic_distances()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre as `geodesic_distances()`.
/// \throws std::invalid_argument as `geodesic_distances()`, and when given sources leave a
///         component without a source.
///
/// \b Complexity: O((V + E) log V) time (two Dijkstra runs by default, one with given
/// sources), O(V) extra memory.
template <typename FaceGraph, typename VertexScalarMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void geodesic_mapping_function(const FaceGraph& mesh, VertexScalarMap field,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;

  if(num_vertices(mesh) == 0)
    throw std::invalid_argument("geodesic_mapping_function: the mesh has no vertices");
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  std::vector<vertex_descriptor> sources;
  if constexpr(is_default_parameter<NamedParameters, internal_np::source_vertices_t>::value)
  {
    const internal::Vertex_components components = internal::vertex_components(mesh, vim);
    sources = internal::diameter_end_per_component(mesh, vim, components, np);
  }
  else
  {
    const auto& given = get_parameter(np, internal_np::source_vertices_tag);
    sources.assign(std::begin(given), std::end(given));
  }

  const std::vector<double> d = internal::distance_field(mesh, vim, sources, np);
  for(vertex_descriptor v : vertices(mesh))
  {
    const double value = d[static_cast<std::size_t>(get(vim, v))];
    if(std::isinf(value))
      throw std::invalid_argument("geodesic_mapping_function: a connected component of the "
                                  "mesh holds none of the given source vertices");
    put(field, v, value);
  }
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_GEODESIC_MAPPING_FUNCTION_H
