// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_VERTEX_NORMALS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_VERTEX_NORMALS_H

// Outward unit normals of the vertices of a triangle soup, for the facing distance of
// compute_skinning_weights(). A modeller's winding may point inwards: each connected piece
// whose signed volume (about its centroid) is negative has its normals turned round, so
// that a mesh and its mirror winding get the same weights.

#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The connected pieces of the triangles (sharing a vertex joins), as a piece number per
// vertex; a vertex of no triangle is a piece of its own.
inline std::vector<std::uint32_t> triangle_pieces(std::size_t vertices,
                                                  const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  std::vector<std::uint32_t> root(vertices);
  std::iota(root.begin(), root.end(), std::uint32_t(0));
  auto find = [&](std::uint32_t v) {
    while(root[v] != v)
      v = root[v] = root[root[v]];
    return v;
  };
  for(const auto& t : triangles)
    for(int c = 1; c < 3; ++c)
      if(const std::uint32_t a = find(t[0]), b = find(t[std::size_t(c)]); a != b)
        root[std::max(a, b)] = std::min(a, b);
  for(std::size_t v = 0; v < vertices; ++v)
    root[v] = find(std::uint32_t(v));
  return root;
}

// Per vertex, the area-weighted mean of its triangles' normals, of length 1 (0 for a vertex
// of degenerate triangles only, or of none), pointing out of its piece.
inline std::vector<Vec3> outward_vertex_normals(const std::vector<Vec3>& points,
                                                const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  const std::size_t n = points.size();
  const std::vector<std::uint32_t> piece = triangle_pieces(n, triangles);
  std::vector<Vec3> centroid(n, Vec3{0, 0, 0});
  std::vector<double> count(n, 0.), volume(n, 0.);
  for(std::size_t v = 0; v < n; ++v)
  {
    for(int c = 0; c < 3; ++c)
      centroid[piece[v]][c] += points[v][c];
    count[piece[v]] += 1;
  }
  for(std::size_t p = 0; p < n; ++p)
    if(count[p] > 0)
      for(int c = 0; c < 3; ++c)
        centroid[p][c] /= count[p];

  std::vector<Vec3> normals(n, Vec3{0, 0, 0});
  for(const auto& t : triangles)
  {
    const Vec3 twice_area_normal = cross3(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]));
    for(std::uint32_t v : t)
      for(int c = 0; c < 3; ++c)
        normals[v][c] += twice_area_normal[c];
    const std::uint32_t p = piece[t[0]];
    volume[p] += dot3(sub(points[t[0]], centroid[p]), twice_area_normal);
  }
  for(std::size_t v = 0; v < n; ++v)
    if(const double length = norm3(normals[v]); length > 0)
    {
      const double scale = (volume[piece[v]] < 0 ? -1 : 1) / length;
      for(int c = 0; c < 3; ++c)
        normals[v][c] *= scale;
    }
  return normals;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_VERTEX_NORMALS_H
