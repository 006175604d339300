// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_DISTANCE_FROM_THE_MIDDLE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_DISTANCE_FROM_THE_MIDDLE_H

// How far along the surface of the mesh points lie from the middle of the model, for the
// order of cut_spurious_cycles()' removals: not part of the API.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/vertex_components.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The area-weighted centroid of the surface, all its connected components together (each
// face's area at its centroid, a polygon as the fan of triangles from its first corner; the
// mean of the vertices for a surface without area): a middle of the model that does not
// depend on how finely each part is tessellated, and that moves with the mesh.
template <typename FaceGraph, typename VertexIndexMap>
Vec3 surface_centroid(const FaceGraph& mesh, VertexIndexMap vim, const std::vector<Vec3>& point)
{
  const auto at = [&](auto v) -> const Vec3& { return point[static_cast<std::size_t>(get(vim, v))]; };
  Vec3 weighted{0, 0, 0};
  double area = 0;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const Vec3& a = at(target(h, mesh));
    for(auto k = next(h, mesh); target(next(k, mesh), mesh) != target(h, mesh); k = next(k, mesh))
    {
      const Vec3& b = at(target(k, mesh));
      const Vec3& c = at(target(next(k, mesh), mesh));
      const double triangle_area = norm3(cross3(sub(b, a), sub(c, a))) / 2;
      for(std::size_t d = 0; d < 3; ++d)
        weighted[d] += triangle_area * (a[d] + b[d] + c[d]) / 3;
      area += triangle_area;
    }
  }
  if(area > 0)
    return Vec3{weighted[0] / area, weighted[1] / area, weighted[2] / area};
  Vec3 mean{0, 0, 0};
  for(const Vec3& p : point)
    for(std::size_t d = 0; d < 3; ++d)
      mean[d] += p[d] / double(point.size());
  return mean;
}

// Of each connected component, the vertex nearest `middle` (by index).
template <typename FaceGraph, typename VertexIndexMap>
std::vector<std::size_t> nearest_vertex_per_component(const FaceGraph& mesh, VertexIndexMap vim,
                                                      const std::vector<Vec3>& point,
                                                      const Vertex_components& components, const Vec3& middle)
{
  std::vector<std::size_t> nearest(components.count, 0);
  std::vector<double> best(components.count, std::numeric_limits<double>::infinity());
  for(auto v : vertices(mesh))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    const std::size_t c = components.component_of[i];
    const double d = squared_distance3(point[i], middle);
    if(d < best[c])
    {
      best[c] = d;
      nearest[c] = i;
    }
  }
  return nearest;
}

// The mesh's vertices and edges as compressed rows: the neighbours of vertex i (by index)
// are `to[first[i] .. first[i + 1])`, at the lengths `length[...]` (single precision: they
// only order the cut's trials).
struct Mesh_adjacency
{
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> to;
  std::vector<float> length;
};

template <typename FaceGraph, typename VertexIndexMap>
Mesh_adjacency mesh_adjacency(const FaceGraph& mesh, VertexIndexMap vim, const std::vector<Vec3>& point)
{
  const auto index = [&](auto v) { return static_cast<std::uint32_t>(get(vim, v)); };
  Mesh_adjacency a;
  a.first.assign(point.size() + 1, 0);
  for(auto h : halfedges(mesh))
    ++a.first[index(target(h, mesh)) + 1];
  for(std::size_t i = 0; i < point.size(); ++i)
    a.first[i + 1] += a.first[i];
  a.to.resize(a.first.back());
  a.length.resize(a.first.back());
  std::vector<std::uint32_t> next(a.first.begin(), a.first.end() - 1);
  for(auto h : halfedges(mesh))
  {
    const std::uint32_t to = index(target(h, mesh)), from = index(source(h, mesh));
    const std::uint32_t k = next[to]++;
    a.to[k] = from;
    a.length[k] = float(norm3(sub(point[from], point[to])));
  }
  return a;
}

