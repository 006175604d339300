// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_OBJ_H
#define CGAL_GEODESIC_SKELETON_IO_OBJ_H

/// \file IO/obj.h
/// Writes a control skeleton as a Wavefront OBJ file of line elements.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>

#include <CGAL/number_utils.h>

#include <ostream>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {

/// \ingroup PkgGeodesicSkeletonRef
/// Writes `skeleton` as OBJ: one vertex `v x y z` per joint, in the order of
/// `skeleton.joints`, then one line element `l parent child` per bone (1-based indices),
/// then the cut bones in a group named `cut_bones`. Any OBJ viewer shows it as a wire
/// skeleton. \returns `os`. \b Complexity: O(J) for J joints.
template <typename Point>
std::ostream& write_OBJ(std::ostream& os, const Control_skeleton<Point>& skeleton)
{
  const auto old_precision = os.precision(9);
  os << "# control skeleton: " << skeleton.joints.size() << " joints, " << skeleton.bones.size()
     << " bones\n";
  for(const Control_joint<Point>& j : skeleton.joints)
    os << "v " << CGAL::to_double(j.point.x()) << ' ' << CGAL::to_double(j.point.y()) << ' '
       << CGAL::to_double(j.point.z()) << '\n';
  os << "g bones\n";
  for(const Control_bone<Point>& b : skeleton.bones)
    os << "l " << b.parent + 1 << ' ' << b.child + 1 << '\n';
  if(!skeleton.cut_bones.empty())
  {
    os << "g cut_bones\n";
    for(const Control_bone<Point>& b : skeleton.cut_bones)
      os << "l " << b.parent + 1 << ' ' << b.child + 1 << '\n';
  }
  os.precision(old_precision);
  return os;
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_OBJ_H
