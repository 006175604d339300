// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_JOINT_TREE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_JOINT_TREE_H

// The trees of a control skeleton's joints, read from their `parent` fields alone (a
// skeleton filled by hand or read from a file may list its joints in any order), with the
// checks that they are trees.

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
};

// Throws std::invalid_argument "<caller>: ..." when a parent does not exist or the parents
// make a cycle.
template <typename Point>
Joint_tree joint_tree(const Control_skeleton<Point>& skeleton, const std::string& caller)
{
  const std::size_t n = skeleton.joints.size();
  Joint_tree tree;
  tree.children.resize(n);
  for(std::size_t j = 0; j < n; ++j)
  {
    const int parent = skeleton.joints[j].parent;
    if(parent == -1)
      tree.roots.push_back(j);
    else if(parent < 0 || std::size_t(parent) >= n || std::size_t(parent) == j)
      throw std::invalid_argument(caller + ": joint " + std::to_string(j) + " has parent " + std::to_string(parent) +
                                  (std::size_t(parent) == j ? ", itself" : ", which does not exist") +
                                  " (a root has parent -1)");
    else
      tree.children[std::size_t(parent)].push_back(j);
  }
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
      if(skeleton.joints[k].parent < 0)
        break;
      k = std::size_t(skeleton.joints[k].parent);
    }
    if(state[k] == 1 && skeleton.joints[k].parent >= 0)
      throw std::invalid_argument(caller + ": the joints' parents make a cycle through joint " + std::to_string(k));
    for(std::size_t q : path)
      state[q] = 2;
  }
  return tree;
}

// The bone that leads to each joint (-1 for a root), once the bones and the parents are
// checked to agree: every bone goes from its child's parent joint, and every joint with a
// parent has exactly one bone leading to it. Throws std::invalid_argument "<caller>: ..."
// otherwise, or when a bone refers to a joint that does not exist.
template <typename Point>
std::vector<long> bone_to_each_joint(const Control_skeleton<Point>& skeleton, const std::string& caller)
{
  const std::size_t joints = skeleton.joints.size();
  std::vector<long> incoming(joints, -1);
  for(std::size_t b = 0; b < skeleton.bones.size(); ++b)
  {
    const Control_bone<Point>& bone = skeleton.bones[b];
    auto fail = [&](const std::string& problem) {
      throw std::invalid_argument(caller + ": bone " + std::to_string(b) + " (" + std::to_string(bone.parent) +
                                  " -> " + std::to_string(bone.child) + ") " + problem);
    };
    if(bone.parent >= joints || bone.child >= joints)
      fail("refers to a joint that does not exist");
    if(skeleton.joints[bone.child].parent != long(bone.parent))
      fail("does not match the parent of joint " + std::to_string(bone.child) + " (" +
           std::to_string(skeleton.joints[bone.child].parent) + ")");
    if(incoming[bone.child] >= 0)
      throw std::invalid_argument(caller + ": two bones lead to joint " + std::to_string(bone.child));
    incoming[bone.child] = long(b);
  }
  for(std::size_t j = 0; j < joints; ++j)
    if(skeleton.joints[j].parent >= 0 && incoming[j] < 0)
      throw std::invalid_argument(caller + ": no bone leads to joint " + std::to_string(j) + " from its parent " +
                                  std::to_string(skeleton.joints[j].parent));
  return incoming;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_JOINT_TREE_H
