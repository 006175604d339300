// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_GEODESIC_DISTANCES_H
#define CGAL_GEODESIC_SKELETON_GEODESIC_DISTANCES_H

/// \file geodesic_distances.h
/// Geodesic distances on the surface of a mesh, approximated by shortest paths along its
/// edges (Dijkstra), the baseline distance field of the package.

#include <CGAL/Geodesic_skeleton/internal/geodesics/edge_length_map.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/indexed_vertices.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/graph/two_bit_color_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Resolved named parameters of the geodesic functions: index, weight and predecessor maps.
template <typename FaceGraph, typename NamedParameters>
struct Geodesic_parameters
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Vertex_point_map = typename CGAL::GetVertexPointMap<FaceGraph, NamedParameters>::const_type;
  using Geom_traits = typename CGAL::GetGeomTraits<FaceGraph, NamedParameters>::type;
  using Vertex_index_map = typename CGAL::GetInitializedVertexIndexMap<FaceGraph, NamedParameters>::const_type;
  using Default_edge_weight_map = Edge_length_map<FaceGraph, Vertex_point_map, Geom_traits>;
  using Edge_weight_map = typename CGAL::internal_np::Lookup_named_param_def<
      internal_np::edge_weight_map_t, NamedParameters, Default_edge_weight_map>::type;
  using Default_predecessor_map = boost::dummy_property_map;
  using Predecessor_map = typename CGAL::internal_np::Lookup_named_param_def<
      internal_np::vertex_predecessor_map_t, NamedParameters, Default_predecessor_map>::type;

  static Edge_weight_map edge_weights(const FaceGraph& g, const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    Default_edge_weight_map lengths{
        &g,
        choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                         get_const_property_map(CGAL::vertex_point, g)),
        choose_parameter<Geom_traits>(get_parameter(np, CGAL::internal_np::geom_traits))};
    return choose_parameter(get_parameter(np, internal_np::edge_weight_map_tag), lengths);
  }

  static Predecessor_map predecessors(const NamedParameters& np)
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    return choose_parameter(get_parameter(np, internal_np::vertex_predecessor_map_tag),
                            Default_predecessor_map());
  }
};

// Every edge weight must be finite and non-negative for Dijkstra to be exact; a NaN or an
// infinite coordinate shows up here as a non-finite length.
template <typename FaceGraph, typename EdgeWeightMap>
void require_valid_edge_weights(const FaceGraph& g, EdgeWeightMap weights, const char* caller)
{
  for(auto e : edges(g))
  {
    const double w = static_cast<double>(get(weights, e));
    if(std::isnan(w) || std::isinf(w))
      throw std::invalid_argument(std::string(caller) +
                                  ": an edge has a non-finite weight (NaN or infinite "
                                  "vertex coordinates?)");
    if(w < 0)
      throw std::invalid_argument(std::string(caller) +
                                  ": an edge has a negative weight; Dijkstra needs "
                                  "non-negative edge weights");
  }
}

// A single vertex descriptor or a range of them, as a vector.
template <typename FaceGraph, typename Sources>
std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>
source_vector(const Sources& sources)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  std::vector<vertex_descriptor> out;
  if constexpr(std::is_convertible<Sources, vertex_descriptor>::value)
    out.push_back(sources);
  else
    out.assign(std::begin(sources), std::end(sources));
  return out;
}

// Thrown by a visitor to stop Dijkstra once a target is settled.
struct Target_reached {};

template <typename Vertex>
struct Stop_at_target : boost::default_dijkstra_visitor
{
  Vertex target;
  template <typename Graph>
  void finish_vertex(Vertex v, const Graph&) const
  {
    if(v == target)
      throw Target_reached();
  }
};

// The common core: checks the input, then runs Boost.Graph's multi-source Dijkstra.
// `target`, unless it is the null vertex, is checked to be a vertex of `g` too.
template <typename FaceGraph, typename VertexDistanceMap, typename PredecessorMap,
          typename NamedParameters, typename Visitor>
