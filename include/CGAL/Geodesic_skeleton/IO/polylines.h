// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_POLYLINES_H
#define CGAL_GEODESIC_SKELETON_IO_POLYLINES_H

/// \file IO/polylines.h
/// Writes skeletons in the polylines text format of CGAL's demos: one polyline per line,
/// `n x1 y1 z1 ... xn yn zn`.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_branches.h>

#include <CGAL/number_utils.h>

#include <ostream>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

template <typename Point>
void write_point(std::ostream& os, const Point& p)
{
  os << ' ' << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z());
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Writes each bone of a control skeleton (its smoothed points, parent to child) as one
/// polyline; cut bones too, after the others. \returns `os`. \b Complexity: O(total points).
template <typename Point>
std::ostream& write_polylines(std::ostream& os, const Control_skeleton<Point>& skeleton)
{
  const auto old_precision = os.precision(9);
  auto write_bone = [&](const Control_bone<Point>& bone) {
    os << bone.points.size();
    for(const Point& p : bone.points)
      internal::write_point(os, p);
    os << '\n';
  };
  for(const auto e : boost::make_iterator_range(edges(skeleton)))
    write_bone(skeleton[e]);
  for(const Control_cut_bone<Point>& bone : skeleton[boost::graph_bundle].cut_bones)
    write_bone(bone);
  os.precision(old_precision);
  return os;
}

/// \ingroup PkgGeodesicSkeletonRef
/// Writes a curve skeleton (a graph whose vertex bundle has a `point`, e.g.
/// `Curve_skeleton`) as polylines, one per branch between end points and junctions (a
/// closed loop repeats its first point). \returns `os`. \b Complexity: O((V + E) log E).
template <typename CurveSkeleton>
std::ostream& write_curve_skeleton_polylines(std::ostream& os, const CurveSkeleton& skeleton)
{
  const auto old_precision = os.precision(9);
  for(const auto& branch : Geodesic_skeleton::internal::skeleton_branches(skeleton))
  {
    os << branch.vertices.size() + (branch.closed ? 1 : 0);
    for(std::size_t v : branch.vertices)
      internal::write_point(os, skeleton[v].point);
    if(branch.closed)
      internal::write_point(os, skeleton[branch.vertices.front()].point);
    os << '\n';
  }
  os.precision(old_precision);
  return os;
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_POLYLINES_H
