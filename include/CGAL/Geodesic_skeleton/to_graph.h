// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_TO_GRAPH_H
#define CGAL_GEODESIC_SKELETON_TO_GRAPH_H

/// \file to_graph.h
/// A one-voxel-thick voxel skeleton as a curve-skeleton graph, with the mesh vertices
/// mapped to its vertices.

#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// For every voxel of the solid of `distances` (and the skeleton's own voxels): the skeleton
// node whose 26-connected breadth-first wave through the solid reaches it first, the
// nearest skeleton voxel along paths inside the shape.
class Nearest_node_inside
{
public:
  Nearest_node_inside(const Voxel_distance_field& distances, const std::vector<Voxel_key>& nodes)
    : m_layout(distances.box().grown(1))
  {
    // Over the field's box grown by one voxel, so that the wave needs no bounds check:
    // BLOCKED outside the solid (and on the added layer), UNREACHED in it.
    m_label.assign(m_layout.volume(), BLOCKED);
    const Grid_layout field(distances.box());
    const auto& values = distances.values();
    std::size_t solid = 0;
    for(std::size_t z = 0; z < field.nz; ++z)
      for(std::size_t y = 0; y < field.ny; ++y)
      {
        const std::uint32_t* from = values.data() + z * std::size_t(field.stride_z) + y * field.nx;
        std::int32_t* to = m_label.data() + m_layout.index(Voxel_key{field.box.min.x, field.box.min.y + int(y),
                                                                     field.box.min.z + int(z)});
        for(std::size_t x = 0; x < field.nx; ++x)
        {
          to[x] = from[x] != 0 ? UNREACHED : BLOCKED;
          solid += from[x] != 0;
        }
      }
    std::vector<std::uint32_t> queue; // each voxel enters once: the solid and the nodes
    queue.reserve(solid + nodes.size());
    for(std::size_t v = 0; v < nodes.size(); ++v)
      if(distances.box().contains(nodes[v]))
      {
        const std::size_t i = m_layout.index(nodes[v]);
        if(m_label[i] < 0)
        {
          m_label[i] = std::int32_t(v);
          queue.push_back(std::uint32_t(i));
        }
      }
    const auto offsets = m_layout.neighbour_offsets();
    for(std::size_t head = 0; head < queue.size(); ++head)
    {
      const std::size_t i = queue[head];
      for(std::ptrdiff_t o : offsets)
      {
        const std::size_t j = std::size_t(std::ptrdiff_t(i) + o);
        if(m_label[j] == UNREACHED)
        {
          m_label[j] = m_label[i];
          queue.push_back(std::uint32_t(j));
        }
      }
    }
  }

  // The node that reaches `k` first, or -1 where no wave arrives (outside the solid).
  std::int32_t operator()(const Voxel_key& k) const
  {
    return m_layout.box.contains(k) ? (std::max)(m_label[m_layout.index(k)], std::int32_t(-1)) : -1;
  }

private:
  static constexpr std::int32_t UNREACHED = -1, BLOCKED = -2;
  Grid_layout m_layout;
  std::vector<std::int32_t> m_label;
};

// The points of the skeleton nodes in world coordinates: each voxel's centre, or, where the
// centre lies outside the mesh (a part thinner than about two voxels, whose skeleton runs
// through voxels that the surface crosses), a point inside the mesh within the same voxel
// or, failing that, its neighbours (inside_points_in_cubes()). A centre that no grid line
// can decide (open surfaces), or where the lines find no inside, keeps its centre.
template <typename MeshLines>
std::vector<Voxel_frame::Vector> skeleton_points_inside(const std::vector<Voxel_key>& nodes, bool has_faces,
                                                        MeshLines& mesh_lines, const Voxel_frame& frame)
{
  std::vector<Vec3> centres(nodes.size());
  for(std::size_t v = 0; v < nodes.size(); ++v)
    centres[v] = Vec3{nodes[v].x + 0.5, nodes[v].y + 0.5, nodes[v].z + 0.5};
  if(has_faces)
  {
    const Grid_line_crossings& g = mesh_lines();
    const std::vector<Point_side> sides = sides_of_points(g, centres);
    std::vector<std::size_t> outside;
    std::vector<Vec3> outside_centres;
    for(std::size_t v = 0; v < nodes.size(); ++v)
      if(sides[v] == Point_side::outside)
      {
        outside.push_back(v);
        outside_centres.push_back(centres[v]);
      }
    // First the deepest inside point of the voxel itself; where the lines through the voxel
    // find none (the part only clips the voxel), the inside point nearest to the centre
    // among the voxel and its neighbours.
    std::vector<bool> found;
    const std::vector<Vec3> in_voxel =
        inside_points_in_cubes(g, outside_centres, own_voxel_half_width, Inside_piece_choice::longest, found);
    std::vector<std::size_t> missed;
    std::vector<Vec3> missed_centres;
    for(std::size_t k = 0; k < outside.size(); ++k)
      if(found[k])
        centres[outside[k]] = in_voxel[k];
      else
      {
        missed.push_back(outside[k]);
        missed_centres.push_back(outside_centres[k]);
      }
    const std::vector<Vec3> nearby =
        inside_points_in_cubes(g, missed_centres, with_neighbours_half_width, Inside_piece_choice::nearest,
                               found);
    for(std::size_t k = 0; k < missed.size(); ++k)
      if(found[k])
        centres[missed[k]] = nearby[k];
  }
  std::vector<Voxel_frame::Vector> points(nodes.size());
  for(std::size_t v = 0; v < nodes.size(); ++v)
    points[v] = frame.to_world(centres[v]);
  return points;
}

