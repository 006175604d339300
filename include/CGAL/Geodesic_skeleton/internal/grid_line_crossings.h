// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_GRID_LINE_CROSSINGS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_GRID_LINE_CROSSINGS_H

// Inside or outside a triangle soup, by counting its signed crossings along lines parallel
// to the axes of the voxel grid (the soup is in grid coordinates). A line whose crossings do
// not sum to zero (it passes through a gap of an open surface, or meets a flipped face)
// cannot tell, and another axis is tried. Crossings of many lines are found at once: the
// lines are bucketed by grid cell and each triangle visits the cells it covers, so the cost
// is O(F + L + C) for F triangles, L lines and C crossings (plus the cells covered).

#include <CGAL/Geodesic_skeleton/internal/voxelize/principal_frame.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/triangle_box_overlap.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A triangle seen along grid axis `axis`: its corners in the two other coordinates (u, v),
// taken in cyclic order so that (u, v, axis) is right-handed, and along the axis (a).
struct Projected_triangle
{
  double u[3], v[3], a[3];
  double area; // twice the signed area in (u, v): positive when the normal points along +axis
  double u_min, u_max, v_min, v_max;

  Projected_triangle(const Triangle3& t, int axis)
  {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    for(int k = 0; k < 3; ++k)
    {
      u[k] = t[k][b];
      v[k] = t[k][c];
      a[k] = t[k][axis];
    }
    area = (u[1] - u[0]) * (v[2] - v[0]) - (v[1] - v[0]) * (u[2] - u[0]);
    u_min = (std::min)({u[0], u[1], u[2]});
    u_max = (std::max)({u[0], u[1], u[2]});
    v_min = (std::min)({v[0], v[1], v[2]});
    v_max = (std::max)({v[0], v[1], v[2]});
  }

  // False for a triangle seen edge-on (or with a non-finite corner): no line crosses it once.
  bool crossable() const { return area != 0 && std::isfinite(area); }
  int sign() const { return area > 0 ? 1 : -1; }

  // Whether the line through (pu, pv) crosses the triangle, and where along the axis. A line
  // through an edge shared by two triangles crosses exactly one of them: each edge function
  // is computed from the edge's lexicographically smaller end, so both triangles get the
  // same value, and a zero goes to the triangle on the left of that direction.
  bool crossing(double pu, double pv, double& at) const
  {
    if(pu < u_min || pu > u_max || pv < v_min || pv > v_max)
      return false; // most lines that reach the edge functions would miss: a cheap test first
    const double side = area > 0 ? 1. : -1.;
    double w[3];
    for(int e = 0; e < 3; ++e)
    {
      const int p = (e + 1) % 3, q = (e + 2) % 3; // edge p -> q, weight of corner e
      const bool forward = u[p] < u[q] || (u[p] == u[q] && v[p] < v[q]);
      const int s = forward ? p : q, r = forward ? q : p;
      const double f = (u[r] - u[s]) * (pv - v[s]) - (v[r] - v[s]) * (pu - u[s]);
      w[e] = (forward ? f : -f) * side;
      if(w[e] < 0)
        return false;
      if(w[e] == 0 && !((forward ? 1. : -1.) * side > 0))
        return false;
    }
    const double sum = w[0] + w[1] + w[2];
    if(!(sum > 0))
      return false;
    at = (w[0] * a[0] + w[1] * a[1] + w[2] * a[2]) / sum;
    return true;
  }
};

// A crossing of a line: where along it, +1 or -1 by the side the triangle faces, and the
// triangle's index in the soup.
struct Line_hit
{
  double at;
  int sign;
  std::uint32_t triangle;
};

// The crossings of one line, sorted along it: a view into a Line_hits.
class Hit_range
{
public:
  Hit_range(const Line_hit* first, const Line_hit* last) : m_first(first), m_last(last) {}
  const Line_hit* begin() const { return m_first; }
  const Line_hit* end() const { return m_last; }
  std::size_t size() const { return std::size_t(m_last - m_first); }
  bool empty() const { return m_first == m_last; }
  const Line_hit& operator[](std::size_t k) const { return m_first[k]; }

private:
  const Line_hit* m_first;
  const Line_hit* m_last;
};

// The crossings of a batch of lines, stored one line after the other (one allocation for
// the batch, not one per line).
class Line_hits
{
public:
  Line_hits(std::vector<std::uint32_t> first, std::vector<Line_hit> hits)
    : m_first(std::move(first)), m_hits(std::move(hits))
  {}
  std::size_t size() const { return m_first.size() - 1; }
  Hit_range operator[](std::size_t line) const
  {
    return Hit_range(m_hits.data() + m_first[line], m_hits.data() + m_first[line + 1]);
  }

private:
  std::vector<std::uint32_t> m_first; // line l's crossings are [m_first[l], m_first[l + 1])
  std::vector<Line_hit> m_hits;
};

