// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_REEB_PIECES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_REEB_PIECES_H

// The regions of a piecewise-linear field between level sets, as unions of face pieces.

#include <boost/graph/graph_traits.hpp>
#include <boost/pending/disjoint_sets.hpp>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// With the field linear on each face, the part of a face whose values fall in an interval
// is connected (a slab cut of a convex polygon): a "piece". The region of an interval is
// the union of its pieces; two pieces of one interval in faces sharing an edge are joined
// when the edge has values in the interval too. The regions' components are the nodes of
// the Reeb graph, and two pieces of one face in consecutive intervals touch along a level
// set: an arc. This follows the level sets through the faces, so a band of values thinner
// than the edges is not cut into false parts (as components of vertices would be).
struct Reeb_pieces
{
  std::vector<std::size_t> first_piece;   // by face index: id of its piece of lowest interval
  std::vector<std::size_t> first_interval; // by face index
  std::vector<std::size_t> node_of_piece;
  std::size_t nodes = 0;
  std::set<std::pair<std::size_t, std::size_t>> arcs;

  std::size_t piece(std::size_t face, std::size_t interval) const
  {
    return first_piece[face] + (interval - first_interval[face]);
  }
};

// `interval_of_vertex(v)` gives the interval of v's value; `face_index` maps the faces into
// [0, num_faces(mesh)).
template <typename FaceGraph, typename FaceIndexMap, typename IntervalOfVertex>
Reeb_pieces reeb_pieces(const FaceGraph& mesh, FaceIndexMap face_index_map,
                        const IntervalOfVertex& interval_of_vertex)
{
  Reeb_pieces r;
  const std::size_t F = static_cast<std::size_t>(num_faces(mesh));
  auto face_index = [&](auto fd) { return static_cast<std::size_t>(get(face_index_map, fd)); };
  std::vector<std::size_t> last_interval(F, 0);
  r.first_piece.assign(F, 0);
  r.first_interval.assign(F, 0);
  std::size_t pieces = 0;
  for(auto fd : faces(mesh))
  {
    const std::size_t f = face_index(fd);
    std::size_t low = std::numeric_limits<std::size_t>::max(), high = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(fd, mesh), mesh))
    {
      low = (std::min)(low, interval_of_vertex(v));
      high = (std::max)(high, interval_of_vertex(v));
    }
    r.first_piece[f] = pieces;
    r.first_interval[f] = low;
    last_interval[f] = high;
    pieces += high - low + 1;
  }

  boost::disjoint_sets_with_storage<> sets(pieces);
  for(std::size_t p = 0; p < pieces; ++p)
    sets.make_set(p);
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh), g = opposite(h, mesh);
    if(is_border(h, mesh) || is_border(g, mesh))
      continue;
    const std::size_t a = face_index(face(h, mesh)), b = face_index(face(g, mesh));
    const std::size_t i = interval_of_vertex(source(h, mesh)), j = interval_of_vertex(target(h, mesh));
    for(std::size_t k = (std::min)(i, j); k <= (std::max)(i, j); ++k)
      sets.union_set(r.piece(a, k), r.piece(b, k));
  }

  // Number the components, then the arcs between consecutive pieces of a face.
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> node_of_root(pieces, none);
  r.node_of_piece.resize(pieces);
  for(std::size_t p = 0; p < pieces; ++p)
  {
    const std::size_t root = sets.find_set(p);
    if(node_of_root[root] == none)
      node_of_root[root] = r.nodes++;
    r.node_of_piece[p] = node_of_root[root];
  }
  for(auto fd : faces(mesh))
    for(std::size_t f = face_index(fd), k = r.first_interval[f]; k < last_interval[f]; ++k)
    {
      const std::size_t a = r.node_of_piece[r.piece(f, k)], b = r.node_of_piece[r.piece(f, k + 1)];
      if(a != b)
        r.arcs.insert({(std::min)(a, b), (std::max)(a, b)});
    }
  return r;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_REEB_PIECES_H
