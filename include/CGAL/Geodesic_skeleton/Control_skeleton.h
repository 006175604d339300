// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_H
#define CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_H

/// \file Control_skeleton.h
/// The animation control skeleton: joints and bones forming rooted trees.

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The kind of a joint of a control skeleton.
enum class Joint_kind
{
  root,     ///< the root of a tree: the most central junction of its component
  junction, ///< where three or more branches of the curve skeleton meet
  bend,     ///< inside a branch, where the chord-to-point distance accumulation peaks
  end       ///< the tip of a limb
};

/// \ingroup PkgGeodesicSkeletonRef
/// The name of a joint kind: "root", "junction", "bend" or "end".
inline std::string to_string(Joint_kind kind)
{
  switch(kind)
  {
    case Joint_kind::root: return "root";
    case Joint_kind::junction: return "junction";
    case Joint_kind::bend: return "bend";
    case Joint_kind::end: return "end";
  }
  return "unknown";
}

/// \ingroup PkgGeodesicSkeletonRef
/// A joint of a control skeleton.
/// \tparam Point a CGAL point type.
template <typename Point>
struct Control_joint
{
  Point point;                     ///< position, in the mesh's coordinates
  double radius = 0;               ///< MAT radius there (world units): the limb's thickness
  Joint_kind kind = Joint_kind::end; ///< root, junction, bend or end
  int parent = -1;                 ///< index of the parent joint, -1 for a root
  std::size_t skeleton_vertex = 0; ///< the curve-skeleton vertex the joint sits on
};

/// \ingroup PkgGeodesicSkeletonRef
/// A bone of a control skeleton: from a parent joint to a child joint, with the smoothed
/// curve-skeleton points it replaces.
template <typename Point>
struct Control_bone
{
  std::size_t parent = 0;    ///< index of the parent joint
  std::size_t child = 0;     ///< index of the child joint
  std::vector<Point> points; ///< the curve-skeleton points from parent to child, both included
  double length = 0;         ///< arc length of `points` (world units)
};

/// \ingroup PkgGeodesicSkeletonRef
/// A control skeleton: one rooted tree of joints and bones per connected component of the
/// curve skeleton.
///
/// Joints are listed so that a parent comes before its children (a root first in each
/// tree), bones so that `bones[i]` leads to joint `bones[i].child` from its parent. When
/// the shape has handles (the curve skeleton has cycles), one bone per independent cycle
/// is left out of the tree and kept in `cut_bones`, so that the rest is a tree.
template <typename Point>
struct Control_skeleton
{
  /// The joints, parents before children.
  std::vector<Control_joint<Point>> joints;
  /// The bones of the trees, one per joint that is not a root.
  std::vector<Control_bone<Point>> bones;
  /// Bones left out to break the cycles of the shape; `parent` and `child` name the joints
  /// they would link.
  std::vector<Control_bone<Point>> cut_bones;
  /// The root joint of each tree, one per connected component.
  std::vector<std::size_t> roots;

  /// Empties the skeleton.
  void clear()
  {
    joints.clear();
    bones.clear();
    cut_bones.clear();
    roots.clear();
  }
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_H
