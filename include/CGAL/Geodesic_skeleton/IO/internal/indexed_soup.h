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

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
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

// The directed edges of a soup and their twins. A directed edge is named by its corner:
// corner c leads from point corners[c] to the point of the next corner of its polygon;
// its twin is the corner whose edge leads back, or `none`.
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
      for(std::size_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c)
        m_next[c] = std::uint32_t(c + 1 == soup.offsets[f + 1] ? soup.offsets[f] : c + 1);
    // The outgoing edges of each point, with their targets side by side (compressed rows),
    // so that finding an edge scans a few contiguous entries.
    std::vector<std::uint32_t> row(n + 1, 0);
    for(std::uint32_t i : soup.corners)
      ++row[i + 1];
    for(std::size_t v = 0; v < n; ++v)
      row[v + 1] += row[v];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out(m); // (target, corner)
    {
      std::vector<std::uint32_t> fill(row.begin(), row.end() - 1);
      for(std::size_t c = 0; c < m; ++c)
        out[fill[soup.corners[c]]++] = {target(c), std::uint32_t(c)};
    }
    m_twin.assign(m, none);
    m_duplicated_edge = false;
    for(std::size_t v = 0; v < n; ++v)
      for(std::uint32_t k = row[v]; k < row[v + 1]; ++k)
      {
        const auto [t, c] = out[k];
        for(std::uint32_t j = k + 1; j < row[v + 1]; ++j)
          m_duplicated_edge = m_duplicated_edge || out[j].first == t;
        for(std::uint32_t j = row[t]; j < row[t + 1]; ++j)
          if(out[j].first == v)
            m_twin[c] = out[j].second;
      }
  }

  std::uint32_t source(std::size_t c) const { return m_soup.corners[c]; }
  std::uint32_t target(std::size_t c) const { return m_soup.corners[m_next[c]]; }
  // The next corner of the polygon of `c`.
  std::uint32_t next(std::size_t c) const { return m_next[c]; }
  // The corner whose edge is the reverse of that of `c`, or `none`.
  std::uint32_t twin(std::size_t c) const { return m_twin[c]; }
  // Whether two corners have the same edge (the same source and target).
  bool has_duplicated_edge() const { return m_duplicated_edge; }

private:
  const Indexed_soup& m_soup;
  std::vector<std::uint32_t> m_next;
  std::vector<std::uint32_t> m_twin;
  bool m_duplicated_edge = false;
};

// Whether the polygons around each point form one fan. Turning around point v takes
// corner c (edge v -> w) to the corner after the twin w -> v in its polygon. A fan that is
// not closed starts at the one corner whose incoming edge u -> v has no twin. The polygons
// around v form one fan when v has at most one such start and the turn from it (or from
// any corner of v, when there is none) visits every corner of v. O(corners).
inline bool has_one_fan_per_point(const Indexed_soup& soup, const Directed_edge_table& edges)
{
  const std::uint32_t none = Directed_edge_table::none;
  const std::size_t n = soup.points.size(), m = soup.corners.size();
  std::vector<std::uint32_t> corners_of(n, 0), start(n, none);
  std::vector<std::uint8_t> fan_starts(n, 0);
  for(std::uint32_t c = 0; c < m; ++c)
  {
    const std::uint32_t v = soup.corners[c];
    ++corners_of[v];
    if(start[v] == none)
      start[v] = c;
  }
  for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
    for(std::size_t c = soup.offsets[f], before = soup.offsets[f + 1] - 1; c < soup.offsets[f + 1]; before = c++)
      if(edges.twin(before) == none)
      {
        const std::uint32_t v = soup.corners[c];
        if(++fan_starts[v] > 1)
          return false;
        start[v] = std::uint32_t(c);
      }
  for(std::uint32_t v = 0; v < n; ++v)
  {
    if(corners_of[v] == 0)
      continue;
    std::uint32_t visited = 1;
    for(std::uint32_t c = start[v];;)
    {
      const std::uint32_t twin = edges.twin(c);
      if(twin == none || edges.next(twin) == start[v])
        break;
      c = edges.next(twin);
      if(++visited > corners_of[v])
        return false;
    }
    if(visited != corners_of[v])
      return false;
  }
  return true;
}

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
  return !edges.has_duplicated_edge() && has_one_fan_per_point(soup, edges);
}

// Builds `mesh` (cleared first) from a soup that is_oriented_manifold() accepts: point i
// becomes vertex i, polygon f face f, and the edges are created in the order and with the
// orientation that CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh() gives
// them (the first polygon along an edge holds its first halfedge; a vertex on the border
// keeps its incoming border halfedge), with each edge's twin taken from the table instead
// of searched in the mesh. O(corners) time.
template <typename PolygonMesh, typename VertexPointMap>
void build_mesh_from_manifold_soup(const Indexed_soup& soup, const Directed_edge_table& edges,
                                   PolygonMesh& mesh, VertexPointMap vpm)
{
  using Graph_traits = boost::graph_traits<PolygonMesh>;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
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
  // The halfedge of each corner (its edge), created at the first polygon along the edge.
  std::vector<halfedge_descriptor> halfedge_of(soup.corners.size());
  std::vector<halfedge_descriptor> border_out(soup.points.size());
  for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
  {
    const auto face = add_face(mesh);
    for(std::size_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c)
    {
      const std::uint32_t twin = edges.twin(c);
      if(twin != none && twin < c)
        halfedge_of[c] = opposite(halfedge_of[twin], mesh);
      else
      {
        const halfedge_descriptor h = halfedge(add_edge(mesh), mesh);
        set_target(h, vertex[edges.target(c)], mesh);
        set_target(opposite(h, mesh), vertex[edges.source(c)], mesh);
        set_face(opposite(h, mesh), Graph_traits::null_face(), mesh);
        halfedge_of[c] = h;
        if(twin == none) // the opposite halfedge is on the border
          border_out[edges.target(c)] = opposite(h, mesh);
      }
      set_face(halfedge_of[c], face, mesh);
      set_halfedge(vertex[edges.target(c)], halfedge_of[c], mesh);
    }
    for(std::size_t c = soup.offsets[f]; c < soup.offsets[f + 1]; ++c)
      set_next(halfedge_of[c], halfedge_of[edges.next(c)], mesh);
    set_halfedge(face, halfedge_of[soup.offsets[f + 1] - 1], mesh);
  }
  // A border halfedge b leads from the target of its corner's edge to the source; the
  // border goes on with the one border halfedge that leaves target(b).
  for(std::size_t c = 0; c < soup.corners.size(); ++c)
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
