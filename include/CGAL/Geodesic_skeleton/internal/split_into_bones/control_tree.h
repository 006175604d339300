// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CONTROL_TREE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CONTROL_TREE_H

// Turns a graph of joints and bones into rooted trees: a root per component (the most
// central junction), a shortest-path tree from it, the bones off the tree cut.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A joint graph before rooting: joints (kind junction/bend/end) and undirected bones.
template <typename Point>
struct Joint_graph
{
  std::vector<Control_joint<Point>> joints;
  std::vector<Control_bone<Point>> bones; // parent/child are just the two ends here
};

struct Shortest_paths
{
  std::vector<double> distance;
  std::vector<long> via_bone; // bone to the predecessor, -1 at the source or unreached
};

template <typename Point>
Shortest_paths joint_distances(const Joint_graph<Point>& g,
                               const std::vector<std::vector<std::size_t>>& bones_at,
                               std::size_t source)
{
  Shortest_paths sp{std::vector<double>(g.joints.size(), std::numeric_limits<double>::infinity()),
                    std::vector<long>(g.joints.size(), -1)};
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  sp.distance[source] = 0;
  queue.emplace(0.0, source);
  while(!queue.empty())
  {
    const auto [d, j] = queue.top();
    queue.pop();
    if(d > sp.distance[j])
      continue;
    for(std::size_t b : bones_at[j])
    {
      const Control_bone<Point>& bone = g.bones[b];
      const std::size_t other = bone.parent == j ? bone.child : bone.parent;
      const double nd = d + bone.length;
      if(nd < sp.distance[other])
      {
        sp.distance[other] = nd;
        sp.via_bone[other] = static_cast<long>(b);
        queue.emplace(nd, other);
      }
    }
  }
  return sp;
}

// Roots the joint graph: for each connected component, the root is the junction whose
// farthest joint (along the bones) is nearest, i.e. the centre of the component's graph
// (ties: larger radius, then smaller index); a component without junction takes its
// central joint of any kind. The tree is the shortest-path tree from the root; bones off
// it close cycles and are cut. Joints are renumbered so that parents come first.
template <typename Point>
Control_skeleton<Point> root_joint_graph(const Joint_graph<Point>& g)
{
  const std::size_t n = g.joints.size();
  std::vector<std::vector<std::size_t>> bones_at(n);
  for(std::size_t b = 0; b < g.bones.size(); ++b)
  {
    bones_at[g.bones[b].parent].push_back(b);
    if(g.bones[b].child != g.bones[b].parent)
      bones_at[g.bones[b].child].push_back(b);
  }

  // Components, and the eccentricity of the candidate roots of each.
  std::vector<long> component(n, -1);
  std::vector<std::vector<std::size_t>> members;
  for(std::size_t s = 0; s < n; ++s)
  {
    if(component[s] >= 0)
      continue;
    const Shortest_paths sp = joint_distances(g, bones_at, s);
    members.emplace_back();
    for(std::size_t j = 0; j < n; ++j)
      if(sp.distance[j] < std::numeric_limits<double>::infinity())
      {
        component[j] = static_cast<long>(members.size() - 1);
        members.back().push_back(j);
      }
  }

  Control_skeleton<Point> out;
  std::vector<bool> in_tree(g.bones.size(), false);
  for(const std::vector<std::size_t>& part : members)
  {
    const bool has_junction = std::any_of(part.begin(), part.end(), [&](std::size_t j) {
      return g.joints[j].kind == Joint_kind::junction;
    });
    std::size_t root = part.front();
    double best = std::numeric_limits<double>::infinity();
    Shortest_paths root_paths;
    for(std::size_t j : part)
    {
      if(has_junction && g.joints[j].kind != Joint_kind::junction)
        continue;
      Shortest_paths sp = joint_distances(g, bones_at, j);
      double eccentricity = 0;
      for(std::size_t k : part)
        eccentricity = std::max(eccentricity, sp.distance[k]);
      const bool better = eccentricity < best - 1e-12 ||
                          (eccentricity <= best + 1e-12 && g.joints[j].radius > g.joints[root].radius);
      if(better)
      {
        best = eccentricity;
        root = j;
        root_paths = std::move(sp);
      }
    }

    // Breadth-first order from the root along tree bones, so that parents come first.
    std::vector<long> new_index(n, -1);
    std::vector<std::size_t> order{root};
    std::vector<std::vector<std::size_t>> tree_children(n);
    for(std::size_t j : part)
      if(root_paths.via_bone[j] >= 0)
      {
        const Control_bone<Point>& bone = g.bones[static_cast<std::size_t>(root_paths.via_bone[j])];
        tree_children[bone.parent == j ? bone.child : bone.parent].push_back(j);
        in_tree[static_cast<std::size_t>(root_paths.via_bone[j])] = true;
      }
    for(std::size_t k = 0; k < order.size(); ++k)
      for(std::size_t c : tree_children[order[k]])
        order.push_back(c);

    const std::size_t first = out.joints.size();
    for(std::size_t k = 0; k < order.size(); ++k)
      new_index[order[k]] = static_cast<long>(first + k);
    out.roots.push_back(first);
    for(std::size_t j : order)
    {
      Control_joint<Point> joint = g.joints[j];
      if(j == root)
      {
        joint.kind = Joint_kind::root;
        joint.parent = -1;
        out.joints.push_back(joint);
        continue;
      }
      Control_bone<Point> bone = g.bones[static_cast<std::size_t>(root_paths.via_bone[j])];
      const std::size_t parent = bone.parent == j ? bone.child : bone.parent;
      if(bone.parent == j) // orient the bone from parent to child
        std::reverse(bone.points.begin(), bone.points.end());
      bone.parent = static_cast<std::size_t>(new_index[parent]);
      bone.child = static_cast<std::size_t>(new_index[j]);
      joint.parent = static_cast<int>(bone.parent);
      out.joints.push_back(joint);
      out.bones.push_back(std::move(bone));
    }
    for(std::size_t b = 0; b < g.bones.size(); ++b)
    {
      const Control_bone<Point>& bone = g.bones[b];
      if(in_tree[b] || component[bone.parent] != component[root])
        continue;
      Control_bone<Point> cut = bone;
      cut.parent = static_cast<std::size_t>(new_index[bone.parent]);
      cut.child = static_cast<std::size_t>(new_index[bone.child]);
      out.cut_bones.push_back(std::move(cut));
    }
  }
  return out;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CONTROL_TREE_H
