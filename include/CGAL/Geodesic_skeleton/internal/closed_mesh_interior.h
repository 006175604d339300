// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CLOSED_MESH_INTERIOR_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CLOSED_MESH_INTERIOR_H

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/internal/principal_frame.h>
#include <CGAL/Geodesic_skeleton/internal/triangle_box_overlap.h>
#include <CGAL/Geodesic_skeleton/internal/vertex_components.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Where the ray from p along d meets triangle t: not at all, once, or too near an edge or
// a vertex to tell (where a crossing could be counted twice or missed). Moeller-Trumbore.
enum class Ray_meets { no, once, unclear };

inline Ray_meets ray_meets_triangle(const Vec3& p, const Vec3& d, const Triangle3& t)
{
  // p + s d = t0 + u (t1 - t0) + v (t2 - t0).
  const Vec3 e1 = sub(t[1], t[0]), e2 = sub(t[2], t[0]);
  const Vec3 h = cross3(d, e2);
  const double det = dot3(e1, h);
  const double scale = norm3(e1) * norm3(e2); // not sqrt of a product of squares: it overflows sooner
  if(std::abs(det) <= 1e-12 * scale)
    return Ray_meets::no; // the ray runs along the triangle's plane: no single crossing
  const Vec3 w = sub(p, t[0]);
  const double u = dot3(w, h) / det;
  const Vec3 q = cross3(w, e1);
  const double v = dot3(d, q) / det;
  const double s = dot3(e2, q) / det;
  const double margin = 1e-9;
  if(u < -margin || v < -margin || u + v > 1 + margin || s < 0)
    return Ray_meets::no;
  if(u < margin || v < margin || u + v > 1 - margin || s < margin)
    return Ray_meets::unclear;
  return Ray_meets::once;
}

// Whether the box of a triangle can meet the ray from p along grid axis `axis`.
inline bool box_meets_axis_ray(const Vec3& p, int axis, const Triangle_box& box)
{
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  return !(p[a] < box.lo[a] || p[a] > box.hi[a] || p[b] < box.lo[b] || p[b] > box.hi[b] || p[axis] > box.hi[axis]);
}

// The directions of the rays of is_inside_closed_soup(), in the order they are tried.
inline const std::array<Vec3, 5>& ray_directions()
{
  static const std::array<Vec3, 5> directions = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1},
                                                 Vec3{0.5773502692, 0.5773502692, 0.5773502692},
                                                 Vec3{0.2672612419, -0.5345224838, 0.8017837257}};
  return directions;
}

// The pieces of a closed triangle soup (its connected components) that a ray has crossed
// an odd number of times so far: its origin is inside the pieces left, by ray parity.
// Parity is taken piece by piece, so that where two closed pieces overlap (a character's
// parts, a self-intersecting union), which voxelize() fills, the point is inside, not
// outside as the parity of all the crossings would say.
class Odd_pieces
{
public:
  void cross(std::size_t piece)
  {
    const auto i = std::find(m_odd.begin(), m_odd.end(), piece);
    if(i == m_odd.end())
      m_odd.push_back(piece);
    else
      m_odd.erase(i);
  }
  bool inside_some_piece() const { return !m_odd.empty(); }

private:
  std::vector<std::size_t> m_odd; // few: the pieces overlapping at one point
};

// Whether p is inside one of the closed pieces of a triangle soup (`piece_of` each triangle),
// by ray parity (Odd_pieces). Rays go along the axes first, so that a triangle whose box
// misses the ray's line is skipped with a few comparisons. A ray that passes too near an
// edge or a vertex of a triangle is dropped and another direction tried, from
// `first_direction` on. Costs O(F) per query: meant for the few points in doubt.
inline bool is_inside_closed_soup(const Vec3& p, const std::vector<Triangle3>& triangles,
                                  const std::vector<std::size_t>& piece_of, int first_direction = 0)
{
  for(int axis = first_direction; axis < 5; ++axis)
  {
    const Vec3& d = ray_directions()[std::size_t(axis)];
    bool ambiguous = false;
    Odd_pieces odd;
    for(std::size_t i = 0; i < triangles.size() && !ambiguous; ++i)
    {
      if(axis < 3 && !box_meets_axis_ray(p, axis, Triangle_box(triangles[i])))
        continue;
      const Ray_meets meets = ray_meets_triangle(p, d, triangles[i]);
      ambiguous = meets == Ray_meets::unclear;
      if(meets == Ray_meets::once)
        odd.cross(piece_of[i]);
    }
    if(!ambiguous)
      return odd.inside_some_piece();
  }
  return false;
}

