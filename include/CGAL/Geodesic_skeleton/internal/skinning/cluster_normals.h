// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_CLUSTER_NORMALS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_CLUSTER_NORMALS_H

// The area and the outward unit normal of each cluster of the surface (surface_clusters.h),
// for the facing distance and the inscribed balls of compute_skinning_weights(). A
// modeller's winding may point inwards: each connected piece whose signed volume (about its
// centroid) is negative has its normals turned round, so that a mesh and its mirror winding
// get the same weights.

#include <CGAL/Geodesic_skeleton/internal/parallel_parts.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/surface_clusters.h>
#include <CGAL/Geodesic_skeleton/internal/union_find.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The parts of the triangles whose sums outward_cluster_normals() takes apart (on as many
// threads as there are), whatever the number of threads.
constexpr std::size_t normal_sum_parts = 4;

// The connected pieces of the surface, as a piece number (its first cluster) per cluster:
// a cluster is connected, so the clusters joined by edges make the mesh's pieces.
inline std::vector<std::uint32_t> cluster_pieces(const Surface_clusters& clusters)
{
  std::vector<std::uint32_t> parent(clusters.number_of_clusters());
  std::iota(parent.begin(), parent.end(), 0u);
  for(std::uint32_t c = 0; c < parent.size(); ++c)
    for(std::uint32_t i = clusters.first_neighbour[c]; i < clusters.first_neighbour[c + 1]; ++i)
      if(const std::uint32_t a = find_root(parent, c), b = find_root(parent, clusters.neighbours[i]); a != b)
        parent[std::max(a, b)] = std::min(a, b);
  for(std::uint32_t c = 0; c < parent.size(); ++c)
    parent[c] = find_root(parent, c);
  return parent;
}

// Per cluster, its area (a third of each incident triangle's per vertex, in the units of
// `points` squared) in `areas`, and in `normals` the sum, over its vertices, of their
// triangles' area-weighted normals, of length 1 (0 for a cluster of degenerate triangles
// only, or of none), pointing out of its piece. A cluster of one vertex gets the vertex's
// normal. On up to `threads` threads.
inline void outward_cluster_normals(const std::vector<Vec3>& points,
                                    const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                    const Surface_clusters& clusters, std::vector<Vec3>& normals,
                                    std::vector<double>& areas, unsigned threads)
{
  const std::size_t m = clusters.number_of_clusters();
  const std::vector<std::uint32_t> piece = cluster_pieces(clusters);
  std::vector<Vec3> centroid(m, Vec3{0, 0, 0});
  std::vector<double> count(m, 0.);
  for(std::size_t c = 0; c < m; ++c)
  {
    for(std::size_t i = 0; i < 3; ++i)
      centroid[piece[c]][i] += clusters.size[c] * clusters.centroid[c][i];
    count[piece[c]] += clusters.size[c];
  }
  for(std::size_t p = 0; p < m; ++p)
    if(count[p] > 0)
      for(double& x : centroid[p])
        x /= count[p];

  // The triangles in a fixed number of parts, each summed on its own, then the parts in order:
  // the same sums with any number of threads.
  struct Sums
  {
    std::vector<Vec3> normals;
    std::vector<double> areas, volume;
  };
  std::vector<Sums> part(normal_sum_parts);
  for_each_part(triangles.size(), normal_sum_parts, threads, [&](std::size_t p, std::size_t begin, std::size_t end) {
    Sums& sums = part[p];
    sums.normals.assign(m, Vec3{0, 0, 0});
    sums.areas.assign(m, 0.);
    sums.volume.assign(m, 0.);
    for(std::size_t i = begin; i < end; ++i)
    {
      const auto& t = triangles[i];
      const Vec3 twice_area_normal = cross3(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]));
      const double third = norm3(twice_area_normal) / 6;
      for(std::uint32_t v : t)
      {
        const std::uint32_t c = clusters.cluster_of[v];
        sums.areas[c] += third;
        for(std::size_t x = 0; x < 3; ++x)
          sums.normals[c][x] += twice_area_normal[x];
      }
      const std::uint32_t pc = piece[clusters.cluster_of[t[0]]];
      sums.volume[pc] += dot3(sub(points[t[0]], centroid[pc]), twice_area_normal);
    }
  });
  normals = std::move(part[0].normals);
  areas = std::move(part[0].areas);
  std::vector<double> volume = std::move(part[0].volume);
  for(std::size_t p = 1; p < normal_sum_parts; ++p)
    for(std::size_t c = 0; c < m; ++c)
    {
      areas[c] += part[p].areas[c];
      volume[c] += part[p].volume[c];
      for(std::size_t x = 0; x < 3; ++x)
        normals[c][x] += part[p].normals[c][x];
    }
  for(std::size_t c = 0; c < m; ++c)
    if(const double length = norm3(normals[c]); length > 0)
    {
      const double scale = (volume[piece[c]] < 0 ? -1 : 1) / length;
      for(double& x : normals[c])
        x *= scale;
    }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_CLUSTER_NORMALS_H
