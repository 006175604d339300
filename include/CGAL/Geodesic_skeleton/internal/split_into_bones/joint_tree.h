// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_JOINT_TREE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_JOINT_TREE_H

// The trees of a control skeleton, with the checks that it is a forest (a skeleton built by
// hand or read from a file may number its joints in any order, and nothing in the type
// keeps two bones from leading to one joint).

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

struct Joint_tree
{
  std::vector<std::vector<std::size_t>> children; // per joint, in increasing order
  std::vector<std::size_t> roots;                 // the joints without a parent, in increasing order
  std::vector<long> incoming;                     // per joint, the number of the bone to it; -1 for a root
};

// Throws std::invalid_argument "<caller>: ..." when a bone links a joint to itself, two
// bones lead to one joint, or the bones make a cycle.
template <typename Point>
Joint_tree joint_tree(const Control_skeleton<Point>& skeleton, const std::string& caller)
{
  const std::size_t n = num_vertices(skeleton);
  Joint_tree tree;
  tree.children.resize(n);
  tree.incoming.assign(n, -1);
  long b = 0;
  for(const auto e : boost::make_iterator_range(edges(skeleton)))
  {
    const std::size_t parent = source(e, skeleton), child = target(e, skeleton);
    if(parent == child)
      throw std::invalid_argument(caller + ": bone " + std::to_string(b) + " links joint " + std::to_string(child) +
                                  " to itself");
    if(tree.incoming[child] >= 0)
      throw std::invalid_argument(caller + ": two bones lead to joint " + std::to_string(child));
    tree.incoming[child] = b++;
  }
  for(std::size_t j = 0; j < n; ++j)
    if(tree.incoming[j] < 0)
      tree.roots.push_back(j);
    else
      tree.children[parent_joint(j, skeleton)].push_back(j);
  // Walk up from every joint; a walk that comes back to a joint of its own path is a cycle.
  std::vector<std::uint8_t> state(n, 0); // 0 not seen, 1 on the current walk, 2 reaches a root
  std::vector<std::size_t> path;
  for(std::size_t j = 0; j < n; ++j)
  {
    path.clear();
    std::size_t k = j;
    while(state[k] == 0)
    {
      state[k] = 1;
      path.push_back(k);
      if(tree.incoming[k] < 0)
        break;
      k = parent_joint(k, skeleton);
    }
    if(state[k] == 1 && tree.incoming[k] >= 0)
      throw std::invalid_argument(caller + ": the joints' parents make a cycle through joint " + std::to_string(k));
    for(std::size_t q : path)
      state[q] = 2;
  }
  return tree;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_JOINT_TREE_H
