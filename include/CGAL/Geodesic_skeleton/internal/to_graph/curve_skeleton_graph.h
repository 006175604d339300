// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_TO_GRAPH_CURVE_SKELETON_GRAPH_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_TO_GRAPH_CURVE_SKELETON_GRAPH_H

// The machinery of to_graph() (include/CGAL/Geodesic_skeleton/to_graph.h): not part of the API.

#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_vertex_maps.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
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
#include <type_traits>
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
  template <typename VoxelDistanceField>
  Nearest_node_inside(const VoxelDistanceField& distances, const std::vector<Voxel_key>& nodes)
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
// The graph's vertices are written through `maps` (Curve_skeleton_output_maps).
template <typename VoxelSet, typename VoxelDistanceField, typename FaceGraph, typename Graph, typename VertexPointMap,
          typename OutputMaps, typename MeshLines>
void to_graph_impl(const VoxelSet& skeleton, const VoxelDistanceField& distances, const FaceGraph& mesh,
                   Graph& graph, VertexPointMap vpm, const OutputMaps& maps, double memory_limit,
                   MeshLines& mesh_lines)
{
  using Point = typename boost::property_traits<typename OutputMaps::Point_map>::value_type;
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
    put(maps.points, gv, Point(points[v][0], points[v][1], points[v][2]));
    put_if_mapped(maps.radii, gv, distances.radius(nodes[v]));
    put_if_mapped(maps.voxels, gv, nodes[v]);
  }
  for(const auto& e : adjacency.edges)
    add_edge(e.first, e.second, graph);

  // Mesh vertices, gathered per node, then written once per node.
  using Mesh_vertex = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  std::vector<std::vector<Mesh_vertex>> mapped(nodes.size());
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
    mapped[std::size_t(best)].push_back(mv);
  }
  if constexpr(!std::is_same_v<typename OutputMaps::Mesh_vertices_map, No_map>)
  {
    using Mesh_vertex_list = typename boost::property_traits<typename OutputMaps::Mesh_vertices_map>::value_type;
    for(std::size_t v = 0; v < nodes.size(); ++v)
      put(maps.mesh_vertices, vertex(v, graph), Mesh_vertex_list(mapped[v].begin(), mapped[v].end()));
  }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_TO_GRAPH_CURVE_SKELETON_GRAPH_H
