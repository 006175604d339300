// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_BONES_IN_GRID_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_BONES_IN_GRID_H

// compute_skinning_weights()'s inputs checked and put in the grid: the bones as polylines
// in grid coordinates, the joints' depths along the bones, and the check that a given solid
// is the one voxelize() gives the mesh.

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/solid_voxels.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The polyline of a bone, in grid coordinates: its points, or the segment from its parent
// joint to its child joint when it has fewer than two.
template <typename Point>
std::vector<Vec3> bone_polyline_in_grid(const Control_skeleton<Point>& skeleton,
                                        typename boost::graph_traits<Control_skeleton<Point>>::edge_descriptor e,
                                        const Voxel_frame& frame)
{
  const Control_bone<Point>& bone = skeleton[e];
  auto grid = [&](const Point& p) {
    return frame.to_grid(Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  };
  std::vector<Vec3> polyline;
  if(bone.points.size() >= 2)
    for(const Point& p : bone.points)
      polyline.push_back(grid(p));
  else
    polyline = {grid(skeleton[source(e, skeleton)].point), grid(skeleton[target(e, skeleton)].point)};
  for(const Vec3& g : polyline)
    if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2]))
      throw std::invalid_argument("compute_skinning_weights: a bone has a non-finite point");
  return polyline;
}

// Throws unless `grid` is, as far as the mesh's vertices tell, the grid that voxelize()
// gives the mesh at `resolution` (a grid of another mesh, or at another resolution, would
// give wrong weights silently): in the grid's frame, the vertices of the faces span
// `resolution` voxels along their longest axis and sit centred in the box with one voxel of
// margin, as voxelize_frame() places them. O(V): the frame is not computed again.
inline void check_grid_frame(const std::vector<Vec3>& grid_points,
                             const std::vector<std::array<std::uint32_t, 3>>& triangles, int resolution,
                             bool empty_grid, const char* caller)
{
  std::vector<bool> of_a_face(grid_points.size(), false);
  for(const auto& t : triangles)
    for(std::uint32_t v : t)
      of_a_face[v] = true;
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(std::size_t v = 0; v < grid_points.size(); ++v)
    if(of_a_face[v])
      for(std::size_t a = 0; a < 3; ++a)
      {
        lo[a] = std::min(lo[a], grid_points[v][a]);
        hi[a] = std::max(hi[a], grid_points[v][a]);
      }
  const double tolerance = 1e-6 * resolution;
  bool matches = !empty_grid && std::abs(std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}) - resolution) <= tolerance;
  for(std::size_t a = 0; a < 3 && matches; ++a)
  {
    // The box has an odd number n of voxels across the extent e, and one of margin: the
    // lowest vertex at 1 + (n - e) / 2 (e in these coordinates is rounded, so n may be the
    // next odd number either way).
    const double e = hi[a] - lo[a];
    const int n = odd_voxel_count(e);
    matches = false;
    for(int candidate : {n - 2, n, n + 2})
      matches = matches || (candidate >= 1 && std::abs(lo[a] - (1 + 0.5 * (candidate - e))) <= tolerance);
  }
  if(!matches)
    throw std::invalid_argument(std::string(caller) + ": the voxelized_solid is not the solid voxelize() gives this "
                                "mesh at resolution " + std::to_string(resolution));
}

template <typename Point>
void check_bones(const Control_skeleton<Point>& skeleton, const char* caller)
{
  if(num_edges(skeleton) == 0)
    throw std::invalid_argument(std::string(caller) + ": the control skeleton has no bone");
  if(num_edges(skeleton) > std::size_t(std::numeric_limits<std::uint32_t>::max()))
    throw std::invalid_argument(std::string(caller) + ": too many bones");
}

// The depth of each joint below the joints without a parent bone (0), along the bones.
template <typename Point, typename Bone>
std::vector<std::uint32_t> joint_depths(const Control_skeleton<Point>& skeleton, const std::vector<Bone>& bones)
{
  const std::size_t joints = num_vertices(skeleton);
  std::vector<std::vector<std::uint32_t>> children(joints);
  std::vector<bool> has_parent(joints, false);
  for(const Bone& b : bones)
  {
    children[source(b, skeleton)].push_back(std::uint32_t(target(b, skeleton)));
    has_parent[target(b, skeleton)] = true;
  }
  constexpr std::uint32_t unreached = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> depth(joints, unreached), queue;
  for(std::uint32_t j = 0; j < joints; ++j)
    if(!has_parent[j])
    {
      depth[j] = 0;
      queue.push_back(j);
    }
  for(std::size_t q = 0; q < queue.size(); ++q)
    for(std::uint32_t c : children[queue[q]])
      if(depth[c] == unreached)
      {
        depth[c] = depth[queue[q]] + 1;
        queue.push_back(c);
      }
  for(std::uint32_t& d : depth) // joints on a loop without a parentless joint
    if(d == unreached)
      d = 0;
  return depth;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_BONES_IN_GRID_H
