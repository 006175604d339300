// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_REEB_GRAPH_H
#define CGAL_GEODESIC_SKELETON_REEB_GRAPH_H

/// \file reeb_graph.h
/// The discrete Reeb graph of a scalar field on the vertices of a mesh (the skeleton that
/// the paper compares its pruned skeleton with).

#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/indexed_vertices.h>
#include <CGAL/Geodesic_skeleton/internal/reeb_graph/reeb_pieces.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
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
/// The range [min, max] of the field is cut into `number_of_intervals` equal intervals, and
/// the field is taken as linear on each face (interpolated from its vertices). A node
/// stands for one connected component of the part of the surface whose values fall into
/// one interval: the part of a face between two level sets is connected, and two such
/// pieces of one interval join across a shared edge whose values reach into the interval.
/// Two nodes are linked when they touch along a level set (their pieces lie in one face,
/// in consecutive intervals). A node holds the mesh vertices whose values fall in it; its
/// point is their centroid (or the centroid of the faces it crosses, when a band of values
/// is thinner than the faces and holds no vertex). Following the level sets through the
/// faces keeps a thin band in one piece, so the graph has no false loops: a surface of
/// genus g gives at most g independent cycles, and a handle gives one when the intervals
/// are fine enough to separate its two sides. Each connected component of the mesh gives
/// one of the graph; a vertex without faces gets a node of its own.
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
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices of `mesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a bijection from the vertices onto [0, `num_vertices(mesh)`)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or one initialised on the fly}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a bijection from the faces onto [0, `num_faces(mesh)`)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's face descriptor as
///                    key type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or one initialised on the fly}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre the mesh has at least one vertex; every value of `field` is finite.
/// \throws std::invalid_argument on an empty mesh, a non-finite value (a geodesic field
///         with a source in another component gives infinity there: use one source per
///         component, as `geodesic_mapping_function()` does), or `number_of_intervals`
///         out of range.
///
/// \b Complexity: O((F k + E k) alpha + V) time and O(F k + V) memory for F faces, E edges
/// and V vertices, where k is the number of intervals a face spans (1 or 2 in practice).
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
  internal::checked_parameter(parameter_ranges::number_of_reeb_intervals, number_of_intervals, caller,
                              "number_of_intervals");

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

  // Nodes and arcs from the pieces of the faces between level sets.
  auto interval_of_vertex = [&](vertex_descriptor v) { return interval[index(v)]; };
  const auto fim = CGAL::get_initialized_face_index_map(mesh, np);
  const internal::Reeb_pieces pieces = internal::reeb_pieces(mesh, fim, interval_of_vertex);
  reeb.clear();
  const double step = (high - low) / static_cast<double>(number_of_intervals);
  for(std::size_t k = 0; k < pieces.nodes; ++k)
    add_vertex(reeb);
  for(const auto& arc : pieces.arcs)
    add_edge(arc.first, arc.second, reeb);

  // Each vertex goes to the node of its interval's piece in a face around it; a node's
  // point is the centroid of its vertices, or of the faces it crosses when it has none.
  std::vector<std::array<double, 4>> vertex_sum(pieces.nodes, {0, 0, 0, 0}), face_sum(pieces.nodes, {0, 0, 0, 0});
  auto position = [&](vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return std::array<double, 3>{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  for(vertex_descriptor v : vertices(mesh))
  {
    // A face around v (a vertex without faces gets a node of its own).
    auto h = halfedge(v, mesh);
    if(h != boost::graph_traits<FaceGraph>::null_halfedge() && is_border(h, mesh))
      h = opposite(h, mesh);
    std::size_t node;
    if(h == boost::graph_traits<FaceGraph>::null_halfedge() || is_border(h, mesh))
    {
      node = add_vertex(reeb);
      vertex_sum.push_back({0, 0, 0, 0});
      face_sum.push_back({0, 0, 0, 0});
      reeb[node].interval = interval[index(v)];
    }
    else
      node = pieces.node_of_piece[pieces.piece(static_cast<std::size_t>(get(fim, face(h, mesh))), interval[index(v)])];
    reeb[node].vertices.push_back(v);
    const auto p = position(v);
    for(int c = 0; c < 3; ++c)
      vertex_sum[node][c] += p[c];
    vertex_sum[node][3] += 1;
  }
  for(auto fd : faces(mesh))
  {
    const std::size_t f = static_cast<std::size_t>(get(fim, fd));
    std::array<double, 3> centre{0, 0, 0};
    double corners = 0;
    std::size_t top = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(fd, mesh), mesh))
    {
      const auto p = position(v);
      for(int c = 0; c < 3; ++c)
        centre[c] += p[c];
      corners += 1;
      top = (std::max)(top, interval[index(v)]);
    }
    for(std::size_t k = pieces.first_interval[f]; k <= top; ++k)
    {
      const std::size_t node = pieces.node_of_piece[pieces.piece(f, k)];
      for(int c = 0; c < 3; ++c)
        face_sum[node][c] += centre[c] / corners;
      face_sum[node][3] += 1;
      reeb[node].interval = k;
    }
  }
  for(std::size_t node = 0; node < num_vertices(reeb); ++node)
  {
    const auto& sum = vertex_sum[node][3] > 0 ? vertex_sum[node] : face_sum[node];
    reeb[node].point = Point(sum[0] / sum[3], sum[1] / sum[3], sum[2] / sum[3]);
    reeb[node].level_min = low + step * static_cast<double>(reeb[node].interval);
    reeb[node].level_max = reeb[node].interval + 1 == number_of_intervals ? high : reeb[node].level_min + step;
  }
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_REEB_GRAPH_H
