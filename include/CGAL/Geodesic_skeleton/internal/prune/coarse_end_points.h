// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_POINTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_POINTS_H

// The end points of the same shape's skeleton on a coarser grid, which tell the snipping
// which end branches a finer grid resolves that the coarser one does not.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The voxels of `skeleton` that are end points of its graph, the one to_graph() makes
// (26-adjacency without junction triangles): the end points the control skeleton gets.
template <typename VoxelSet>
std::vector<Voxel_key> graph_end_points(const VoxelSet& skeleton)
{
  const Skeleton_adjacency graph = skeleton_adjacency(skeleton);
  std::vector<std::size_t> degree(graph.nodes.size(), 0);
  for(const auto& edge : graph.edges)
  {
    ++degree[std::size_t(edge.first)];
    ++degree[std::size_t(edge.second)];
  }
  std::vector<Voxel_key> ends;
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    if(degree[v] == 1)
      ends.push_back(graph.nodes[v]);
  return ends;
}

// How much larger the snipping's thresholds are for an end branch that the coarser
// skeleton does not have: 3 times the default level of detail (0.75 of the body's thickness)
// is more than 2 thicknesses, more than the corner branches of a block reach out, and less
// than a limb, which reaches out several thicknesses; such a branch is snipped only while
// the finer skeleton has more end points than the coarser.
constexpr double unmatched_threshold_factor = 3.;

// What the snipping reads of a coarser skeleton: its end points, in the grid coordinates
// of the skeleton being pruned, and how near one must be to a branch's tip for the coarse
// grid to have the branch too. An end branch whose tip has none that near is judged with
// thresholds `unmatched_factor` times larger, as long as the pruned skeleton has more end
// points than the coarse one (`budget`, spent by each branch snipped that only the larger
// thresholds call a spur).
struct Coarse_end_point_guide
{
  std::vector<std::array<double, 3>> points;
  double tolerance = 0;
  double unmatched_factor = 1;
  std::size_t budget = 0;

  bool has_match_near(const Voxel_key& tip) const
  {
    const Vec3 centre{tip.x + 0.5, tip.y + 0.5, tip.z + 0.5};
    for(const Vec3& p : points)
      if(squared_distance3(p, centre) <= tolerance * tolerance)
        return true;
    return false;
  }

  // The factor of the snipping's thresholds for the end branch whose tip is `tip`.
  double threshold_factor(const Voxel_key& tip) const
  {
    return budget > 0 && !has_match_near(tip) ? unmatched_factor : 1.;
  }

  // Records the snipping of an end branch that only the larger thresholds call a spur.
  void snipped()
  {
    if(budget > 0)
      --budget;
  }
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_COARSE_END_POINTS_H