// to_graph() with its inside tests against `mesh_lines` (a callable returning the mesh's
// Grid_line_crossings in the frame of the skeleton).
template <typename VoxelSet, typename FaceGraph, typename Graph, typename VertexPointMap, typename MeshLines>
void to_graph_impl(const VoxelSet& skeleton, const Voxel_distance_field& distances, const FaceGraph& mesh,
                   Graph& graph, VertexPointMap vpm, double memory_limit, MeshLines& mesh_lines)
{
  using Vertex_bundle = typename boost::vertex_bundle_type<Graph>::type;
  using Point = decltype(Vertex_bundle::point);
  const char* caller = "to_graph";

  const Voxel_box skeleton_box = require_nonempty_box(skeleton, 1, caller);
  const Grid_layout nodes_layout(skeleton_box);
  const Grid_layout solid_layout(distances.box().grown(1)); // as Nearest_node_inside needs it
  require_memory(4. * double(nodes_layout.volume() + solid_layout.volume()), memory_limit, nodes_layout,
                 caller, "the graph of a skeleton in a box");

  const Skeleton_adjacency adjacency = skeleton_adjacency(skeleton, nodes_layout);
  const std::vector<Voxel_key>& nodes = adjacency.nodes;
  const Voxel_frame& frame = skeleton.frame();
  const std::vector<Voxel_frame::Vector> points =
      skeleton_points_inside(nodes, num_faces(mesh) != 0, mesh_lines, frame);

  graph.clear();
  for(std::size_t v = 0; v < nodes.size(); ++v)
  {
    const auto gv = add_vertex(graph);
    graph[gv].point = Point(points[v][0], points[v][1], points[v][2]);
    graph[gv].radius = distances.radius(nodes[v]);
    graph[gv].voxel = nodes[v];
  }
  for(const auto& e : adjacency.edges)
    add_edge(e.first, e.second, graph);

  // Mesh vertices.
  const Nearest_node_inside nearest_node(distances, nodes);
  for(auto mv : vertices(mesh))
  {
    const auto& p = get(vpm, mv);
    const Voxel_frame::Vector q{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      throw std::invalid_argument("to_graph: a mesh vertex has a non-finite coordinate");
    const Voxel_frame::Vector g = frame.to_grid(q);
    std::int32_t best = -1;
    if(std::abs(g[0]) < 1e9 && std::abs(g[1]) < 1e9 && std::abs(g[2]) < 1e9)
    {
      const Voxel_key k = frame.voxel_of(q);
      best = nearest_node(k);
      double best_d2 = std::numeric_limits<double>::infinity();
      if(best < 0)
        for(const Voxel_key& o : neighbourhood_26())
        {
          const Voxel_key n = k + o;
          const std::int32_t label = nearest_node(n);
          if(label < 0)
            continue;
          const double d2 = (g[0] - n.x - 0.5) * (g[0] - n.x - 0.5) +
                            (g[1] - n.y - 0.5) * (g[1] - n.y - 0.5) +
                            (g[2] - n.z - 0.5) * (g[2] - n.z - 0.5);
          if(d2 < best_d2)
          {
            best_d2 = d2;
            best = label;
          }
        }
    }
    if(best < 0) // far from the solid: the Euclidean nearest skeleton voxel
    {
      double best_d2 = std::numeric_limits<double>::infinity();
      for(std::size_t v = 0; v < nodes.size(); ++v)
      {
        const double d2 = (g[0] - nodes[v].x - 0.5) * (g[0] - nodes[v].x - 0.5) +
                          (g[1] - nodes[v].y - 0.5) * (g[1] - nodes[v].y - 0.5) +
                          (g[2] - nodes[v].z - 0.5) * (g[2] - nodes[v].z - 0.5);
        if(d2 < best_d2)
        {
          best_d2 = d2;
          best = std::int32_t(v);
        }
      }
    }
    graph[std::size_t(best)].vertices.push_back(mv);
  }
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Converts a one-voxel-thick voxel skeleton (the output of `thin()`) into a curve-skeleton
/// graph: one graph vertex per skeleton voxel, with the medial radius there; an edge
/// between 26-adjacent voxels, except the shortcuts that would make little triangles; and
/// every vertex of `mesh` mapped to exactly one graph vertex.
///
/// <b>Points.</b> A graph vertex is at its voxel's centre, in the mesh's own coordinates,
/// unless that centre is outside the mesh. Where the shape is thinner than about two voxels
/// (a horn, an ear, a tail tip), the skeleton must run through voxels that the surface
/// crosses to stay connected, and such a centre may lie outside the mesh; the vertex then
/// moves to a point inside the mesh: among the lines along the three grid axes through the
/// 3 x 3 points at -1/3, 0 and 1/3 of the voxel's cross-section, the midpoint of the
/// longest piece that is in the voxel and inside the mesh; where these lines find none (the
/// part only clips the voxel), the inside point nearest to the centre on such lines through
/// the voxel and its 26 neighbours (so a point moves by at most 1.5 voxels along each
/// axis). Inside and outside are decided by the winding number of the surface (hole-filling
/// fans included, as in `voxelize()`), counted along grid lines; a line whose crossings do
/// not sum to zero (through a gap of an open surface) cannot decide, and a vertex that no
/// line decides, or near which no line finds inside (a part much thinner than a third of a
/// voxel), stays at the centre.
///
/// <b>Edges.</b> Three pairwise 26-adjacent voxels make a triangle of the adjacency graph
/// that is no cycle of the shape. Edges are removed, longest first (a corner diagonal before
/// an edge diagonal before a face link), each only when it fills exactly one independent
/// triangle, until no triangle is left: the graph has then no triangle, the same connected
/// components as the voxels, and exactly as many independent cycles as the voxel skeleton
/// has tunnels (its first Betti number, with the voxels as closed unit cubes).
///
/// <b>Mesh vertices.</b> A mesh vertex maps to the skeleton voxel that a breadth-first
/// wave from all skeleton voxels, through the solid of `distances` (26-connected), reaches
/// first at the vertex's voxel: a nearest skeleton voxel along a path inside the shape, so a
/// vertex of a leg maps to the leg's skeleton, not to the nearest point of the other leg.
/// A vertex whose voxel the wave does not reach (outside the solid) takes a reached
/// 26-neighbour voxel's label, else the Euclidean nearest skeleton voxel.
///
/// \tparam VoxelSet a model of `VoxelSet`.
/// \tparam FaceGraph a model of `FaceListGraph`: its vertices are mapped, its faces decide
///         which voxel centres are inside.
/// \tparam Graph a `boost::adjacency_list` with `vecS` vertices, such as
///         `Curve_skeleton<Point, vertex_descriptor>`, whose vertex bundle has members
///         `point` (constructible from three `double`s), `radius` (`double`), `vertices`
///         (a container of `FaceGraph` vertex descriptors with `push_back`) and `voxel`.
/// \param skeleton the voxel skeleton (its frame maps voxels to the mesh's coordinates).
/// \param distances the distance field of the solid the skeleton was thinned from
///        (`distance_transform()`); it gives the radii and the solid for the mapping.
/// \param mesh the mesh whose vertices are mapped.
/// \param graph receives the skeleton (cleared first). Vertices are in increasing
///        `(z, y, x)` voxel order.
/// \param np optional named parameters among:
///   - `vertex_point_map`: the positions of the mesh vertices (default:
///     `get(CGAL::vertex_point, mesh)`).
///   - `fill_holes` (package parameter, `bool`): count the fans that close the mesh's holes
///     as surface in the inside test, as `voxelize()` does (default: `true`).
///   - `voxelized_surface` (package parameter, `const Voxelized_surface*`): the mesh as
///     `voxelize()` rasterised it (its `voxelized_surface_output`), for the inside test
///     (default: built from `mesh`, `vertex_point_map` and `fill_holes` when a centre is
///     in doubt). It must be in the skeleton's frame.
///   - `memory_limit` (package parameter, `double`, bytes): the most memory the function
///     may allocate (default: `default_voxel_memory_limit`, 2 GiB); the need, 4 bytes per
///     voxel of the field's box and of the skeleton's box, is checked before allocating.
///
/// \pre `skeleton` is not empty, and has the frame of `distances`.
/// \throws std::invalid_argument when `skeleton` is empty, a mesh vertex has a
///      non-finite coordinate, or `voxelized_surface` is in another frame.
/// \throws std::length_error when the work arrays would need more than `memory_limit`.
///
/// \b Complexity: O(S + B + M + F) time for S skeleton voxels, B voxels in the field's box,
///    M mesh vertices and F faces (plus the grid cells that the faces cover, seen along
///    each axis, and the rare triangle clusters, each of a few voxels).
template <typename VoxelSet, typename FaceGraph, typename Graph,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void to_graph(const VoxelSet& skeleton, const Voxel_distance_field& distances,
              const FaceGraph& mesh, Graph& graph,
              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  internal::Stage_surface<FaceGraph, decltype(vpm)> mesh_lines(
      choose_parameter(get_parameter(np, internal_np::voxelized_surface_tag), static_cast<const Voxelized_surface*>(nullptr)),
      mesh, vpm, skeleton.frame(), choose_parameter(get_parameter(np, internal_np::fill_holes_tag), true), "to_graph");
  internal::to_graph_impl(skeleton, distances, mesh, graph, vpm, internal::memory_limit(np), mesh_lines);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_TO_GRAPH_H
