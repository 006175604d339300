// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_BRANCHES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_BRANCHES_H

#include <CGAL/boost/graph/split_graph_into_polylines.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A branch of a skeleton graph: the vertices from one node (a vertex of degree other than
// 2) to the next along vertices of degree 2, both nodes included; or a closed loop of
// vertices of degree 2, listed once (the first vertex is not repeated at the end).
struct Skeleton_branch
{
  std::vector<std::size_t> vertices;
  bool closed = false;
};

// Collects the polylines of CGAL::split_graph_into_polylines().
struct Polyline_collector
{
  std::vector<std::vector<std::size_t>> polylines;
  void start_new_polyline() { polylines.emplace_back(); }
  template <typename VertexDescriptor>
  void add_node(VertexDescriptor v)
  {
    polylines.back().push_back(static_cast<std::size_t>(v));
  }
  void end_polyline() {}
};

// Splits a graph with vecS vertex storage into its branches (by
// CGAL::split_graph_into_polylines(); self loops and parallel edges are ignored, isolated
// vertices give no branch). Every edge belongs to exactly one branch.
//
// Deterministic, in a fixed order and direction: the open branches first, each walked from
// its node of lower index (a loop through one node: towards the lower of its two
// neighbours on the loop), sorted by their first then their second vertex; then the closed
// loops, each starting at its vertex of lower index towards the lower of that vertex's two
// neighbours, sorted by their first vertex.
//
// Complexity: O((V + E) log V).
template <typename Graph>
std::vector<Skeleton_branch> skeleton_branches(const Graph& g)
{
  Polyline_collector collector;
  CGAL::split_graph_into_polylines(g, collector);

  auto is_node = [&](std::size_t v) { // as CGAL's function counts: self loops and parallel edges ignored
    std::vector<std::size_t> neighbours;
    for(auto w : boost::make_iterator_range(boost::adjacent_vertices(v, g)))
      if(static_cast<std::size_t>(w) != v)
        neighbours.push_back(static_cast<std::size_t>(w));
    std::sort(neighbours.begin(), neighbours.end());
    return std::unique(neighbours.begin(), neighbours.end()) - neighbours.begin() != 2;
  };
  std::vector<Skeleton_branch> open, closed;
  for(std::vector<std::size_t>& polyline : collector.polylines)
  {
    if(polyline.size() < 2)
      continue; // an isolated vertex
    Skeleton_branch branch;
    const std::size_t first = polyline.front();
    // A polyline that comes back to its start is a loop through a node, or a closed loop
    // when its start is no node.
    branch.closed = polyline.back() == first && !is_node(first);
    if(branch.closed)
    {
      polyline.pop_back();
      std::rotate(polyline.begin(), std::min_element(polyline.begin(), polyline.end()), polyline.end());
      if(polyline.back() < polyline[1])
        std::reverse(polyline.begin() + 1, polyline.end());
    }
    else if(polyline.back() < first || (polyline.back() == first && polyline[polyline.size() - 2] < polyline[1]))
      std::reverse(polyline.begin(), polyline.end());
    branch.vertices = std::move(polyline);
    (branch.closed ? closed : open).push_back(std::move(branch));
  }
  auto by_first_two = [](const Skeleton_branch& a, const Skeleton_branch& b) {
    return std::make_pair(a.vertices[0], a.vertices[1]) < std::make_pair(b.vertices[0], b.vertices[1]);
  };
  std::sort(open.begin(), open.end(), by_first_two);
  std::sort(closed.begin(), closed.end(), by_first_two);
  open.insert(open.end(), std::make_move_iterator(closed.begin()), std::make_move_iterator(closed.end()));
  return open;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_BRANCHES_H
