// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_INTERNAL_INDEXED_SOUP_H
#define CGAL_GEODESIC_SKELETON_IO_INTERNAL_INDEXED_SOUP_H

// A polygon soup in flat arrays (the corners of all polygons in one array), the test that
// it already is an oriented manifold mesh, and the construction of a mesh from it without
// CGAL's Euler::add_face, which searches the mesh for every edge. IO::read_mesh() uses them
// for the files its fast readers parse; a soup that fails the test takes CGAL's repair path.

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

// Polygon f has the corners corners[offsets[f]] ... corners[offsets[f + 1] - 1], each a
// point index.
struct Indexed_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::uint32_t> corners;
  std::vector<std::uint32_t> offsets{0};

  std::size_t number_of_polygons() const { return offsets.size() - 1; }
  std::size_t polygon_size(std::size_t f) const { return offsets[f + 1] - offsets[f]; }
  void close_polygon() { offsets.push_back(static_cast<std::uint32_t>(corners.size())); }

  bool has_only_finite_points() const
  {
    for(const auto& p : points)
      if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        return false;
    return true;
  }
  bool has_only_valid_indices() const
  {
    for(std::uint32_t i : corners)
      if(i >= points.size())
        return false;
    return true;
  }
};

// The directed edges of a soup, their twins, and whether the polygons around each point
// form one fan. A directed edge is named by its corner: corner c leads from point
// corners[c] to the point of the next corner of its polygon; its twin is the corner whose
// edge leads back, or `none`.
//
// Everything is read from the star of each point: the corners at the point, each with the
// point after it and the point before it in its polygon. The twin of corner c (edge v -> w)
// is the edge w -> v, which ends at v: it belongs to the corner before the corner at v whose
// previous point is w, in v's own star. So one scatter of the corners into stars (compressed
// rows) is the only access out of order; the rest reads each star as a contiguous block.
class Directed_edge_table
{
public:
  static constexpr std::uint32_t none = std::uint32_t(-1);

  // Precondition: fewer than 2^32 - 1 corners, every index below the number of points.
  explicit Directed_edge_table(const Indexed_soup& soup) : m_soup(soup)
  {
    const std::size_t n = soup.points.size(), m = soup.corners.size();
    m_next.resize(m);
    for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
      for(std::uint32_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c)
        m_next[c] = c + 1 == soup.offsets[f + 1] ? soup.offsets[f] : c + 1;
    // The stars are allocated last and freed first: on a heap that keeps freed memory (as
    // skeletonize's), their block is then free at the top, where the mesh's arrays go next.
    m_twin.assign(m, none);
    std::vector<std::uint32_t> row(n + 1, 0);
    for(std::uint32_t i : soup.corners)
      ++row[i + 1];
    for(std::size_t v = 0; v < n; ++v)
      row[v + 1] += row[v];
    const std::vector<Star_corner> stars = scattered_into_stars(soup, row);
    for(std::size_t v = 0; v < n; ++v)
      read_star(stars.data() + row[v], row[v + 1] - row[v]);
  }

  std::uint32_t source(std::size_t c) const { return m_soup.corners[c]; }
  std::uint32_t target(std::size_t c) const { return m_soup.corners[m_next[c]]; }
  // The next corner of the polygon of `c`.
  std::uint32_t next(std::size_t c) const { return m_next[c]; }
  // The corner whose edge is the reverse of that of `c`, or `none`.
  std::uint32_t twin(std::size_t c) const { return m_twin[c]; }
  // Whether two corners have the same edge (the same source and target).
  bool has_duplicated_edge() const { return m_duplicated_edge; }
  // Whether the polygons around each point form one fan (meaningful without duplicated
  // edges): turning around point v takes corner c (edge v -> w) to the corner after the
  // twin w -> v; the turn from the one corner whose incoming edge has no twin (or from any
  // corner of v, when there is none) must visit every corner of v.
  bool has_one_fan_per_point() const { return m_one_fan_per_point; }

private:
  // A corner at a point v, in v's star: the points after and before v in its polygon, the
  // corner and the corner before it (whose edge ends at v).
  struct Star_corner
  {
    std::uint32_t after, before, corner, corner_before;
  };

