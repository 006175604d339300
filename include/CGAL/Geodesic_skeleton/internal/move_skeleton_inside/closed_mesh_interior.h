// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CLOSED_MESH_INTERIOR_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CLOSED_MESH_INTERIOR_H

// Moving the points of a curve skeleton that smoothing took out of a closed mesh back in,
// with the inside test of the voxel stages (winding numbers along grid lines) on the
// triangles that voxelize() rasterised.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

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

// The squared distance from p to the unit cells a triangle's box covers: a lower bound of
// its distance to the triangle; 0 for a triangle without cells (not finite or far away),
// which is then measured.
inline double squared_distance_to_cells(const Vec3& p, const Grid_line_crossings::Cell_box& cells)
{
  double d2 = 0;
  for(int i = 0; i < 3; ++i)
  {
    if(cells.lo[i] > cells.hi[i])
      return 0;
    const double below = double(cells.lo[i]) - p[i], above = p[i] - (double(cells.hi[i]) + 1);
    const double gap = (std::max)({below, above, 0.});
    d2 += gap * gap;
  }
  return d2;
}

// The point of the soup of `lines` nearest p (grid coordinates), or p for an empty soup.
// A triangle whose cells are farther than the nearest point so far is skipped after a few
// comparisons. O(F) per query, with a small constant: meant for the few points to move.
inline Vec3 nearest_point_on_soup(const Grid_line_crossings& lines, const Vec3& p)
{
  Vec3 nearest = p;
  double best = std::numeric_limits<double>::infinity();
  const std::vector<Triangle3>& triangles = lines.triangles();
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    if(squared_distance_to_cells(p, lines.cells_of(t)) >= best)
      continue;
    const Vec3 q = closest_point_on_triangle(p, triangles[t]);
    const double d2 = dot3(sub(q, p), sub(q, p));
    if(d2 < best)
    {
      best = d2;
      nearest = q;
    }
  }
  return nearest;
}

// How far inside the surface move_curve_points_inside() puts a point, in voxels: deep
// enough that the rounding of coordinates cannot take it back out, shallow enough to stay
// on the medial side of a limb one voxel thin.
constexpr double depth_inside_in_voxels = 0.25;
// The step inwards is halved while it lands outside (past a part thinner than the depth),
// down to this fraction of the depth (about 20 halvings); a point still outside then is
// placed by a search of the voxels around it instead.
constexpr double smallest_inward_step_in_depths = 1e-6;