// A triangle soup (grid coordinates) and the crossings of lines parallel to the grid axes
// with it. The unit cells that each triangle's box covers are computed once; each call
// buckets its lines by unit cell of the two other coordinates, and each triangle looks up
// the cells its box covers (one to four, for triangles about a voxel wide) and tests only
// the lines there. A call costs O(F + L + C) for F triangles, L lines and C candidate
// pairs, a triangle far from every line a few integer comparisons. `of_a_mesh` tells that
// the soup is a mesh's faces then its hole-filling fans, in the order of mesh_triangles()
// and close_holes() (so that triangle_parts() of the mesh names their components).
class Grid_line_crossings
{
public:
  explicit Grid_line_crossings(std::vector<Triangle3> g, bool of_a_mesh = false)
    : m_g(std::move(g)), m_of_a_mesh(of_a_mesh), m_cells(m_g.size())
  {
    for(std::size_t t = 0; t < m_g.size(); ++t)
    {
      const Triangle_box box(m_g[t]);
      for(int d = 0; d < 3; ++d)
      {
        const double lo = box.lo[d], hi = box.hi[d];
        if(!(std::abs(lo) < cell_bound && std::abs(hi) < cell_bound))
        {
          // Not finite, or far beyond any grid: no line of a grid crosses it.
          m_cells[t].lo[d] = 1;
          m_cells[t].hi[d] = 0;
          continue;
        }
        m_cells[t].lo[d] = std::int32_t(floor_to_long(lo));
        m_cells[t].hi[d] = std::int32_t(floor_to_long(hi));
      }
    }
  }

  // The crossings of each line (u, v) parallel to `axis`, sorted along the line.
  Line_hits crossings(int axis, const std::vector<std::array<double, 2>>& lines) const
  {
    std::vector<std::uint32_t> first_hit(lines.size() + 1, 0);
    if(lines.empty())
      return Line_hits(std::move(first_hit), {});
    long lo[2] = {LONG_MAX, LONG_MAX}, hi[2] = {LONG_MIN, LONG_MIN};
    for(const auto& l : lines)
      for(int d = 0; d < 2; ++d)
      {
        lo[d] = (std::min)(lo[d], floor_to_long(l[d]));
        hi[d] = (std::max)(hi[d], floor_to_long(l[d]));
      }
    const std::size_t nu = std::size_t(hi[0] - lo[0] + 1), nv = std::size_t(hi[1] - lo[1] + 1);
    // The lines by cell (a counting sort): those of cell k are in_cell[first[k] .. first[k + 1]),
    // with their coordinates next to each other in `at`.
    std::vector<std::uint32_t> first(nu * nv + 1, 0), cell_of(lines.size());
    std::vector<std::uint8_t> near(nu * nv, 0); // whether a line is in the 2 x 2 cells from here on
    for(std::size_t i = 0; i < lines.size(); ++i)
    {
      const std::size_t u = std::size_t(floor_to_long(lines[i][0]) - lo[0]);
      const std::size_t v = std::size_t(floor_to_long(lines[i][1]) - lo[1]);
      cell_of[i] = std::uint32_t(v * nu + u);
      ++first[v * nu + u + 1];
      for(std::size_t dv = 0; dv < 2 && dv <= v; ++dv)
        for(std::size_t du = 0; du < 2 && du <= u; ++du)
          near[(v - dv) * nu + (u - du)] = 1;
    }
    for(std::size_t k = 1; k < first.size(); ++k)
      first[k] += first[k - 1];
    std::vector<std::uint32_t> in_cell(lines.size());
    std::vector<std::array<double, 2>> at(lines.size());
    {
      std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
      for(std::size_t i = 0; i < lines.size(); ++i)
      {
        const std::uint32_t slot = fill[cell_of[i]]++;
        in_cell[slot] = std::uint32_t(i);
        at[slot] = lines[i];
      }
    }
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    std::vector<std::pair<std::uint32_t, Line_hit>> found; // (line, crossing), by triangle
    for(std::size_t t = 0; t < m_g.size(); ++t)
    {
      const Cell_box& cells = m_cells[t];
      const long from_u = (std::max)(lo[0], long(cells.lo[b])), to_u = (std::min)(hi[0], long(cells.hi[b]));
      const long from_v = (std::max)(lo[1], long(cells.lo[c])), to_v = (std::min)(hi[1], long(cells.hi[c]));
      if(from_u > to_u || from_v > to_v)
        continue; // far from every line (or not finite)
      if(to_u - from_u <= 1 && to_v - from_v <= 1 &&
         !near[std::size_t(from_v - lo[1]) * nu + std::size_t(from_u - lo[0])])
        continue; // a small triangle with no line in its cells: most of them
      const Triangle3& g = m_g[t];
      const double u_min = (std::min)({g[0][b], g[1][b], g[2][b]}), u_max = (std::max)({g[0][b], g[1][b], g[2][b]});
      const double v_min = (std::min)({g[0][c], g[1][c], g[2][c]}), v_max = (std::max)({g[0][c], g[1][c], g[2][c]});
      std::optional<Projected_triangle> pt; // built once a line is in the triangle's box
      for(long cv = from_v; cv <= to_v; ++cv)
        for(long cu = from_u; cu <= to_u; ++cu)
        {
          const std::size_t cell = std::size_t(cv - lo[1]) * nu + std::size_t(cu - lo[0]);
          for(std::uint32_t slot = first[cell]; slot < first[cell + 1]; ++slot)
          {
            const double pu = at[slot][0], pv = at[slot][1];
            if(pu < u_min || pu > u_max || pv < v_min || pv > v_max)
              continue; // most lines of the cells miss the box of a small triangle
            if(!pt)
              pt.emplace(g, axis);
            double along;
            if(pt->crossable() && pt->crossing(pu, pv, along))
              found.emplace_back(in_cell[slot], Line_hit{along, pt->sign(), std::uint32_t(t)});
          }
        }
    }
    // By line (a counting sort, which keeps the triangles' order), then along each line.
    for(const auto& f : found)
      ++first_hit[f.first + 1];
    for(std::size_t l = 0; l < lines.size(); ++l)
      first_hit[l + 1] += first_hit[l];
    std::vector<Line_hit> hits(found.size());
    {
      std::vector<std::uint32_t> fill(first_hit.begin(), first_hit.end() - 1);
      for(const auto& f : found)
        hits[fill[f.first]++] = f.second;
    }
    for(std::size_t l = 0; l < lines.size(); ++l)
      std::sort(hits.begin() + first_hit[l], hits.begin() + first_hit[l + 1],
                [](const Line_hit& x, const Line_hit& y) { return x.at < y.at; });
    return Line_hits(std::move(first_hit), std::move(hits));
  }

