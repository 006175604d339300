// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_MESH_TRIANGLES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_MESH_TRIANGLES_H

// A mesh as a soup of triangles in double precision, with its holes (not the rims of its
// sheets) closed by fans, as the voxel stages see it (voxelize() rasterises it; to_graph()
// and cut_spurious_cycles() count its crossings along grid lines).

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/vertex_components.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>
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

// A border cycle whose fan (from the centroid of its vertices) has at least this fraction of
// the area of the mesh component it bounds is the rim of a sheet, not a hole: a cape, a
// flag or a wing made as one layer of faces, whose fan would add a second layer a few
// voxels off the first and a lens of volume between them. A hole that the modeller left (an
// open neck, a missing sole, faces lost) is small beside its component: a hemisphere's rim
// has a fan of half its area, a sheet bent by a right angle nine tenths.
constexpr double sheet_rim_fan_area_fraction = 0.75;

// A border cycle of a mesh: its vertices' points in order, the index of one of them (to
// name its connected component), and whether a fan closes it.
struct Border_loop
{
  std::vector<Vec3> points;
  std::size_t vertex = 0;
  bool closed = false;
};

// The triangles that close `loop` by a fan from the centroid of its points.
inline std::vector<Triangle3> fan_of(const std::vector<Vec3>& loop)
{
  Vec3 centre{0., 0., 0.};
  for(const Vec3& p : loop)
    for(int c = 0; c < 3; ++c)
      centre[c] += p[c] / double(loop.size());
  std::vector<Triangle3> fan;
  for(std::size_t i = 0; i < loop.size(); ++i)
    fan.push_back(Triangle3{centre, loop[i], loop[(i + 1) % loop.size()]});
  return fan;
}

inline double area_of(const Triangle3& t) { return 0.5 * norm3(cross3(sub(t[1], t[0]), sub(t[2], t[0]))); }

// The mesh's border cycles of three edges or more (for_each_border_cycle()'s order) and,
// with `fill_holes`, whether each is closed by a fan: every cycle whose fan has less than
// sheet_rim_fan_area_fraction of its component's area. When that leaves no component closed
// (every component has the rim of a sheet: a cape alone, a curved patch), every cycle is,
// as the only way such a mesh encloses some volume. Without `fill_holes`, none is.
// `known_components`, when given, are the mesh's vertex_components(); else they are computed
// when a cycle needs them. O(V + F + H log H) for V vertices, F faces and H halfedges.
template <typename FaceGraph, typename VertexPointMap>
std::vector<Border_loop> border_loops(const FaceGraph& mesh, VertexPointMap vpm, bool fill_holes,
                                      const Vertex_components* known_components = nullptr)
{
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  const auto point = [&](auto v) {
    const auto& p = get(vpm, v);
    return Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  };
  std::vector<Border_loop> loops;
  for_each_border_cycle(mesh, [&](const auto& cycle) {
    if(cycle.size() < 3)
      return;
    Border_loop loop;
    for(auto h : cycle)
      loop.points.push_back(point(target(h, mesh)));
    loop.vertex = std::size_t(get(vim, target(cycle.front(), mesh)));
    loop.closed = fill_holes;
    loops.push_back(std::move(loop));
  });
  if(loops.empty() || !fill_holes)
    return loops;

  std::optional<Vertex_components> computed_components;
  if(known_components == nullptr)
    computed_components = vertex_components(mesh, vim);
  const Vertex_components& components = known_components ? *known_components : *computed_components;
  std::vector<double> area(components.count, 0.);
  std::vector<Vec3> corners;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh);
    const Vec3 first = point(target(h, mesh));
    corners.clear();
    for(auto v : vertices_around_face(h, mesh))
      corners.push_back(point(v));
    double face_area = 0;
    for(std::size_t i = 1; i + 1 < corners.size(); ++i)
      face_area += area_of(Triangle3{first, corners[i], corners[i + 1]});
    area[components.component_of[std::size_t(get(vim, target(h, mesh)))]] += face_area;
  }
  std::vector<bool> has_sheet_rim(components.count, false);
  for(Border_loop& loop : loops)
  {
    const std::size_t component = components.component_of[loop.vertex];
    double fan_area = 0;
    for(const Triangle3& t : fan_of(loop.points))
      fan_area += area_of(t);
    loop.closed = fan_area < sheet_rim_fan_area_fraction * area[component];
    if(!loop.closed)
      has_sheet_rim[component] = true;
  }
  if(std::find(has_sheet_rim.begin(), has_sheet_rim.end(), false) == has_sheet_rim.end())
    for(Border_loop& loop : loops)
      loop.closed = true;
  return loops;
}

// Closes the holes of the mesh that border_loops() closes (with `fill_holes`, every
// cycle of border halfedges but the rims of sheets) by fans of triangles from the centroid
// of their vertices, appended to `triangles`; returns the number of holes closed. The fan
// may self-intersect or cross the mesh: it is only rasterised, never used as a surface.
template <typename FaceGraph, typename VertexPointMap>
std::size_t close_holes(const FaceGraph& mesh, VertexPointMap vpm, std::vector<Triangle3>& triangles,
                        bool fill_holes = true)
{
  std::size_t holes = 0;
  for(const Border_loop& loop : border_loops(mesh, vpm, fill_holes))
    if(loop.closed)
    {
      const std::vector<Triangle3> fan = fan_of(loop.points);
      triangles.insert(triangles.end(), fan.begin(), fan.end());
      ++holes;
    }
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
// and of each triangle of close_holes() (one per border halfedge of each hole it closes):
// its connected component in `components` (the mesh's vertex_components(), through its
// edges). O(V + F + H log H) for V vertices, F faces and H halfedges.
template <typename FaceGraph, typename VertexPointMap>
std::vector<std::uint32_t> triangle_parts(const FaceGraph& mesh, VertexPointMap vpm, bool fill_holes,
                                          const Vertex_components& components)
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
  for(const Border_loop& loop : border_loops(mesh, vpm, fill_holes, &components))
    if(loop.closed)
      parts.insert(parts.end(), loop.points.size(), std::uint32_t(component[loop.vertex]));
  return parts;
}

// The faces of `mesh` (and, with `fill_holes`, the fans that close its holes) in the grid
// coordinates of `frame`, ready for inside tests along grid lines.
template <typename FaceGraph, typename VertexPointMap>
Grid_line_crossings mesh_grid_lines(const FaceGraph& mesh, VertexPointMap vpm, const Voxel_frame& frame,
                                    bool fill_holes, const char* caller)
{
  std::vector<Triangle3> triangles = mesh_triangles(mesh, vpm, caller);
  close_holes(mesh, vpm, triangles, fill_holes);
  to_grid(triangles, frame);
  return Grid_line_crossings(std::move(triangles), true);
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_MESH_TRIANGLES_H