// Moves every point of a curve skeleton that lies outside a closed triangle mesh just
// inside it: to the nearest point of the surface, then `depth` voxels further along the
// direction from the point to it, halving the step while that lands outside (on the other
// side of a thin part); where no step enters, the inside point nearest to that surface
// point on grid lines within a voxel and a half of it (inside_points_in_cubes()).
// to_graph() puts the points inside, but smoothing averages them along the bends of the
// skeleton, which in a limb a few voxels thin can take them out (up to 1.6 % of the
// diagonal). Every point is tested, not only the thin ones: the medial
// radius is that of the voxel solid, which the voxels the surface touches make thicker
// than the mesh, and points of 2 to 3.3 voxels' radius come out too (cow and camel at
// resolutions 96 and 128, man at 48 to 96). The joints and the bones' points are the
// curve's points (split_into_bones()), so moving the points before the split puts them
// inside too.
//
// `lines` holds the mesh's faces in the grid coordinates of `frame` (the triangles that
// voxelize() rasterised); inside is where the winding number is not zero, as for the
// other inside tests of the voxel stages (sides_of_points()), so overlapping closed
// pieces are inside. A point no grid line can decide is left where it is. The caller
// checks that the mesh is closed (move_skeleton_inside()). Returns the vertices moved, in
// increasing order.
//
// Complexity: O(F + N + C) for F faces, N points and C pairs of a point and a face whose
// cells its grid line meets, plus O(F) for each point moved (most faces skipped by their
// cells) and O(F) per halving of the step.
template <typename CurveSkeleton>
std::vector<std::size_t> move_curve_points_inside(const Voxel_frame& frame, const Grid_line_crossings& lines,
                                                  CurveSkeleton& skeleton, double depth)
{
  using Point = decltype(skeleton[0].point);
  const std::size_t n = num_vertices(skeleton);
  std::vector<Vec3> points(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    const Point& q = skeleton[v].point;
    points[v] = frame.to_grid(Vec3{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
  }
  const std::vector<Point_side> sides = sides_of_points(lines, points);

  // The points outside, their nearest surface points and the direction inwards.
  std::vector<std::size_t> outside;
  std::vector<Vec3> on_surface, inwards;
  for(std::size_t v = 0; v < n; ++v)
  {
    if(sides[v] != Point_side::outside)
      continue;
    const Vec3 nearest = nearest_point_on_soup(lines, points[v]);
    const Vec3 in = sub(nearest, points[v]);
    const double length = norm3(in);
    if(!(length > 0))
      continue;
    outside.push_back(v);
    on_surface.push_back(nearest);
    inwards.push_back(Vec3{in[0] / length, in[1] / length, in[2] / length});
  }

  // All the candidates of one step size in one inside test.
  std::vector<bool> placed(outside.size(), false);
  std::vector<std::size_t> moved;
  for(double step = depth; step > smallest_inward_step_in_depths * depth; step /= 2)
  {
    std::vector<std::size_t> trying;
    std::vector<Vec3> candidates;
    for(std::size_t i = 0; i < outside.size(); ++i)
      if(!placed[i])
      {
        trying.push_back(i);
        const Vec3& s = on_surface[i];
        candidates.push_back(Vec3{s[0] + step * inwards[i][0], s[1] + step * inwards[i][1], s[2] + step * inwards[i][2]});
      }
    if(trying.empty())
      break;
    const std::vector<Point_side> candidate_sides = sides_of_points(lines, candidates);
    for(std::size_t k = 0; k < trying.size(); ++k)
      if(candidate_sides[k] == Point_side::inside)
      {
        placed[trying[k]] = true;
        const std::size_t v = outside[trying[k]];
        const Vec3 w = frame.to_world(candidates[k]);
        skeleton[v].point = Point(w[0], w[1], w[2]);
        moved.push_back(v);
      }
  }
  // Where no step along that direction enters the mesh (the nearest point is the tip of a
  // sharp horn, seen from the side: the direction misses the horn), the inside point
  // nearest to the surface point on grid lines around it, within a voxel and a half along
  // each axis.
  std::vector<std::size_t> unplaced;
  std::vector<Vec3> around;
  for(std::size_t i = 0; i < outside.size(); ++i)
    if(!placed[i])
    {
      unplaced.push_back(i);
      around.push_back(on_surface[i]);
    }
  std::vector<bool> found;
  const std::vector<Vec3> nearby =
      inside_points_in_cubes(lines, around, with_neighbours_half_width, Inside_piece_choice::nearest, found);
  for(std::size_t k = 0; k < unplaced.size(); ++k)
    if(found[k])
    {
      const std::size_t v = outside[unplaced[k]];
      const Vec3 w = frame.to_world(nearby[k]);
      skeleton[v].point = Point(w[0], w[1], w[2]);
      moved.push_back(v);
    }
  std::sort(moved.begin(), moved.end());
  return moved;
}

// How many joints sit on the curve-skeleton vertices `moved` (sorted): the joints that
// move_curve_points_inside() took inside with their points.
template <typename Point>
std::size_t joints_on_vertices(const Control_skeleton<Point>& control, const std::vector<std::size_t>& moved)
{
  const auto joints = vertices(control);
  return std::size_t(std::count_if(joints.first, joints.second, [&](std::size_t j) {
    return std::binary_search(moved.begin(), moved.end(), control[j].skeleton_vertex);
  }));
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CLOSED_MESH_INTERIOR_H