  // The unit cells [lo, hi] (integer parts of the coordinates) that a triangle's box covers;
  // empty (lo > hi) for a triangle that is not finite or far beyond any grid.
  struct Cell_box
  {
    std::int32_t lo[3], hi[3];
  };

  const std::vector<Triangle3>& triangles() const { return m_g; }
  const Cell_box& cells_of(std::size_t triangle) const { return m_cells[triangle]; }
  bool of_a_mesh() const { return m_of_a_mesh; }

private:
  static constexpr double cell_bound = 1e9;

  std::vector<Triangle3> m_g;
  bool m_of_a_mesh;
  std::vector<Cell_box> m_cells;
};

// Whether the crossings of a line sum to zero: then the winding number is well defined
// along it (zero at both ends).
inline bool is_balanced(const Hit_range& hits)
{
  int total = 0;
  for(const Line_hit& h : hits)
    total += h.sign;
  return total == 0;
}

// The winding number of the surface around the point at `at` of a balanced line.
inline int winding_before(const Hit_range& hits, double at)
{
  int winding = 0;
  for(const Line_hit& h : hits)
  {
    if(!(h.at < at))
      break;
    winding += h.sign;
  }
  return winding;
}

enum class Point_side : std::uint8_t { outside, inside, undecided };

// Where each point (grid coordinates) lies: inside the surface `g` where its winding number
// is not zero, of either sign (so overlapping parts and inverted components are inside),
// along the first axis whose line through the point is balanced; undecided where no line
// is (a point in line with gaps of an open surface along all three axes).
inline std::vector<Point_side> sides_of_points(const Grid_line_crossings& g, const std::vector<Vec3>& points)
{
  std::vector<Point_side> side(points.size(), Point_side::undecided);
  std::vector<std::size_t> pending(points.size());
  std::iota(pending.begin(), pending.end(), std::size_t(0));
  for(int axis = 0; axis < 3 && !pending.empty(); ++axis)
  {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    std::vector<std::array<double, 2>> lines;
    lines.reserve(pending.size());
    for(std::size_t i : pending)
      lines.push_back({points[i][b], points[i][c]});
    const auto hits = g.crossings(axis, lines);
    std::vector<std::size_t> still;
    for(std::size_t k = 0; k < pending.size(); ++k)
    {
      if(!is_balanced(hits[k]))
      {
        still.push_back(pending[k]);
        continue;
      }
      const std::size_t i = pending[k];
      side[i] = winding_before(hits[k], points[i][axis]) != 0 ? Point_side::inside : Point_side::outside;
    }
    pending.swap(still);
  }
  return side;
}