void run_dijkstra(const FaceGraph& g,
                  const std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>& sources,
                  typename boost::graph_traits<FaceGraph>::vertex_descriptor target,
                  VertexDistanceMap distances, PredecessorMap predecessors,
                  const NamedParameters& np, Visitor visitor, const char* caller)
{
  using Params = Geodesic_parameters<FaceGraph, NamedParameters>;
  using Distance = typename boost::property_traits<VertexDistanceMap>::value_type;
  static_assert(std::numeric_limits<Distance>::has_infinity,
                "the distance map's value type must have an infinity (float, double, ...)");

  if(num_vertices(g) == 0)
    throw std::invalid_argument(std::string(caller) + ": the mesh has no vertices");
  if(sources.empty())
    throw std::invalid_argument(std::string(caller) + ": no source vertex was given");

  const auto vim = CGAL::get_initialized_vertex_index_map(g, np);
  const Indexed_vertices<FaceGraph, decltype(vim)> indexed(g, vim, caller);
  for(auto s : sources)
    indexed.require(s, "source vertex");
  if(target != boost::graph_traits<FaceGraph>::null_vertex())
    indexed.require(target, "target vertex");

  const auto weights = Params::edge_weights(g, np);
  require_valid_edge_weights(g, weights, caller);

  boost::two_bit_color_map<decltype(vim)> colors(indexed.size(), vim);
  boost::dijkstra_shortest_paths(g, sources.begin(), sources.end(), predecessors, distances,
                                 weights, vim, std::less<Distance>(),
                                 boost::closed_plus<Distance>(),
                                 std::numeric_limits<Distance>::infinity(), Distance(0),
                                 visitor, colors);
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Computes, for every vertex of `g`, the length of the shortest path along the edges of
/// `g` to the nearest source vertex (the Dijkstra approximation of the geodesic distance).
///
/// \tparam FaceGraph a model of `FaceListGraph` (any CGAL mesh: `Surface_mesh`,
///         `Polyhedron_3`, ...); only its vertices and edges are used.
/// \tparam SourceVertices either one `boost::graph_traits<FaceGraph>::vertex_descriptor`
///         or a range of them.
/// \tparam VertexDistanceMap a model of `ReadWritePropertyMap` with the vertex descriptor
///         as key and a floating-point value type (`double`, `float`).
/// \tparam NamedParameters a sequence of named parameters.
///
/// \param g the mesh.
/// \param sources the source vertex, or the source vertices (a multi-source field: each
///        vertex gets the distance to its nearest source).
/// \param distances receives the distance of every vertex. A vertex that no path reaches
///        (another connected component) gets `std::numeric_limits<value_type>::infinity()`.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices, used for the default edge
///                           weights}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key
///                    type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, g)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a bijection from the vertices onto `[0, num_vertices(g))`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key
///                    type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or one initialised on the fly}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_weight_map}
///     \cgalParamDescription{the length of every edge, finite and non-negative (package
///                           parameter)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the edge descriptor as key type
///                    and a number type as value type}
///     \cgalParamDefault{the Euclidean length of the edge, from the point map}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_predecessor_map}
///     \cgalParamDescription{receives, for each reached vertex, its predecessor on a
///                           shortest path; a source and an unreached vertex get
///                           themselves (package parameter)}
///     \cgalParamType{a model of `WritablePropertyMap` with the vertex descriptor as key
///                    and value type}
///     \cgalParamDefault{not recorded}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `g` has at least one vertex; every source is a vertex of `g`; every edge weight is
///      finite and non-negative; the vertex index map is a bijection onto
///      `[0, num_vertices(g))` (for a `Surface_mesh` with removed elements, call
///      `collect_garbage()` first).
/// \throws std::invalid_argument when a precondition does not hold (checked, with a
///      message naming it), e.g. an empty mesh, a source vertex not in the mesh, a negative
///      weight, or NaN / infinite coordinates.
///
/// \b Complexity: O((V + E) log V) time and O(V) extra memory, for V vertices and E edges.
template <typename FaceGraph, typename SourceVertices, typename VertexDistanceMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void geodesic_distances(const FaceGraph& g, const SourceVertices& sources,
                        VertexDistanceMap distances,
                        const NamedParameters& np = CGAL::parameters::default_values())
{
  using Params = internal::Geodesic_parameters<FaceGraph, NamedParameters>;
  internal::run_dijkstra(g, internal::source_vector<FaceGraph>(sources),
                         boost::graph_traits<FaceGraph>::null_vertex(), distances,
                         Params::predecessors(np), np, boost::default_dijkstra_visitor(),
                         "geodesic_distances");
}

/// \ingroup PkgGeodesicSkeletonRef
/// Writes the vertices of a shortest edge path of `g` from `source` to `target` (both
/// included, in that order) to `out`, and returns its length. The search stops as soon as
/// `target` is settled, so a near target is found fast.
///
/// \tparam FaceGraph a model of `FaceListGraph`, as for `geodesic_distances()`.
/// \tparam OutputIterator an output iterator accepting vertex descriptors.
/// \tparam NamedParameters a sequence of named parameters.
/// \param g the mesh.
/// \param source the first vertex of the path.
/// \param target the last vertex of the path.
/// \param out receives the vertices of the path, from `source` to `target`.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices, used for the default edge
///                           weights}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key
///                    type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, g)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a bijection from the vertices onto `[0, num_vertices(g))`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key
///                    type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or one initialised on the fly}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_weight_map}
///     \cgalParamDescription{the length of every edge, finite and non-negative (package
///                           parameter)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the edge descriptor as key type
///                    and a number type as value type}
///     \cgalParamDefault{the Euclidean length of the edge, from the point map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the length of the path, or `std::numeric_limits<double>::infinity()` when
///        `target` is not reachable from `source` (nothing is written then).
/// \pre and \throws as `geodesic_distances()`; `target` must be a vertex of `g` too.
///
/// \b Complexity: O((V + E) log V) time in the worst case, O(V) extra memory.
template <typename FaceGraph, typename OutputIterator,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
double shortest_path(const FaceGraph& g,
                     typename boost::graph_traits<FaceGraph>::vertex_descriptor source,
                     typename boost::graph_traits<FaceGraph>::vertex_descriptor target,
                     OutputIterator out,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  if(target == boost::graph_traits<FaceGraph>::null_vertex())
    throw std::invalid_argument("shortest_path: the target vertex is not a vertex of the mesh");
  const auto vim = CGAL::get_initialized_vertex_index_map(g, np);
  const std::size_t n = static_cast<std::size_t>(num_vertices(g));
  std::vector<double> distance_storage(n);
  std::vector<vertex_descriptor> predecessor_storage(n);
  auto distances = boost::make_iterator_property_map(distance_storage.begin(), vim);
  auto predecessors = boost::make_iterator_property_map(predecessor_storage.begin(), vim);

  internal::Stop_at_target<vertex_descriptor> stop{{}, target};
  try
  {
    internal::run_dijkstra(g, std::vector<vertex_descriptor>(1, source), target, distances,
                           predecessors, np, stop, "shortest_path");
  }
  catch(const internal::Target_reached&)
  {
  }

  const double length = get(distances, target);
  if(std::isinf(length))
    return length;
  std::vector<vertex_descriptor> path(1, target);
  while(path.back() != source)
    path.push_back(get(predecessors, path.back()));
  std::copy(path.rbegin(), path.rend(), out);
  return length;
}

/// \ingroup PkgGeodesicSkeletonRef
/// Finds the vertex of `g` whose geodesic distance (as computed by `geodesic_distances()`)
/// to the nearest of `sources` is largest, among the vertices that a path reaches.
///
/// \tparam FaceGraph a model of `FaceListGraph`, as for `geodesic_distances()`.
/// \tparam SourceVertices either one `boost::graph_traits<FaceGraph>::vertex_descriptor`
///         or a range of them.
/// \tparam NamedParameters a sequence of named parameters.
/// \param g the mesh.
/// \param sources the source vertex, or the source vertices.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices, used for the default edge
///                           weights}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key
///                    type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, g)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a bijection from the vertices onto `[0, num_vertices(g))`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key
///                    type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or one initialised on the fly}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_weight_map}
///     \cgalParamDescription{the length of every edge, finite and non-negative (package
///                           parameter)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the edge descriptor as key type
///                    and a number type as value type}
///     \cgalParamDefault{the Euclidean length of the edge, from the point map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns the vertex and its distance. Ties are broken by the smallest vertex index, so
///          the answer is deterministic. When only the sources are reachable, a source is
///          returned with distance 0.
/// \pre and \throws as `geodesic_distances()`.
///
/// \b Complexity: O((V + E) log V) time and O(V) extra memory.
template <typename FaceGraph, typename SourceVertices,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::pair<typename boost::graph_traits<FaceGraph>::vertex_descriptor, double>
farthest_vertex(const FaceGraph& g, const SourceVertices& sources,
                const NamedParameters& np = CGAL::parameters::default_values())
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  const auto vim = CGAL::get_initialized_vertex_index_map(g, np);
  std::vector<double> distance_storage(static_cast<std::size_t>(num_vertices(g)));
  auto distances = boost::make_iterator_property_map(distance_storage.begin(), vim);
  internal::run_dijkstra(g, internal::source_vector<FaceGraph>(sources),
                         boost::graph_traits<FaceGraph>::null_vertex(), distances,
                         boost::dummy_property_map(), np, boost::default_dijkstra_visitor(),
                         "farthest_vertex");

  std::pair<vertex_descriptor, double> farthest(boost::graph_traits<FaceGraph>::null_vertex(), -1.);
  std::size_t farthest_index = 0;
  for(vertex_descriptor v : vertices(g))
  {
    const double d = get(distances, v);
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    if(std::isinf(d))
      continue;
    if(d > farthest.second || (d == farthest.second && i < farthest_index))
    {
      farthest = {v, d};
      farthest_index = i;
    }
  }
  return farthest;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_GEODESIC_DISTANCES_H
