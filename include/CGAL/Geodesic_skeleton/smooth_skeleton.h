// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_SMOOTH_SKELETON_H
#define CGAL_GEODESIC_SKELETON_SMOOTH_SKELETON_H

/// \file smooth_skeleton.h
/// The paper's smoothing of the pruned skeleton (section III.B.i, equation 3): a moving
/// average over consecutive points along each branch.

#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_branches.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_vertex_maps.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The smoothing window that `extract_control_skeleton()` uses when none is given: the
/// paper's 5 points at the default resolution (`default_voxel_resolution`), and in
/// proportion to the resolution elsewhere, so that the window spans about the same length
/// of the shape (2.5 voxels of the default grid on either side) whatever the grid: 2
/// round(2 `resolution` / 64) + 1 points, at least 3. At resolutions 48 and 64: 5; at 96:
/// 7; at 128: 9. A window of a fixed number of points averages half the length of the shape
/// on a grid twice as fine, and leaves it the voxel wiggles that the split counts as bends.
/// \param resolution the resolution of the voxel grid (`resolution` named parameter).
///
/// \b Complexity: O(1).
inline int default_smoothing_window(int resolution)
{
  const long half = std::lround(2.0 * double(resolution) / double(default_voxel_resolution));
  const long largest_half = long(parameter_ranges::smoothing_window.high) / 2;
  return int(2 * (std::min)((std::max)(half, 1L), largest_half) + 1);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Smooths a curve skeleton in place: every point that is neither an end point nor a
/// junction moves to the average of the `window` consecutive points centred on it along
/// its branch (paper, equation 3, with a window of 5); its MAT radius, when the skeleton
/// has one, is averaged the same way. End points and junctions (vertices of degree other
/// than 2) stay where they are.
///
/// Near the ends of a branch the window shrinks symmetrically: the point at index i of a
/// branch of N points (nodes at 0 and N-1) averages the 2h+1 points around it with
/// h = min((window-1)/2, i, N-1-i). So a branch shorter than the window is still smoothed,
/// as much as it allows, without pulling its interior towards one end. A closed loop
/// without any junction wraps around, with the window capped to the loop's length. Every
/// average uses the positions before smoothing (one pass of equation 3).
///
/// The points and radii are read and written through property maps, so the skeleton of
/// `CGAL::extract_mean_curvature_flow_skeleton()`
/// (`CGAL::Mean_curvature_flow_skeletonization<TriangleMesh>::Skeleton`, whose vertices
/// have a `point` and no radius) is smoothed as it is: its points only, or its points and
/// the radii of a `mat_radius_map` that the caller gives.
///
/// \tparam CurveSkeleton a `boost::adjacency_list` with `vecS` vertex storage (its vertex
///         descriptors are the indices 0 to N-1), e.g. `Curve_skeleton<Point, MeshVertex>`
///         or `CGAL::Mean_curvature_flow_skeletonization<TriangleMesh>::Skeleton`. Its
///         vertex bundle has a `point` member (a CGAL point type) unless a
///         `vertex_point_map` is given.
/// \param skeleton the skeleton, smoothed in place; its graph is not changed.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the point of each skeleton vertex, read and written}
///     \cgalParamType{a model of `ReadWritePropertyMap` with the skeleton's vertex
///                    descriptor as key type and a CGAL point type constructible from
///                    three `double`s as value type}
///     \cgalParamDefault{`get(&Bundle::point, skeleton)`, the bundle's `point` member}
///   \cgalParamNEnd
///   \cgalParamNBegin{mat_radius_map}
///     \cgalParamDescription{the MAT radius at each skeleton vertex, in world units, read
///                           and written (package parameter)}
///     \cgalParamType{a model of `ReadWritePropertyMap` with the skeleton's vertex
///                    descriptor as key type and `double` as value type}
///     \cgalParamDefault{`get(&Bundle::radius, skeleton)` when the vertex bundle has a
///                       `radius` member, as `Curve_skeleton_vertex` has; otherwise
///                       none, and only the points are smoothed}
///   \cgalParamNEnd
///   \cgalParamNBegin{smoothing_window}
///     \cgalParamDescription{the number of consecutive points averaged, an odd number in
///                           [1, 1001]; 1 changes nothing (package parameter)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{5, the paper's (`extract_control_skeleton()` scales it with the
///                       resolution: `default_smoothing_window()`)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
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

  const int window = internal::checked_parameter(
      parameter_ranges::smoothing_window,
      choose_parameter(get_parameter(np, internal_np::smoothing_window_tag),
                       static_cast<int>(parameter_ranges::smoothing_window.default_value)),
      "smooth_skeleton");
  const int half = window / 2;

  auto point_map = internal::skeleton_point_map(skeleton, np);
  using Point = typename boost::property_traits<decltype(point_map)>::value_type;
  auto radius_map = internal::skeleton_radius_map(skeleton, np);
  constexpr bool with_radius = !std::is_same_v<decltype(radius_map), internal::No_map>;

  // Positions before smoothing: x, y, z, radius (0 without radius map).
  const std::size_t n = num_vertices(skeleton);
  std::vector<std::array<double, 4>> before(n);
  for(std::size_t v = 0; v < n; ++v)
  {
    const Point p = get(point_map, v);
    double radius = 0;
    if constexpr(with_radius)
      radius = static_cast<double>(get(radius_map, v));
    before[v] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()), radius};
  }
  auto set_average = [&](std::size_t v, const std::vector<std::size_t>& points) {
    std::array<double, 4> sum{0, 0, 0, 0};
    for(std::size_t w : points)
      for(int c = 0; c < 4; ++c)
        sum[c] += before[w][c];
    const double count = static_cast<double>(points.size());
    put(point_map, v, Point(sum[0] / count, sum[1] / count, sum[2] / count));
    if constexpr(with_radius)
      put(radius_map, v, sum[3] / count);
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