// The half-widths (voxels) of the cubes that inside_points_in_cubes() searches around a
// voxel centre: the voxel itself, or the voxel and its 26 neighbours.
constexpr double own_voxel_half_width = 0.5;
constexpr double with_neighbours_half_width = 1.5;
// The spacing of the lines that inside_points_in_cubes() casts through a cube: this many
// per voxel along each axis (3: the lines at -1/3, 0 and 1/3 of a voxel's cross-section),
// so that a part a third of a voxel thick is still met, for 9 lines per axis and voxel.
constexpr int lines_per_voxel = 3;
// The shortest inside piece of a line that inside_points_in_cubes() takes (voxels). A line
// that grazes an edge or a corner of the surface crosses it twice at the same place up to
// rounding: the piece between is a sliver whose midpoint lies on the surface, outside for
// any other inside test (it put a curve point of bones.off on the surface at resolution 64).
constexpr double shortest_inside_piece = 1e-6;

// How inside_points_in_cubes() chooses among the inside pieces of its lines.
enum class Inside_piece_choice { longest, nearest };

// For each cube of centre `centres[i]` (grid coordinates) and half-width `half_width`
// (voxels): a point inside the surface `g` and in the cube, found on the lines along the
// three axes through the points of the cube's cross-section at multiples of 1/3 voxel from
// its centre (3 x 3 lines per axis in a voxel, 9 x 9 in a cube of three voxels). Among the
// pieces of these (balanced) lines that are both in the cube and inside the surface, the
// midpoint of the longest (the deepest point in the thinnest direction the lines sample),
// or the midpoint nearest the centre. The axes are tried in turn, the next one only for the
// cubes where the lines so far found nothing. `found[i]` is false where no line has such a piece
// (the surface only grazes the cube, or is thinner than the lines' spacing there).
inline std::vector<Vec3> inside_points_in_cubes(const Grid_line_crossings& g, const std::vector<Vec3>& centres,
                                                double half_width, Inside_piece_choice choice,
                                                std::vector<bool>& found)
{
  std::vector<double> offsets;
  const int reach = int(std::ceil(lines_per_voxel * half_width));
  for(int k = -reach; k <= reach; ++k)
    if(std::abs(k / double(lines_per_voxel)) < half_width)
      offsets.push_back(k / double(lines_per_voxel));
  const std::size_t per_cube = offsets.size() * offsets.size();
  std::vector<Vec3> best_point(centres);
  std::vector<double> best_score(centres.size(), -HUGE_VAL);
  found.assign(centres.size(), false);
  std::vector<std::size_t> pending(centres.size());
  std::iota(pending.begin(), pending.end(), std::size_t(0));
  for(int axis = 0; axis < 3 && !pending.empty(); ++axis)
  {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    std::vector<std::array<double, 2>> lines;
    lines.reserve(per_cube * pending.size());
    for(std::size_t i : pending)
      for(double dv : offsets)
        for(double du : offsets)
          lines.push_back({centres[i][b] + du, centres[i][c] + dv});
    const auto hits = g.crossings(axis, lines);
    for(std::size_t l = 0; l < lines.size(); ++l)
    {
      if(hits[l].empty() || !is_balanced(hits[l]))
        continue;
      const std::size_t i = pending[l / per_cube];
      const double from = centres[i][axis] - half_width, to = centres[i][axis] + half_width;
      int winding = 0;
      for(std::size_t k = 0; k + 1 < hits[l].size(); ++k)
      {
        winding += hits[l][k].sign;
        const double piece_from = (std::max)(from, hits[l][k].at);
        const double piece_to = (std::min)(to, hits[l][k + 1].at);
        if(winding == 0 || !(piece_to - piece_from > shortest_inside_piece))
          continue;
        Vec3 q;
        q[axis] = 0.5 * (piece_from + piece_to);
        q[b] = lines[l][0];
        q[c] = lines[l][1];
        const double score = choice == Inside_piece_choice::longest ? piece_to - piece_from
                                                                   : -norm3(sub(q, centres[i]));
        if(score > best_score[i])
        {
          best_score[i] = score;
          best_point[i] = q;
          found[i] = true;
        }
      }
    }
    // The other axes only for the cubes where this one found nothing.
    std::vector<std::size_t> still;
    for(std::size_t i : pending)
      if(!found[i])
        still.push_back(i);
    pending.swap(still);
  }
  return best_point;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_GRID_LINE_CROSSINGS_H