  // The corners of the soup as the stars of its points: point v's star is
  // stars[row[v]] ... stars[row[v + 1] - 1].
  std::vector<Star_corner> scattered_into_stars(const Indexed_soup& soup, const std::vector<std::uint32_t>& row)
  {
    std::vector<Star_corner> stars(soup.corners.size());
    std::vector<std::uint32_t> fill(row.begin(), row.end() - 1);
    for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
      for(std::uint32_t c = soup.offsets[f], before = soup.offsets[f + 1] - 1; c < soup.offsets[f + 1]; before = c++)
        stars[fill[soup.corners[c]]++] = {soup.corners[m_next[c]], soup.corners[before], c, before};
    return stars;
  }

  // The index in `star` of the corner whose `after` (or `before`) is `point`, or k. Stars
  // are small (six corners on a regular triangle mesh), so a scan; a large star (the apex of
  // a cone of many triangles) is sorted once and searched.
  template <typename Key>
  static std::uint32_t find(const Star_corner* star, std::uint32_t k, const std::vector<std::uint32_t>& sorted,
                            std::uint32_t point, Key key)
  {
    if(sorted.empty())
    {
      for(std::uint32_t i = 0; i < k; ++i)
        if(star[i].*key == point)
          return i;
      return k;
    }
    const auto found = std::lower_bound(sorted.begin(), sorted.end(), point,
                                        [&](std::uint32_t i, std::uint32_t p) { return star[i].*key < p; });
    return found != sorted.end() && star[*found].*key == point ? *found : k;
  }

  void read_star(const Star_corner* star, std::uint32_t k)
  {
    if(k == 0)
      return;
    constexpr std::uint32_t largest_scanned_star = 16;
    std::vector<std::uint32_t>& by_after = m_by_after;
    std::vector<std::uint32_t>& by_before = m_by_before;
    by_after.clear();
    by_before.clear();
    if(k > largest_scanned_star)
    {
      by_after.resize(k);
      std::iota(by_after.begin(), by_after.end(), 0u);
      by_before = by_after;
      std::sort(by_after.begin(), by_after.end(),
                [&](std::uint32_t a, std::uint32_t b) { return star[a].after < star[b].after; });
      std::sort(by_before.begin(), by_before.end(),
                [&](std::uint32_t a, std::uint32_t b) { return star[a].before < star[b].before; });
    }
    // Twins, and the start of an open fan: a corner whose incoming edge has no twin.
    std::uint32_t start = 0, fan_starts = 0;
    for(std::uint32_t i = 0; i < k; ++i)
    {
      if(k <= largest_scanned_star)
        for(std::uint32_t j = i + 1; j < k; ++j)
          m_duplicated_edge = m_duplicated_edge || star[j].after == star[i].after;
      else if(i + 1 < k)
        m_duplicated_edge = m_duplicated_edge || star[by_after[i]].after == star[by_after[i + 1]].after;
      const std::uint32_t back = find(star, k, by_before, star[i].after, &Star_corner::before);
      if(back != k)
        m_twin[star[i].corner] = star[back].corner_before;
      if(find(star, k, by_after, star[i].before, &Star_corner::after) == k)
      {
        ++fan_starts;
        start = i;
      }
    }
    if(fan_starts > 1)
    {
      m_one_fan_per_point = false;
      return;
    }
    std::uint32_t visited = 1;
    for(std::uint32_t i = start;;)
    {
      const std::uint32_t turned = find(star, k, by_before, star[i].after, &Star_corner::before);
      if(turned == k || turned == start)
        break;
      i = turned;
      if(++visited > k)
        break;
    }
    m_one_fan_per_point = m_one_fan_per_point && visited == k;
  }

  const Indexed_soup& m_soup;
  std::vector<std::uint32_t> m_next;
  std::vector<std::uint32_t> m_twin;
  bool m_duplicated_edge = false;
  bool m_one_fan_per_point = true;
  std::vector<std::uint32_t> m_by_after, m_by_before; // a large star's corners, sorted
};

