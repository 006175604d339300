// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_REEB_GRAPH_H
#define CGAL_GEODESIC_SKELETON_REEB_GRAPH_H

/// \file reeb_graph.h
/// The discrete Reeb graph of a scalar field on the vertices of a mesh (the skeleton that
/// the paper compares its pruned skeleton with).

#include <CGAL/Geodesic_skeleton/internal/indexed_vertices.h>
#include <CGAL/Geodesic_skeleton/internal/vertex_components.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// A node of a Reeb graph: one connected part of the mesh inside one interval of the field.
/// \tparam Point the mesh's point type.
/// \tparam VertexDescriptor the mesh's vertex descriptor.
template <typename Point, typename VertexDescriptor>
struct Reeb_graph_node
{
  /// Index of the interval of the field, from 0 (lowest values) to `number_of_intervals - 1`.
  std::size_t interval = 0;
  /// The interval of the field that the node covers: [`level_min`, `level_max`].
  double level_min = 0, level_max = 0; ///< The upper end of the node's interval of the field.
  /// The centroid of the node's mesh vertices.
  Point point;
  /// The mesh vertices of the node.
  std::vector<VertexDescriptor> vertices;
};

/// \ingroup PkgGeodesicSkeletonRef
/// The Reeb graph type for a mesh type: an undirected `boost::adjacency_list` whose vertex
/// property is a `Reeb_graph_node`.
template <typename FaceGraph,
          typename Point = typename boost::property_traits<
              typename boost::property_map<FaceGraph, CGAL::vertex_point_t>::const_type>::value_type>
using Reeb_graph = boost::adjacency_list<
    boost::vecS, boost::vecS, boost::undirectedS,
    Reeb_graph_node<Point, typename boost::graph_traits<FaceGraph>::vertex_descriptor>>;

namespace internal {

// The interval of `value` among `count` equal intervals of [low, high].
inline std::size_t interval_of(double value, double low, double high, std::size_t count)
{
  if(high <= low)
    return 0;
  const double t = (value - low) / (high - low) * static_cast<double>(count);
  return std::min(static_cast<std::size_t>(std::max(t, 0.0)), count - 1);
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Builds the discrete Reeb graph of the scalar field `field` on the vertices of `mesh`.
///
/// The range [min, max] of the field is cut into `number_of_intervals` equal intervals. A
/// node stands for one connected component of the vertices whose value falls into one
/// interval (connected through mesh edges whose two ends are in that interval); its point
/// is the centroid of those vertices. Two nodes are linked when a mesh edge joins their
/// vertices (nodes of adjacent intervals; when an edge spans more than one interval, as on
/// a coarse mesh with many intervals, its two nodes are linked directly so that the graph
/// keeps the mesh's connectivity). Each mesh connected component gives one connected
/// component of the graph, and a handle of the mesh gives a cycle when the intervals are
/// fine enough to separate its two sides.
///
/// \tparam FaceGraph a model of `FaceListGraph`.
/// \tparam VertexScalarMap a readable vertex property map with a value convertible to `double`.
/// \tparam ReebGraph a `boost::adjacency_list` with `vecS` vertex storage whose vertex
///         property is `Reeb_graph_node<Point, vertex_descriptor>`, e.g. `Reeb_graph<FaceGraph>`.
///
/// \param mesh the mesh.
/// \param field the mapping function, e.g. from `geodesic_mapping_function()` or
///        `integral_geodesic_mapping_function()`, or any other (height, harmonic, ...).
/// \param number_of_intervals how many intervals the range of the field is cut into; in
///        [1, 1e6].
/// \param reeb receives the graph (cleared first).
/// \param np optional named parameters among `vertex_point_map` (default:
///        `get(CGAL::vertex_point, mesh)`) and `vertex_index_map`.
///
/// \pre the mesh has at least one vertex; every value of `field` is finite.
/// \throws std::invalid_argument on an empty mesh, a non-finite value (a geodesic field
///         with a source in another component gives infinity there: use one source per
///         component, as `geodesic_mapping_function()` does), or `number_of_intervals`
///         out of range.
///
/// \b Complexity: O((V + E) alpha(V) + E log E) time, O(V + E) memory.
template <typename FaceGraph, typename VertexScalarMap, typename ReebGraph,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void reeb_graph(const FaceGraph& mesh, VertexScalarMap field, std::size_t number_of_intervals,
                ReebGraph& reeb, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  using Node = typename boost::vertex_bundle_type<ReebGraph>::type;
  using Point = decltype(Node().point);

  const char* caller = "reeb_graph";
  if(num_vertices(mesh) == 0)
    throw std::invalid_argument("reeb_graph: the mesh has no vertices");
  if(number_of_intervals < 1 || number_of_intervals > 1000000)
    throw std::invalid_argument("reeb_graph: number_of_intervals must be in [1, 1000000], got " +
                                std::to_string(number_of_intervals));

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  const internal::Indexed_vertices<FaceGraph, decltype(vim)> indexed(mesh, vim, caller);

  // Intervals of the field.
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for(vertex_descriptor v : vertices(mesh))
  {
    const double value = static_cast<double>(get(field, v));
    if(!std::isfinite(value))
      throw std::invalid_argument("reeb_graph: the field has a non-finite value (a vertex in "
                                  "a component without a source?)");
    low = std::min(low, value);
    high = std::max(high, value);
  }
  std::vector<std::size_t> interval(indexed.size(), 0);
  for(vertex_descriptor v : vertices(mesh))
    interval[get(vim, v)] = internal::interval_of(static_cast<double>(get(field, v)), low, high,
                                                  number_of_intervals);
  auto index = [&](vertex_descriptor v) { return static_cast<std::size_t>(get(vim, v)); };

  // Nodes: components of the vertices of each interval.
  const internal::Vertex_components parts = internal::vertex_components(mesh, vim, [&](auto e) {
    return interval[index(source(e, mesh))] == interval[index(target(e, mesh))];
  });
  reeb.clear();
  const double step = (high - low) / static_cast<double>(number_of_intervals);
  std::vector<std::array<double, 3>> centroid_sum(parts.count, {0, 0, 0});
  for(std::size_t k = 0; k < parts.count; ++k)
    add_vertex(reeb);
  for(vertex_descriptor v : vertices(mesh))
  {
    const std::size_t node = parts.component_of[index(v)];
    Node& n = reeb[node];
    n.interval = interval[index(v)];
    n.level_min = low + step * static_cast<double>(n.interval);
    n.level_max = n.interval + 1 == number_of_intervals ? high : n.level_min + step;
    n.vertices.push_back(v);
    const auto& p = get(vpm, v);
    centroid_sum[node][0] += CGAL::to_double(p.x());
    centroid_sum[node][1] += CGAL::to_double(p.y());
    centroid_sum[node][2] += CGAL::to_double(p.z());
  }
  for(std::size_t node = 0; node < parts.count; ++node)
  {
    const double count = static_cast<double>(reeb[node].vertices.size());
    reeb[node].point = Point(centroid_sum[node][0] / count, centroid_sum[node][1] / count,
                             centroid_sum[node][2] / count);
  }

  // Arcs: mesh edges between different nodes, each pair once.
  std::set<std::pair<std::size_t, std::size_t>> arcs;
  for(auto e : edges(mesh))
  {
    const std::size_t a = parts.component_of[index(source(e, mesh))];
    const std::size_t b = parts.component_of[index(target(e, mesh))];
    if(a != b)
      arcs.insert(std::minmax(a, b));
  }
  for(const auto& arc : arcs)
    add_edge(arc.first, arc.second, reeb);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_REEB_GRAPH_H
