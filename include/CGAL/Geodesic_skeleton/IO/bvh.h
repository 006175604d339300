// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_BVH_H
#define CGAL_GEODESIC_SKELETON_IO_BVH_H

/// \file IO/bvh.h
/// Writes a control skeleton as a BVH (Biovision hierarchy) file with a one-frame rest pose.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/split_into_bones/joint_tree.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <CGAL/number_utils.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

template <typename Point>
struct Bvh_writer
{
  const Control_skeleton<Point>& skeleton;
  std::ostream& os;
  Geodesic_skeleton::internal::Joint_tree tree;
  std::size_t written = 0; // joints written so far

  static std::string joint_name(std::size_t j, Joint_kind kind)
  {
    return to_string(kind) + "_" + std::to_string(j);
  }
  std::array<double, 3> position(std::size_t j) const
  {
    const Point& p = skeleton[j].point;
    return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
  }
  void indent(int depth) { os << std::string(2 * static_cast<std::size_t>(depth), ' '); }
  void offset(int depth, const std::array<double, 3>& d)
  {
    indent(depth);
    os << "OFFSET " << d[0] << ' ' << d[1] << ' ' << d[2] << '\n';
  }

  // A leaf joint gets an End Site one MAT radius further along its bone: the tip of the
  // limb's flesh, and a non-zero last bone for tools that drop zero-length bones.
  std::array<double, 3> end_site(std::size_t j) const
  {
    std::array<double, 3> d{0, 0, 0};
    if(tree.incoming[j] < 0)
      return {0, std::max(skeleton[j].radius, 1e-6), 0};
    const auto p = position(j), q = position(parent_joint(j, skeleton));
    const double length = Geodesic_skeleton::internal::norm3(Geodesic_skeleton::internal::sub(p, q));
    const double extent = std::max(skeleton[j].radius, 1e-3 * length);
    for(int c = 0; c < 3; ++c)
      d[c] = length > 0 ? (p[c] - q[c]) / length * extent : 0.0;
    if(length == 0)
      d[1] = extent;
    return d;
  }

  void write_joint(std::size_t j, int depth)
  {
    const bool root = tree.incoming[j] < 0;
    ++written;
    indent(depth);
    os << (root ? "ROOT " : "JOINT ") << joint_name(j, skeleton[j].kind) << '\n';
    indent(depth);
    os << "{\n";
    if(root)
    {
      offset(depth + 1, position(j));
      indent(depth + 1);
      os << "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
    }
    else
    {
      const auto p = position(j), q = position(parent_joint(j, skeleton));
      offset(depth + 1, {p[0] - q[0], p[1] - q[1], p[2] - q[2]});
      indent(depth + 1);
      os << "CHANNELS 3 Zrotation Xrotation Yrotation\n";
    }
    for(std::size_t c : tree.children[j])
      write_joint(c, depth + 1);
    if(tree.children[j].empty())
    {
      indent(depth + 1);
      os << "End Site\n";
      indent(depth + 1);
      os << "{\n";
      offset(depth + 2, end_site(j));
      indent(depth + 1);
      os << "}\n";
    }
    indent(depth);
    os << "}\n";
  }
};

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Writes `skeleton` to `os` in the BVH format: the hierarchy of joints with their offsets
/// from their parents (in the mesh's units and coordinates), then a MOTION section with one
/// frame, the rest pose (every channel 0). Blender, Maya and MotionBuilder import it as an
/// armature.
///
/// A BVH file holds one hierarchy: with several trees (a mesh of several parts) only the
/// tree of root `skeleton[boost::graph_bundle].roots[tree]` is written. Joints are named `<kind>_<index>` (for
/// example `root_0`, `junction_3`, `end_7`). The root has 6 channels (position, then
/// rotation in Z, X, Y order), every other joint 3 (rotation). A leaf joint ends with an
/// End Site one MAT radius further along its bone. Bones cut to break cycles are not
/// written.
///
/// \param os the output stream (its precision is raised to 9 significant digits).
/// \param skeleton a control skeleton, from `split_into_bones()`.
/// \param tree which tree to write, an index into the roots (default 0).
/// \returns `os`.
/// \throws std::invalid_argument when the skeleton is empty, `tree` is out of range, or the
///         skeleton is not a forest.
///
/// \b Complexity: O(J) for J joints.
template <typename Point>
std::ostream& write_BVH(std::ostream& os, const Control_skeleton<Point>& skeleton, std::size_t tree = 0)
{
  const std::vector<std::size_t>& roots = skeleton[boost::graph_bundle].roots;
  if(num_vertices(skeleton) == 0 || tree >= roots.size())
    throw std::invalid_argument("write_BVH: the control skeleton has no tree " + std::to_string(tree));
  internal::Bvh_writer<Point> writer{skeleton, os, Geodesic_skeleton::internal::joint_tree(skeleton, "write_BVH")};

  const auto old_precision = os.precision(9);
  os << "HIERARCHY\n";
  const std::size_t root = roots[tree];
  writer.write_joint(root, 0);

  os << "MOTION\nFrames: 1\nFrame Time: 0.0333333\n";
  const std::size_t channels = 6 + 3 * (writer.written - 1);
  for(std::size_t c = 0; c < channels; ++c)
    os << (c == 0 ? "" : " ") << 0;
  os << '\n';
  os.precision(old_precision);
  return os;
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_BVH_H
