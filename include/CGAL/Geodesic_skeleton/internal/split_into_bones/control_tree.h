// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CONTROL_TREE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CONTROL_TREE_H

// Turns a graph of joints and bones into rooted trees: a root per component (the most
// central junction), a shortest-path tree from it, the bones off the tree cut.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A bone of the joint graph before rooting: its points run from joint `first` to joint
// `last`, and `index` is its rank among the bones (the order cut bones are listed in).
template <typename Point>
struct Joint_graph_bone : Control_bone<Point>
{
  std::size_t first = 0;
  std::size_t last = 0;
  std::size_t index = 0;
};

// A joint graph before rooting: joints (kind junction/bend/end) and undirected bones.
template <typename Point>
using Joint_graph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, Control_joint<Point>, Joint_graph_bone<Point>>;

template <typename Point>
void add_bone(std::size_t first, std::size_t last, Control_bone<Point> bone, Joint_graph<Point>& g)
{
  Joint_graph_bone<Point> b;
  static_cast<Control_bone<Point>&>(b) = std::move(bone);
  b.first = first;
  b.last = last;
  b.index = num_edges(g);
  add_edge(first, last, std::move(b), g);
}

template <typename Point>
struct Shortest_paths
{
  using Bone = typename boost::graph_traits<Joint_graph<Point>>::edge_descriptor;
  std::vector<double> distance;
  std::vector<Bone> via_bone; // the bone to the predecessor; meaningless at the source
};

// Distances along the bones from joint `source`, and the shortest-path tree.
template <typename Point>
Shortest_paths<Point> joint_distances(const Joint_graph<Point>& g, std::size_t source)
{
  using Bone = typename Shortest_paths<Point>::Bone;
  const std::size_t n = num_vertices(g);
  Shortest_paths<Point> sp{std::vector<double>(n), std::vector<Bone>(n)};
  const auto bone_length = boost::make_function_property_map<Bone>([&g](const Bone& e) { return g[e].length; });
  boost::dijkstra_shortest_paths(
      g, source,
      boost::weight_map(bone_length)
          .distance_map(boost::make_iterator_property_map(sp.distance.begin(), get(boost::vertex_index, g)))
          .distance_inf(std::numeric_limits<double>::infinity())
          .visitor(boost::make_dijkstra_visitor(boost::record_edge_predecessors(
              boost::make_iterator_property_map(sp.via_bone.begin(), get(boost::vertex_index, g)),
              boost::on_edge_relaxed()))));
  return sp;
}

// Roots the joint graph: for each connected component, the root is the junction whose
// farthest joint (along the bones) is nearest, i.e. the centre of the component's graph
// (ties: larger radius, then smaller index); a component without junction takes its
// central joint of any kind. The tree is the shortest-path tree from the root; bones off
// it close cycles and are cut. Joints are renumbered so that parents come first, and
// bones are added in the order of their child joints.
template <typename Point>
Control_skeleton<Point> root_joint_graph(const Joint_graph<Point>& g)
{
  const std::size_t n = num_vertices(g);
  std::vector<std::size_t> component(n);
  const std::size_t components = n == 0 ? 0 : boost::connected_components(
      g, boost::make_iterator_property_map(component.begin(), get(boost::vertex_index, g)));
  std::vector<std::vector<std::size_t>> members(components);
  for(std::size_t j = 0; j < n; ++j)
    members[component[j]].push_back(j);

  Control_skeleton<Point> out;
  std::vector<bool> in_tree(num_edges(g), false);
  for(const std::vector<std::size_t>& part : members)
  {
    const bool has_junction = std::any_of(part.begin(), part.end(), [&](std::size_t j) {
      return g[j].kind == Joint_kind::junction;
    });
    std::size_t root = part.front();
    double best = std::numeric_limits<double>::infinity();
    Shortest_paths<Point> root_paths;
    for(std::size_t j : part)
    {
      if(has_junction && g[j].kind != Joint_kind::junction)
        continue;
      Shortest_paths<Point> sp = joint_distances(g, j);
      double eccentricity = 0;
      for(std::size_t k : part)
        eccentricity = std::max(eccentricity, sp.distance[k]);
      // Equal up to rounding (relative, so that it holds at any scale): the thicker wins.
      const double rounding = 1e-9 * eccentricity;
      const bool better = eccentricity < best - rounding ||
                          (eccentricity <= best + rounding && g[j].radius > g[root].radius);
      if(better)
      {
        best = eccentricity;
        root = j;
        root_paths = std::move(sp);
      }
    }

    // Breadth-first order from the root along tree bones, so that parents come first.
    auto parent_in_tree = [&](std::size_t j) {
      const auto& bone = g[root_paths.via_bone[j]];
      return bone.first == j ? bone.last : bone.first;
    };
    std::vector<std::size_t> order{root};
    std::vector<std::vector<std::size_t>> tree_children(n);
    for(std::size_t j : part)
      if(j != root)
      {
        tree_children[parent_in_tree(j)].push_back(j);
        in_tree[g[root_paths.via_bone[j]].index] = true;
      }
    for(std::size_t k = 0; k < order.size(); ++k)
      for(std::size_t c : tree_children[order[k]])
        order.push_back(c);

    std::vector<std::size_t> new_index(n);
    for(std::size_t j : order)
    {
      Control_joint<Point> joint = g[j];
      if(j == root)
        joint.kind = Joint_kind::root;
      new_index[j] = add_vertex(joint, out);
      if(j == root)
      {
        out[boost::graph_bundle].roots.push_back(new_index[j]);
        continue;
      }
      const Joint_graph_bone<Point>& bone = g[root_paths.via_bone[j]];
      Control_bone<Point> oriented = bone;
      if(bone.first == j) // orient the bone from parent to child
        std::reverse(oriented.points.begin(), oriented.points.end());
      add_edge(new_index[parent_in_tree(j)], new_index[j], std::move(oriented), out);
    }
    for(const auto e : boost::make_iterator_range(edges(g)))
    {
      const Joint_graph_bone<Point>& bone = g[e];
      if(in_tree[bone.index] || component[bone.first] != component[root])
        continue;
      Control_cut_bone<Point> cut;
      static_cast<Control_bone<Point>&>(cut) = bone;
      cut.source = new_index[bone.first];
      cut.target = new_index[bone.last];
      out[boost::graph_bundle].cut_bones.push_back(std::move(cut));
    }
  }
  return out;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CONTROL_TREE_H