// Whether the soup is an oriented manifold polygon mesh as
// CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh() defines it: every
// polygon has three corners or more and no point twice, no directed edge is used twice,
// and the polygons around each point form one fan. O(corners) time and memory, for a
// bounded polygon size and point degree.
inline bool is_oriented_manifold(const Indexed_soup& soup, const Directed_edge_table& edges)
{
  for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
  {
    if(soup.polygon_size(f) < 3)
      return false;
    for(std::size_t a = soup.offsets[f]; a < soup.offsets[f + 1]; ++a)
      for(std::size_t b = a + 1; b < soup.offsets[f + 1]; ++b)
        if(soup.corners[a] == soup.corners[b])
          return false;
  }
  return !edges.has_duplicated_edge() && edges.has_one_fan_per_point();
}

// Builds `mesh` (cleared first) from a soup that is_oriented_manifold() accepts: point i
// becomes vertex i, polygon f face f, and the edges are created in the order and with the
// orientation that CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh() gives
// them (the first polygon along an edge holds its first halfedge; a vertex on the border
// keeps its incoming border halfedge), with each edge's twin taken from the table instead
// of searched in the mesh. The edges are created first, so that the mesh is then linked
// in one pass over the corners. O(corners) time.
template <typename PolygonMesh, typename VertexPointMap>
void build_mesh_from_manifold_soup(const Indexed_soup& soup, const Directed_edge_table& edges,
                                   PolygonMesh& mesh, VertexPointMap vpm)
{
  using Graph_traits = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  using face_descriptor = typename Graph_traits::face_descriptor;
  using halfedge_descriptor = typename Graph_traits::halfedge_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  const std::uint32_t none = Directed_edge_table::none;

  clear(mesh);
  reserve(mesh, static_cast<typename Graph_traits::vertices_size_type>(soup.points.size()),
          static_cast<typename Graph_traits::edges_size_type>(soup.corners.size() / 2 + 1),
          static_cast<typename Graph_traits::faces_size_type>(soup.number_of_polygons()));
  std::vector<vertex_descriptor> vertex(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i)
  {
    vertex[i] = add_vertex(mesh);
    put(vpm, vertex[i], Point(soup.points[i][0], soup.points[i][1], soup.points[i][2]));
  }
  // The halfedge of each corner, created with its edge at the first polygon along the edge;
  // the twin's halfedge is written then, so that no corner reads back an earlier one.
  std::vector<halfedge_descriptor> halfedge_of(soup.corners.size());
  for(std::uint32_t c = 0; c < soup.corners.size(); ++c)
  {
    const std::uint32_t twin = edges.twin(c);
    if(twin != none && twin < c)
      continue;
    halfedge_of[c] = halfedge(add_edge(mesh), mesh);
    if(twin != none)
      halfedge_of[twin] = opposite(halfedge_of[c], mesh);
  }
  std::vector<halfedge_descriptor> border_out(soup.points.size());
  for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
  {
    const face_descriptor face = add_face(mesh);
    for(std::uint32_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c)
    {
      const halfedge_descriptor h = halfedge_of[c];
      set_target(h, vertex[edges.target(c)], mesh);
      set_face(h, face, mesh);
      set_next(h, halfedge_of[edges.next(c)], mesh);
      set_halfedge(vertex[edges.target(c)], h, mesh);
      if(edges.twin(c) == none) // the opposite halfedge is on the border
      {
        set_target(opposite(h, mesh), vertex[edges.source(c)], mesh);
        set_face(opposite(h, mesh), Graph_traits::null_face(), mesh);
        border_out[edges.target(c)] = opposite(h, mesh);
      }
    }
    set_halfedge(face, halfedge_of[soup.offsets[f + 1] - 1], mesh);
  }
  // A border halfedge b leads from the target of its corner's edge to the source; the
  // border goes on with the one border halfedge that leaves target(b).
  for(std::uint32_t c = 0; c < soup.corners.size(); ++c)
    if(edges.twin(c) == none)
    {
      const halfedge_descriptor b = opposite(halfedge_of[c], mesh);
      set_next(b, border_out[edges.source(c)], mesh);
      set_halfedge(vertex[edges.source(c)], b, mesh);
    }
}

} // namespace internal
} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_INTERNAL_INDEXED_SOUP_H
