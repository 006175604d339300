// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_H
#define CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_H

/// \file Control_skeleton.h
/// The animation control skeleton: a `boost::adjacency_list` forest of joints and bones.

#include <boost/graph/adjacency_list.hpp>
#include <boost/range/iterator_range.hpp>

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
/// A joint of a control skeleton: the vertex bundle of `Control_skeleton`.
/// \tparam Point a CGAL point type.
template <typename Point>
struct Control_joint
{
  Point point;                     ///< position, in the mesh's coordinates
  double radius = 0;               ///< MAT radius there (world units): the limb's thickness
  Joint_kind kind = Joint_kind::end; ///< root, junction, bend or end
  std::size_t skeleton_vertex = 0; ///< the curve-skeleton vertex the joint sits on
};

/// \ingroup PkgGeodesicSkeletonRef
/// A bone of a control skeleton, the edge bundle of `Control_skeleton`: the smoothed
/// curve-skeleton points that the edge from a parent joint to a child joint replaces.
/// \tparam Point a CGAL point type.
template <typename Point>
struct Control_bone
{
  std::vector<Point> points; ///< the curve-skeleton points from parent to child, both included
  double length = 0;         ///< arc length of `points` (world units)
};

/// \ingroup PkgGeodesicSkeletonRef
/// A bone left out of the trees of a control skeleton to break a cycle of the shape: the
/// two joints it would link and the points between them.
/// \tparam Point a CGAL point type.
template <typename Point>
struct Control_cut_bone : Control_bone<Point>
{
  std::size_t source = 0; ///< the joint at `points.front()`
  std::size_t target = 0; ///< the joint at `points.back()`
};

/// \ingroup PkgGeodesicSkeletonRef
/// The graph bundle of `Control_skeleton` (`skeleton[boost::graph_bundle]`): what is
/// not a joint or a bone of the trees.
/// \tparam Point a CGAL point type.
template <typename Point>
struct Control_skeleton_property
{
  /// The root joint of each tree, one per connected component of the curve skeleton.
  std::vector<std::size_t> roots;
  /// Bones left out to break the cycles of the shape (one per independent cycle), so that
  /// the graph stays a forest.
  std::vector<Control_cut_bone<Point>> cut_bones;
};

/// \ingroup PkgGeodesicSkeletonRef
/// A control skeleton: a `boost::adjacency_list` forest with one rooted tree of joints and
/// bones per connected component of the curve skeleton.
///
/// - A vertex is a joint (`Control_joint`, its bundle: `skeleton[j]`). Vertices are
///   numbered so that a parent comes before its children, a root first in each tree.
/// - An edge is a bone (`Control_bone`, its bundle: `skeleton[e]`), directed from the
///   parent joint (`source(e, skeleton)`) to the child joint (`target(e, skeleton)`).
///   Every joint but a root has exactly one in-edge; a root has none. Bone `b` is the
///   `b`-th edge of `edges(skeleton)`, which lists the edges in the order they were added:
///   `Bone_weights` and the file formats number bones so (see `numbered_bones()`).
/// - The graph bundle (`Control_skeleton_property`, `skeleton[boost::graph_bundle]`) holds
///   the roots and, when the shape has handles (the curve skeleton has cycles), the bones
///   left out of the trees, one per independent cycle.
///
/// Any Boost.Graph algorithm walks it, e.g. a `boost::breadth_first_search` from a root.
/// \tparam Point a CGAL point type.
template <typename Point>
using Control_skeleton = boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS, Control_joint<Point>,
                                               Control_bone<Point>, Control_skeleton_property<Point>>;

/// \ingroup PkgGeodesicSkeletonRef
/// The parent of joint `joint` in `skeleton`, or `boost::graph_traits<Control_skeleton<Point>>::null_vertex()`
/// for a root.
/// \pre `joint` is a joint of `skeleton`.
/// \b Complexity: O(1).
template <typename Point>
typename boost::graph_traits<Control_skeleton<Point>>::vertex_descriptor
parent_joint(typename boost::graph_traits<Control_skeleton<Point>>::vertex_descriptor joint,
             const Control_skeleton<Point>& skeleton)
{
  const auto in = in_edges(joint, skeleton);
  return in.first == in.second ? boost::graph_traits<Control_skeleton<Point>>::null_vertex()
                               : source(*in.first, skeleton);
}

/// \ingroup PkgGeodesicSkeletonRef
/// The bone that leads to joint `joint` from its parent.
/// \pre `joint` is a joint of `skeleton` and not a root (`in_degree(joint, skeleton) == 1`).
/// \b Complexity: O(1).
template <typename Point>
typename boost::graph_traits<Control_skeleton<Point>>::edge_descriptor
bone_to(typename boost::graph_traits<Control_skeleton<Point>>::vertex_descriptor joint,
        const Control_skeleton<Point>& skeleton)
{
  return *in_edges(joint, skeleton).first;
}

/// \ingroup PkgGeodesicSkeletonRef
/// The bones of `skeleton` by number: element `b` is bone `b`, the `b`-th edge of
/// `edges(skeleton)`.
/// \b Complexity: O(number of bones).
template <typename Point>
std::vector<typename boost::graph_traits<Control_skeleton<Point>>::edge_descriptor>
numbered_bones(const Control_skeleton<Point>& skeleton)
{
  const auto all = edges(skeleton);
  return {all.first, all.second};
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_CONTROL_SKELETON_H
