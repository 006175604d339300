// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_BRANCHES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_BRANCHES_H

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <set>
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

// Splits a graph with vecS vertex storage into its branches. Every edge belongs to
// exactly one branch. Deterministic: branches are found from the nodes in index order.
//
// Complexity: O((V + E) log E).
template <typename Graph>
std::vector<Skeleton_branch> skeleton_branches(const Graph& g)
{
  std::set<std::pair<std::size_t, std::size_t>> walked;
  auto edge_key = [](std::size_t a, std::size_t b) {
    return std::pair<std::size_t, std::size_t>(std::min(a, b), std::max(a, b));
  };
  auto neighbours = [&](std::size_t v) {
    std::vector<std::size_t> n;
    for(auto w : boost::make_iterator_range(boost::adjacent_vertices(v, g)))
      if(static_cast<std::size_t>(w) != v) // ignore self loops
        n.push_back(static_cast<std::size_t>(w));
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    return n;
  };
  auto is_node = [&](std::size_t v) { return neighbours(v).size() != 2; };

  // Walks from `from` through `next` along vertices of degree 2 until a node, or back to
  // `from` (a loop through a node).
  auto walk = [&](std::size_t from, std::size_t next, bool stop_at_start) {
    Skeleton_branch branch;
    branch.vertices = {from};
    std::size_t previous = from, current = next;
    walked.insert(edge_key(previous, current));
    while(true)
    {
      branch.vertices.push_back(current);
      if(is_node(current) || (stop_at_start && current == from))
        break;
      const std::vector<std::size_t> n = neighbours(current);
      const std::size_t following = n[0] == previous ? n[1] : n[0];
      if(walked.count(edge_key(current, following)) != 0)
        break; // back to the start of a loop of degree-2 vertices
      walked.insert(edge_key(current, following));
      previous = current;
      current = following;
    }
    return branch;
  };

  std::vector<Skeleton_branch> branches;
  const std::size_t n = num_vertices(g);
  for(std::size_t v = 0; v < n; ++v)
  {
    if(!is_node(v))
      continue;
    for(std::size_t w : neighbours(v))
      if(walked.count(edge_key(v, w)) == 0)
        branches.push_back(walk(v, w, true));
  }
  // What is left are loops made of vertices of degree 2 only.
  for(std::size_t v = 0; v < n; ++v)
  {
    const std::vector<std::size_t> nv = neighbours(v);
    if(nv.size() != 2 || walked.count(edge_key(v, nv[0])) != 0)
      continue;
    Skeleton_branch loop = walk(v, nv[0], true);
    loop.closed = true;
    if(loop.vertices.size() > 1 && loop.vertices.back() == loop.vertices.front())
      loop.vertices.pop_back();
    branches.push_back(std::move(loop));
  }
  return branches;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKELETON_BRANCHES_H