// The lengths of the shortest paths along `graph` from `sources` (vertex indices), by
// index; infinity for a vertex never reached, and an edge of non-finite length (a vertex at
// NaN or infinity) links nothing. The vertices are taken in buckets of distance as wide as
// the mean edge (Dial's order, label-correcting: a vertex improved after it was taken is
// taken again, so the lengths are exact whatever the width). No path is longer than all
// the edges together, so there are at most as many buckets as edge ends; O(V + E) in
// practice, since a mesh's edges are about as long as each other.
inline std::vector<float> shortest_path_lengths(const Mesh_adjacency& graph, const std::vector<std::size_t>& sources)
{
  double total = 0;
  std::size_t finite = 0;
  for(float l : graph.length)
    if(std::isfinite(l))
    {
      total += double(l);
      ++finite;
    }
  const double width = total > 0 ? total / double(finite) : 1;
  std::vector<float> distance(graph.first.size() - 1, std::numeric_limits<float>::infinity());
  const auto bucket_of = [&](float d) { return std::size_t(double(d) / width); };
  std::vector<std::vector<std::uint32_t>> buckets(1);
  for(std::size_t s : sources)
  {
    distance[s] = 0;
    buckets[0].push_back(std::uint32_t(s));
  }
  for(std::size_t b = 0; b < buckets.size(); ++b)
    for(std::size_t k = 0; k < buckets[b].size(); ++k)
    {
      const std::uint32_t v = buckets[b][k];
      if(bucket_of(distance[v]) != b)
        continue; // taken again from a nearer bucket
      for(std::uint32_t e = graph.first[v]; e < graph.first[v + 1]; ++e)
      {
        const float d = distance[v] + graph.length[e];
        if(d < distance[graph.to[e]]) // false for a NaN or infinite length
        {
          distance[graph.to[e]] = d;
          const std::size_t to_bucket = bucket_of(d);
          if(to_bucket >= buckets.size())
            buckets.resize(to_bucket + 1);
          buckets[to_bucket].push_back(graph.to[e]);
        }
      }
    }
  return distance;
}

// The vertex (index into `point`) nearest each of `queries`, by brute force: O(V Q).
inline std::vector<std::size_t> nearest_vertices(const std::vector<Vec3>& point, const std::vector<Vec3>& queries)
{
  std::vector<std::size_t> nearest(queries.size(), 0);
  std::vector<double> best(queries.size(), std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < point.size(); ++i)
    for(std::size_t q = 0; q < queries.size(); ++q)
    {
      const double d = squared_distance3(point[i], queries[q]);
      if(d < best[q])
      {
        best[q] = d;
        nearest[q] = i;
      }
    }
  return nearest;
}

// How far along the surface voxels lie from the middle of the model: the length of the
// shortest path along the mesh's edges to the vertex nearest the voxel's centre from the
// vertex of its connected component nearest the surface's centroid. A part that hangs from
// a body (a limb, a tail) lies farther the nearer its tip a voxel is, also when the part is
// a piece of its own. Everything is measured in the grid coordinates of `frame` (voxels),
// so that neither the centroid's sums nor the single-precision lengths overflow or vanish,
// whatever the mesh's scale. `components`: the mesh's vertex_components().
//
// Complexity: O(F + E) to build, for F face corners and E edges, in practice (one run of
// shortest_path_lengths()), and O(V Q) for Q voxels asked (their nearest vertices, by brute
// force: the voxels are the few a cut chooses among).
class Surface_distance_from_the_middle
{
public:
  template <typename FaceGraph, typename VertexPointMap>
  Surface_distance_from_the_middle(const FaceGraph& mesh, VertexPointMap vpm, const Vertex_components& components,
                                   const Voxel_frame& frame)
  {
    const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
    m_point.resize(static_cast<std::size_t>(num_vertices(mesh)));
    for(auto v : vertices(mesh))
    {
      const auto& p = get(vpm, v);
      m_point[static_cast<std::size_t>(get(vim, v))] =
          frame.to_grid({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    if(m_point.empty())
      return;
    m_distance = shortest_path_lengths(
        mesh_adjacency(mesh, vim, m_point),
        nearest_vertex_per_component(mesh, vim, m_point, components, surface_centroid(mesh, vim, m_point)));
  }

  // The distance of each of `voxels`, in voxels; infinity for a mesh without vertices.
  std::vector<double> operator()(const std::vector<Voxel_key>& voxels) const
  {
    if(m_point.empty())
      return std::vector<double>(voxels.size(), std::numeric_limits<double>::infinity());
    std::vector<Vec3> centres;
    for(const Voxel_key& k : voxels)
      centres.push_back({k.x + 0.5, k.y + 0.5, k.z + 0.5});
    std::vector<double> distance;
    for(std::size_t i : nearest_vertices(m_point, centres))
      distance.push_back(m_distance[i]);
    return distance;
  }

private:
  std::vector<Vec3> m_point;     // by vertex index, in grid coordinates
  std::vector<float> m_distance; // by vertex index, in voxels
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_DISTANCE_FROM_THE_MIDDLE_H
