// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_SMOOTH_SKELETON_H
#define CGAL_GEODESIC_SKELETON_SMOOTH_SKELETON_H

/// \file smooth_skeleton.h
/// The paper's smoothing of the pruned skeleton (section III.B.i, equation 3): a moving
/// average over consecutive points along each branch.

#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_branches.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Smooths a curve skeleton in place: every point that is neither an end point nor a
/// junction moves to the average of the `window` consecutive points centred on it along
/// its branch (paper, equation 3, with a window of 5); its MAT radius is averaged the same
/// way. End points and junctions (vertices of degree other than 2) stay where they are.
///
/// Near the ends of a branch the window shrinks symmetrically: the point at index i of a
/// branch of N points (nodes at 0 and N-1) averages the 2h+1 points around it with
/// h = min((window-1)/2, i, N-1-i). So a branch shorter than the window is still smoothed,
/// as much as it allows, without pulling its interior towards one end. A closed loop
/// without any junction wraps around, with the window capped to the loop's length. Every
/// average uses the positions before smoothing (one pass of equation 3).
///
/// \tparam CurveSkeleton a `boost::adjacency_list` with `vecS` vertex storage whose vertex
///         bundle has a `point` (a CGAL point type) and a `radius` (`double`), e.g.
///         `Curve_skeleton<Point, MeshVertex>`.
/// \param skeleton the skeleton, smoothed in place; its graph is not changed.
/// \param np optional named parameters among:
///   - `smoothing_window` (package parameter): the number of consecutive points averaged,
///     an odd number in [1, 1001] (default: 5, the paper's); 1 changes nothing.
///
/// \throws std::invalid_argument when the window is even or out of range.
///
/// \b Complexity: O(N * window) for N skeleton vertices, O(N) extra memory.
template <typename CurveSkeleton, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void smooth_skeleton(CurveSkeleton& skeleton,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using Point = decltype(skeleton[0].point);

  const int window = internal::checked_parameter(
      parameter_ranges::smoothing_window,
      choose_parameter(get_parameter(np, internal_np::smoothing_window_tag),
                       static_cast<int>(parameter_ranges::smoothing_window.default_value)),
      "smooth_skeleton");
  const int half = window / 2;

  // Positions before smoothing: x, y, z, radius.
  const std::size_t n = num_vertices(skeleton);
  std::vector<std::array<double, 4>> before(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    const Point& p = skeleton[v].point;
    before[v] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()),
                 skeleton[v].radius};
  }
  auto set_average = [&](std::size_t v, const std::vector<std::size_t>& points) {
    std::array<double, 4> sum{0, 0, 0, 0};
    for(std::size_t w : points)
      for(int c = 0; c < 4; ++c)
        sum[c] += before[w][c];
    const double count = static_cast<double>(points.size());
    skeleton[v].point = Point(sum[0] / count, sum[1] / count, sum[2] / count);
    skeleton[v].radius = sum[3] / count;
  };

  for(const internal::Skeleton_branch& branch : internal::skeleton_branches(skeleton))
  {
    const std::vector<std::size_t>& b = branch.vertices;
    const int size = static_cast<int>(b.size());
    std::vector<std::size_t> points;
    if(branch.closed)
    {
      const int h = std::min(half, (size - 1) / 2);
      for(int i = 0; i < size; ++i)
      {
        points.clear();
        for(int j = i - h; j <= i + h; ++j)
          points.push_back(b[static_cast<std::size_t>(((j % size) + size) % size)]);
        set_average(b[static_cast<std::size_t>(i)], points);
      }
      continue;
    }
    for(int i = 1; i + 1 < size; ++i)
    {
      const int h = std::min({half, i, size - 1 - i});
      points.assign(b.begin() + (i - h), b.begin() + (i + h + 1));
      set_average(b[static_cast<std::size_t>(i)], points);
    }
  }
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_SMOOTH_SKELETON_H
