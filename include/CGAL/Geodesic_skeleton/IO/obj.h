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
/// `vertices(skeleton)`, then one line element `l parent child` per bone (1-based indices),
/// then the cut bones in a group named `cut_bones`. Any OBJ viewer shows it as a wire
/// skeleton. \returns `os`. \b Complexity: O(J) for J joints.
template <typename Point>
std::ostream& write_OBJ(std::ostream& os, const Control_skeleton<Point>& skeleton)
{
  const auto old_precision = os.precision(9);
  os << "# control skeleton: " << num_vertices(skeleton) << " joints, " << num_edges(skeleton) << " bones\n";
  for(const auto v : boost::make_iterator_range(vertices(skeleton)))
  {
    const Point& p = skeleton[v].point;
    os << "v " << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z()) << '\n';
  }
  os << "g bones\n";
  for(const auto e : boost::make_iterator_range(edges(skeleton)))
    os << "l " << source(e, skeleton) + 1 << ' ' << target(e, skeleton) + 1 << '\n';
  const auto& cut_bones = skeleton[boost::graph_bundle].cut_bones;
  if(!cut_bones.empty())
  {
    os << "g cut_bones\n";
    for(const Control_cut_bone<Point>& b : cut_bones)
      os << "l " << b.source + 1 << ' ' << b.target + 1 << '\n';
  }
  os.precision(old_precision);
  return os;
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_OBJ_H