// The point of triangle t nearest p (by the regions of the triangle's Voronoi diagram).
inline Vec3 closest_point_on_triangle(const Vec3& p, const Triangle3& t)
{
  const Vec3 ab = sub(t[1], t[0]), ac = sub(t[2], t[0]), ap = sub(p, t[0]);
  const double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
  if(d1 <= 0 && d2 <= 0)
    return t[0];
  const Vec3 bp = sub(p, t[1]);
  const double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
  if(d3 >= 0 && d4 <= d3)
    return t[1];
  auto along = [](const Vec3& a, const Vec3& e, double f) {
    return Vec3{a[0] + f * e[0], a[1] + f * e[1], a[2] + f * e[2]};
  };
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0 && d1 >= 0 && d3 <= 0)
    return along(t[0], ab, d1 / (d1 - d3));
  const Vec3 cp = sub(p, t[2]);
  const double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
  if(d6 >= 0 && d5 <= d6)
    return t[2];
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0 && d2 >= 0 && d6 <= 0)
    return along(t[0], ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return along(t[1], sub(t[2], t[1]), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denominator = 1 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return Vec3{t[0][0] + ab[0] * v + ac[0] * w, t[0][1] + ab[1] * v + ac[1] * w, t[0][2] + ab[2] * v + ac[2] * w};
}

// The triangles of a closed triangle mesh and the piece (connected component) of each, to
// ask whether points are inside it and to move the ones outside just in. Empty (and every
// answer "leave it") for a mesh that is not a closed triangle mesh: it has no inside to test.
class Closed_mesh_interior
{
public:
  // `face_triangles` are the faces of `mesh`, in world coordinates, in the order of
  // faces(mesh) (mesh_triangles()).
  template <typename TriangleMesh>
  Closed_mesh_interior(const TriangleMesh& mesh, std::vector<Triangle3> face_triangles)
  {
    if(!CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
      return;
    m_triangles = std::move(face_triangles);
    const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
    const Vertex_components pieces = vertex_components(mesh, vim);
    for(auto f : faces(mesh))
      m_piece_of.push_back(pieces.component_of[std::size_t(get(vim, target(halfedge(f, mesh), mesh)))]);
  }

  bool has_interior() const { return !m_triangles.empty(); }

  // Whether each point is inside (is_inside_closed_soup()), the rays along x of all the
  // points in one pass over the triangles (the points sorted by y, each triangle looking up
  // those in its box's y range); the other rays only for the points x cannot tell.
  std::vector<bool> inside(const std::vector<Vec3>& points) const
  {
    std::vector<std::size_t> by_y(points.size());
    for(std::size_t k = 0; k < points.size(); ++k)
      by_y[k] = k;
    std::sort(by_y.begin(), by_y.end(), [&](std::size_t a, std::size_t b) { return points[a][1] < points[b][1]; });
    std::vector<Odd_pieces> odd(points.size());
    std::vector<bool> unclear(points.size(), false);
    for(std::size_t i = 0; i < m_triangles.size(); ++i)
    {
      const Triangle_box box(m_triangles[i]); // (not stored: as large as the mesh)
      auto k = std::lower_bound(by_y.begin(), by_y.end(), box.lo[1],
                                [&](std::size_t a, double y) { return points[a][1] < y; });
      for(; k != by_y.end() && points[*k][1] <= box.hi[1]; ++k)
      {
        if(unclear[*k] || !box_meets_axis_ray(points[*k], 0, box))
          continue;
        const Ray_meets meets = ray_meets_triangle(points[*k], ray_directions()[0], m_triangles[i]);
        unclear[*k] = meets == Ray_meets::unclear;
        if(meets == Ray_meets::once)
          odd[*k].cross(m_piece_of[i]);
      }
    }
    std::vector<bool> in(points.size());
    for(std::size_t k = 0; k < points.size(); ++k)
      in[k] = unclear[k] ? is_inside_closed_soup(points[k], m_triangles, m_piece_of, 1) : odd[k].inside_some_piece();
    return in;
  }

  // Moves `p`, outside the mesh, to the nearest point of the surface and `depth` further in
  // (halving the step while it would leave the mesh on the other side). Returns whether it
  // moved.
  bool move_inside(Vec3& p, double depth) const
  {
    if(!has_interior())
      return false;
    Vec3 nearest = p;
    double best = std::numeric_limits<double>::infinity();
    for(const Triangle3& t : m_triangles)
    {
      const Vec3 q = closest_point_on_triangle(p, t);
      const double d = dot3(sub(q, p), sub(q, p));
      if(d < best)
      {
        best = d;
        nearest = q;
      }
    }
    const Vec3 in = sub(nearest, p);
    const double length = norm3(in);
    if(!(length > 0))
      return false;
    for(double step = depth; step > 1e-6 * depth; step /= 2)
    {
      const Vec3 candidate{nearest[0] + step * in[0] / length, nearest[1] + step * in[1] / length,
                           nearest[2] + step * in[2] / length};
      if(is_inside_closed_soup(candidate, m_triangles, m_piece_of))
      {
        p = candidate;
        return true;
      }
    }
    return false;
  }

private:
  std::vector<Triangle3> m_triangles;
  std::vector<std::size_t> m_piece_of; // by triangle
};

// Moves every point of a curve skeleton that lies outside a closed triangle mesh just
// inside it (see Closed_mesh_interior::move_inside): to_graph() puts the points inside,
// but smoothing averages them along the bends of the skeleton, which in a limb a few
// voxels thin can take them out (up to 1.6 % of the diagonal). Every point is tested,
// not only the thin ones: the medial radius is that of the voxel solid, which the voxels
// the surface touches make thicker than the mesh, and points of 2 to 3.3 voxels' radius
// come out too (cow and camel at resolutions 96 and 128, man at 48 to 96). The joints and
// the bones' points are the curve's points (split_into_bones()), so moving the points
// before the split puts them inside too. Returns the vertices moved, in increasing order.
//
// Complexity: O(F log N + C) for N points, F faces and C pairs of a point and a face that
// its ray along x may cross, plus O(F) for each point moved.
template <typename TriangleMesh, typename VertexPointMap, typename CurveSkeleton>
std::vector<std::size_t> move_curve_points_inside(const TriangleMesh& mesh, VertexPointMap vpm,
                                                  CurveSkeleton& skeleton, double depth)
{
  using Point = decltype(skeleton[0].point);
  const std::size_t n = num_vertices(skeleton);
  if(n == 0 || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh))
    return {};
  std::vector<Vec3> points(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    const Point& q = skeleton[v].point;
    points[v] = Vec3{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
  }
  const Closed_mesh_interior interior(mesh, mesh_triangles(mesh, vpm, "extract_control_skeleton"));
  const std::vector<bool> inside = interior.inside(points);
  std::vector<std::size_t> moved;
  for(std::size_t v = 0; v < n; ++v)
    if(!inside[v] && interior.move_inside(points[v], depth))
    {
      skeleton[v].point = Point(points[v][0], points[v][1], points[v][2]);
      moved.push_back(v);
    }
  return moved;
}

// How many joints sit on the curve-skeleton vertices `moved` (sorted): the joints that
// move_curve_points_inside() took inside with their points.
template <typename Point>
std::size_t joints_on_vertices(const Control_skeleton<Point>& control, const std::vector<std::size_t>& moved)
{
  return std::size_t(std::count_if(control.joints.begin(), control.joints.end(), [&](const Control_joint<Point>& j) {
    return std::binary_search(moved.begin(), moved.end(), j.skeleton_vertex);
  }));
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CLOSED_MESH_INTERIOR_H
