// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_MESH_TRIANGLES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_MESH_TRIANGLES_H

// A mesh as a soup of triangles in double precision, with its holes closed by fans, as the
// voxel stages see it (voxelize() rasterises it; to_graph() and cut_spurious_cycles()
// count its crossings along grid lines).

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/vertex_components.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/polygon_triangles.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/principal_frame.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The triangles of the faces of `mesh` (a face with more than three vertices is split into
// its n - 2 triangles by append_polygon_triangles(), in the face's order), with finite
// coordinates checked.
template <typename FaceGraph, typename VertexPointMap>
std::vector<Triangle3> mesh_triangles(const FaceGraph& mesh, VertexPointMap vpm, const char* caller)
{
  std::vector<Triangle3> triangles;
  triangles.reserve(static_cast<std::size_t>(num_faces(mesh)));
  auto corner = [&](auto v) {
    const auto& p = get(vpm, v);
    const Vec3 q{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      throw std::invalid_argument(std::string(caller) +
                                  ": a vertex has a non-finite coordinate (NaN or infinite)");
    return q;
  };
  std::vector<Vec3> corners;
  std::vector<Corner_triple> polygon;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const auto h1 = next(h, mesh), h2 = next(h1, mesh);
    if(next(h2, mesh) == h) // a triangle: its corners in the order vertices_around_face() gives
    {
      triangles.push_back(Triangle3{corner(target(h, mesh)), corner(target(h1, mesh)), corner(target(h2, mesh))});
      continue;
    }
    corners.clear();
    for(auto v : vertices_around_face(h, mesh))
      corners.push_back(corner(v));
    polygon.clear();
    append_polygon_triangles(corners, polygon);
    for(const Corner_triple& t : polygon)
      triangles.push_back(Triangle3{corners[t[0]], corners[t[1]], corners[t[2]]});
  }
  if(triangles.empty())
    throw std::invalid_argument(std::string(caller) + ": the mesh has no faces");
  return triangles;
}

// Calls f(cycle) for each cycle of border halfedges of the mesh (a hole), with its
// halfedges in order along the border; a non-manifold border that comes back to a
// halfedge already walked ends the cycle there. O(H log H) for H halfedges.
template <typename FaceGraph, typename Function>
void for_each_border_cycle(const FaceGraph& mesh, Function f)
{
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;
  std::vector<halfedge_descriptor> border;
  for(halfedge_descriptor h : halfedges(mesh))
    if(is_border(h, mesh))
      border.push_back(h);
  std::sort(border.begin(), border.end());
  std::vector<bool> done(border.size(), false);
  std::vector<halfedge_descriptor> cycle;
  for(std::size_t start = 0; start < border.size(); ++start)
  {
    if(done[start])
      continue;
    cycle.clear();
    halfedge_descriptor h = border[start];
    for(std::size_t steps = 0; steps <= border.size(); ++steps)
    {
      const std::size_t i = std::size_t(std::lower_bound(border.begin(), border.end(), h) - border.begin());
      if(i >= border.size() || border[i] != h || done[i])
        break;
      done[i] = true;
      cycle.push_back(h);
      h = next(h, mesh);
    }
    f(cycle);
  }
}

// Closes every hole of the mesh (a cycle of border halfedges) by a fan of triangles from
// the centroid of its vertices, appended to `triangles`; returns the number of holes. The
// fan may self-intersect or cross the mesh: it is only rasterised, never used as a surface.
template <typename FaceGraph, typename VertexPointMap>
std::size_t close_holes(const FaceGraph& mesh, VertexPointMap vpm, std::vector<Triangle3>& triangles)
{
  std::size_t holes = 0;
  for_each_border_cycle(mesh, [&](const auto& cycle) {
    if(cycle.size() < 3)
      return;
    std::vector<Vec3> loop;
    for(auto h : cycle)
    {
      const auto& p = get(vpm, target(h, mesh));
      loop.push_back(Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    Vec3 centre{0., 0., 0.};
    for(const Vec3& p : loop)
      for(int c = 0; c < 3; ++c)
        centre[c] += p[c] / double(loop.size());
    for(std::size_t i = 0; i < loop.size(); ++i)
      triangles.push_back(Triangle3{centre, loop[i], loop[(i + 1) % loop.size()]});
    ++holes;
  });
  return holes;
}

// Moves the triangles into grid coordinates (`frame.to_grid` of their corners), in place:
// a copy would be as large as the mesh.
inline void to_grid(std::vector<Triangle3>& triangles, const Voxel_frame& frame)
{
  for(Triangle3& t : triangles)
    for(Vec3& corner : t)
      corner = frame.to_grid(corner);
}

// The part of each triangle of mesh_triangles() (n - 2 per face, in the order of the faces)
// and, with `fill_holes`, of each triangle of close_holes() (one per border halfedge of
// each hole): its connected component in `components` (the mesh's vertex_components(),
// through its edges). O(V + H log H) for V vertices and H halfedges.
template <typename FaceGraph>
std::vector<std::uint32_t> triangle_parts(const FaceGraph& mesh, bool fill_holes, const Vertex_components& components)
{
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  const std::vector<std::size_t>& component = components.component_of;
  const auto part = [&](auto v) { return std::uint32_t(component[static_cast<std::size_t>(get(vim, v))]); };
  std::vector<std::uint32_t> parts;
  parts.reserve(static_cast<std::size_t>(num_faces(mesh)));
  for(auto f : faces(mesh))
  {
    const std::size_t corners = static_cast<std::size_t>(degree(f, mesh));
    if(corners >= 3)
      parts.insert(parts.end(), corners - 2, part(target(halfedge(f, mesh), mesh)));
  }
  if(fill_holes)
    for_each_border_cycle(mesh, [&](const auto& cycle) {
      if(cycle.size() >= 3)
        parts.insert(parts.end(), cycle.size(), part(target(cycle.front(), mesh)));
    });
  return parts;
}

// The faces of `mesh` (and, with `fill_holes`, the fans that close its holes) in the grid
// coordinates of `frame`, ready for inside tests along grid lines.
template <typename FaceGraph, typename VertexPointMap>
Grid_line_crossings mesh_grid_lines(const FaceGraph& mesh, VertexPointMap vpm, const Voxel_frame& frame,
                                    bool fill_holes, const char* caller)
{
  std::vector<Triangle3> triangles = mesh_triangles(mesh, vpm, caller);
  if(fill_holes)
    close_holes(mesh, vpm, triangles);
  to_grid(triangles, frame);
  return Grid_line_crossings(std::move(triangles), true);
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_MESH_TRIANGLES_H
