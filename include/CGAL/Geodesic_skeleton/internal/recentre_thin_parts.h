// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_RECENTRE_THIN_PARTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_RECENTRE_THIN_PARTS_H

#include <CGAL/number_utils.h>

#include <boost/graph/adjacency_list.hpp>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Where a limb is about a voxel thick, its skeleton runs through voxels that the surface
// crosses, and a voxel centre may lie outside the mesh by up to half a voxel diagonal. The
// mesh vertices mapped to such a skeleton vertex and to its neighbours in the skeleton ring
// the limb there (or cap its tip), and their centroid lies inside the convex hull of that
// piece of the limb: the skeleton vertex moves there. Vertices of radius `max_radius` or
// more (world units), or with no mesh vertex around, stay at their voxel centre. The new
// positions are computed from the mapped vertices only, so the order does not matter.
//
// Complexity: O(V + E + M) for V skeleton vertices, E edges and M mesh vertices.
template <typename CurveSkeleton, typename VertexPointMap>
std::size_t recentre_thin_parts(CurveSkeleton& skeleton, VertexPointMap vpm, double max_radius)
{
  using Point = decltype(skeleton[0].point);
  std::size_t moved = 0;
  for(std::size_t v = 0; v < num_vertices(skeleton); ++v)
  {
    auto& node = skeleton[v];
    if(node.radius >= max_radius)
      continue;
    std::array<double, 3> sum{0, 0, 0};
    std::size_t count = 0;
    auto add_vertices_of = [&](std::size_t w) {
      for(const auto& mesh_vertex : skeleton[w].vertices)
      {
        const auto& p = get(vpm, mesh_vertex);
        sum[0] += CGAL::to_double(p.x());
        sum[1] += CGAL::to_double(p.y());
        sum[2] += CGAL::to_double(p.z());
        ++count;
      }
    };
    add_vertices_of(v);
    for(auto w : boost::make_iterator_range(boost::adjacent_vertices(v, skeleton)))
      add_vertices_of(static_cast<std::size_t>(w));
    if(count == 0)
      continue;
    const double n = static_cast<double>(count);
    node.point = Point(sum[0] / n, sum[1] / n, sum[2] / n);
    ++moved;
  }
  return moved;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_RECENTRE_THIN_PARTS_H
