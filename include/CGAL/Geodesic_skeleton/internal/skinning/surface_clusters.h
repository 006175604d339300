// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_SURFACE_CLUSTERS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_SURFACE_CLUSTERS_H

// The surface of compute_skinning_weights() at the scale of the voxels, where the heat is
// diffused. The bones' heat varies over a few voxels (it spreads as far as the bone is from
// the surface), so a mesh finer than the grid adds unknowns and no detail: the vertices are
// clustered in cells of the grid, and the heat is solved on the clustered surface, whose
// size is the grid's whatever the mesh's. A cluster is the vertices of a cell (half a voxel across)
// joined by the mesh's edges inside that cell: two fingers, or a hand and a thigh, that pass
// through one cell stay apart. A mesh coarser than the cells is its own clustering.
//
// The clustered surface has a vertex at each cluster's centroid and a triangle for each
// triangle of the mesh whose corners fall in three clusters (vertex clustering, after
// Rossignac and Borrel, 1993); each vertex of the mesh then reads the weights of its cluster
// with their gradient there (a least-squares fit over the neighbouring clusters), so that the
// weights vary smoothly across the clusters instead of in steps.

#include <CGAL/Geodesic_skeleton/internal/parallel_parts.h>
#include <CGAL/Geodesic_skeleton/internal/union_find.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

struct Surface_clusters
{
  std::vector<std::uint32_t> cluster_of;                  // per vertex
  std::vector<std::uint32_t> size;                        // per cluster: its vertices
  std::vector<Vec3> centroid;                             // per cluster, in grid coordinates
  std::vector<std::array<std::uint32_t, 3>> triangles;    // of clusters, each once
  std::vector<std::uint32_t> first_neighbour, neighbours; // per cluster, those an edge joins it to

  std::size_t number_of_clusters() const { return centroid.size(); }
};

// The clusters are half a voxel across: on artists' characters (benchmark/EXPERIMENTS.md)
// a voxel's clusters lose detail where the heat turns within a voxel (fingers, ears); half a
// voxel gives the weights of the unclustered mesh, at 4 times the clusters of a voxel.
constexpr double cells_per_voxel = 2;

// The unit cell of a point, as one integer; coordinates are at most 2^20 across, and points
// a little outside the grid keep distinct keys.
inline std::uint64_t cell_key_of(const Vec3& g)
{
  auto coordinate = [](double x) {
    const double clamped = std::clamp(std::floor(x) + double(1 << 20), 0., double((1 << 21) - 1));
    return std::uint64_t(clamped);
  };
  return coordinate(g[0]) | coordinate(g[1]) << 21 | coordinate(g[2]) << 42;
}

// Clusters the vertices `points` (grid coordinates) of `triangles` by cell and by the edges
// inside each cell. Clusters are numbered by their first vertex. O(N + F log F) for the
// sort of the triangles and edges that join clusters (a small share of a fine mesh's). The
// passes over the vertices and the triangles run on up to `threads` threads, with the same
// clusters for any number.
inline Surface_clusters cluster_surface(const std::vector<Vec3>& points,
                                        const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                        unsigned threads)
{
  const std::size_t n = points.size();
  std::vector<std::uint64_t> key(n);
  for_each_index(n, threads, [&](std::size_t v) {
    key[v] = cell_key_of(Vec3{points[v][0] * cells_per_voxel, points[v][1] * cells_per_voxel,
                              points[v][2] * cells_per_voxel});
  });
  // The root of a set is its first vertex, whatever the order of the joins: the triangles
  // are joined by parts, side by side.
  Concurrent_forest forest(n);
  for_each_part(triangles.size(), index_parts(triangles.size(), threads), threads,
                [&](std::size_t, std::size_t begin, std::size_t end) {
                  for(std::size_t f = begin; f < end; ++f)
                  {
                    const auto [a, b, c] = triangles[f];
                    const bool ab = key[a] == key[b], bc = key[b] == key[c];
                    if(ab)
                      forest.join(a, b);
                    if(bc)
                      forest.join(b, c);
                    if(!(ab && bc) && key[c] == key[a]) // with both others, c and a are joined already
                      forest.join(c, a);
                  }
                });
  key = std::vector<std::uint64_t>();

  Surface_clusters c;
  c.cluster_of.resize(n); // each vertex's root, then its cluster
  for_each_index(n, threads, [&](std::size_t v) { c.cluster_of[v] = forest.root(std::uint32_t(v)); });
  for(std::uint32_t v = 0; v < n; ++v)
  {
    if(c.cluster_of[v] == v)
    {
      c.cluster_of[v] = std::uint32_t(c.centroid.size());
      c.centroid.push_back(Vec3{0, 0, 0});
      c.size.push_back(0);
    }
    else
      c.cluster_of[v] = c.cluster_of[c.cluster_of[v]]; // the root is smaller: numbered already
    Vec3& sum = c.centroid[c.cluster_of[v]];
    for(int i = 0; i < 3; ++i)
      sum[std::size_t(i)] += points[v][std::size_t(i)];
    ++c.size[c.cluster_of[v]];
  }
  for(std::size_t k = 0; k < c.centroid.size(); ++k)
    for(double& x : c.centroid[k])
      x /= double(c.size[k]);

  // The edges and the triangles between clusters, by parts of the triangles; the order does
  // not matter (both are sorted below).
  using Edge = std::pair<std::uint32_t, std::uint32_t>;
  const std::size_t parts = index_parts(triangles.size(), threads);
  std::vector<std::vector<Edge>> part_edges(parts);
  std::vector<std::vector<std::array<std::uint32_t, 3>>> part_triangles(parts);
  for_each_part(triangles.size(), parts, threads, [&](std::size_t part, std::size_t begin, std::size_t end) {
    part_edges[part].reserve(3 * (end - begin)); // address space: only what is written is touched
    part_triangles[part].reserve(end - begin);
    // The edges met lately, by a (Fibonacci) hash of their ends: an edge between two
    // clusters is met in the many triangles along it, mostly a few triangles apart, and kept
    // once for those; the buckets below drop the repeats that remain.
    std::vector<std::uint64_t> recent(4096, ~std::uint64_t(0));
    for(std::size_t f = begin; f < end; ++f)
    {
      const auto& t = triangles[f];
      std::array<std::uint32_t, 3> k{c.cluster_of[t[0]], c.cluster_of[t[1]], c.cluster_of[t[2]]};
      for(int i = 0; i < 3; ++i)
        if(const std::uint32_t a = k[std::size_t(i)], b = k[std::size_t((i + 1) % 3)]; a != b)
        {
          const std::uint64_t edge = std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
          if(std::uint64_t& slot = recent[(edge * 0x9E3779B97F4A7C15ull) >> 52]; slot != edge)
          {
            slot = edge;
            part_edges[part].emplace_back(std::min(a, b), std::max(a, b));
          }
        }
      if(k[0] != k[1] && k[1] != k[2] && k[0] != k[2])
      {
        std::sort(k.begin(), k.end()); // the cotangent weights do not depend on the orientation
        part_triangles[part].push_back(k);
      }
    }
  });
  // Each part's triangles sorted on its own thread, then merged: sorted, each once.
  for_each_part(parts, parts, threads, [&](std::size_t part, std::size_t, std::size_t) {
    std::sort(part_triangles[part].begin(), part_triangles[part].end());
  });
  c.triangles = std::move(part_triangles[0]);
  for(std::size_t part = 1; part < parts; ++part)
  {
    std::vector<std::array<std::uint32_t, 3>> merged(c.triangles.size() + part_triangles[part].size());
    std::merge(c.triangles.begin(), c.triangles.end(), part_triangles[part].begin(), part_triangles[part].end(),
               merged.begin());
    c.triangles = std::move(merged);
  }
  part_triangles.clear();
  c.triangles.erase(std::unique(c.triangles.begin(), c.triangles.end()), c.triangles.end());
  // The neighbours of each cluster: the edges in both directions bucketed by cluster (a
  // counting sort, each part of the edges writing its own share of every bucket); each
  // bucket, a few dozen entries that name a few clusters many times, keeps each cluster
  // once (a stamp per cluster), in increasing order. Both by parts, on their threads.
  const std::size_t m = c.centroid.size();
  std::vector<std::vector<std::uint32_t>> part_next(parts); // per part: its entries per cluster, then where they go
  for_each_part(parts, parts, threads, [&](std::size_t part, std::size_t, std::size_t) {
    part_next[part].assign(m, 0);
    for(const auto& [a, b] : part_edges[part])
    {
      ++part_next[part][a];
      ++part_next[part][b];
    }
  });
  std::vector<std::uint32_t> first(m + 1, 0);
  for(std::size_t k = 0; k < m; ++k)
  {
    std::uint32_t at = first[k];
    for(std::vector<std::uint32_t>& next : part_next)
    {
      const std::uint32_t count = next[k];
      next[k] = at; // where the part's entries of cluster k go
      at += count;
    }
    first[k + 1] = at;
  }
  std::vector<std::uint32_t> all(first.back());
  for_each_part(parts, parts, threads, [&](std::size_t part, std::size_t, std::size_t) {
    std::vector<std::uint32_t>& next = part_next[part];
    for(const auto& [a, b] : part_edges[part])
    {
      all[next[a]++] = b;
      all[next[b]++] = a;
    }
  });
  part_edges.clear();
  part_next.clear();
  const std::size_t cluster_parts = index_parts(m, threads);
  std::vector<std::vector<std::uint32_t>> part_neighbours(cluster_parts);
  c.first_neighbour.assign(m + 1, 0);
  for_each_part(m, cluster_parts, threads, [&](std::size_t part, std::size_t begin_cluster, std::size_t end_cluster) {
    std::vector<std::uint32_t>& neighbours = part_neighbours[part];
    neighbours.reserve((first[end_cluster] - first[begin_cluster]) / 4);
    std::vector<std::uint32_t> stamp(m, std::uint32_t(-1));
    for(std::size_t k = begin_cluster; k < end_cluster; ++k)
    {
      const std::size_t begin = neighbours.size();
      for(std::uint32_t i = first[k]; i < first[k + 1]; ++i)
        if(const std::uint32_t q = all[i]; stamp[q] != k)
        {
          stamp[q] = std::uint32_t(k);
          neighbours.push_back(q);
        }
      std::sort(neighbours.begin() + std::ptrdiff_t(begin), neighbours.end());
      c.first_neighbour[k + 1] = std::uint32_t(neighbours.size() - begin); // a count, made an offset below
    }
  });
  for(std::size_t k = 0; k < m; ++k)
    c.first_neighbour[k + 1] += c.first_neighbour[k];
  c.neighbours.reserve(c.first_neighbour[m]);
  for(const std::vector<std::uint32_t>& neighbours : part_neighbours)
    c.neighbours.insert(c.neighbours.end(), neighbours.begin(), neighbours.end());
  return c;
}

// The vectors k_q of cluster `p` that give the gradient of a function f known at the
// centroids, sum over the neighbours q of k_q (f(q) - f(p)): the least-squares fit of
// f(q) - f(p) = g . (c_q - c_p), regularised by a share of the spread so that clusters on a
// line or a plane (a surface's are) get no gradient across it. Appended to `k` in the
// order of p's neighbours.
inline void gradient_weights(const Surface_clusters& c, std::uint32_t p, std::vector<Vec3>& k)
{
  constexpr double regularisation = 1e-2;
  std::array<std::array<double, 3>, 3> m{};
  for(std::uint32_t i = c.first_neighbour[p]; i < c.first_neighbour[p + 1]; ++i)
  {
    const Vec3 d = sub(c.centroid[c.neighbours[i]], c.centroid[p]);
    for(int r = 0; r < 3; ++r)
      for(int s = 0; s < 3; ++s)
        m[std::size_t(r)][std::size_t(s)] += d[std::size_t(r)] * d[std::size_t(s)];
  }
  const double lambda = regularisation * (m[0][0] + m[1][1] + m[2][2]) + 1e-12;
  for(int r = 0; r < 3; ++r)
    m[std::size_t(r)][std::size_t(r)] += lambda;
  // The inverse of the symmetric positive definite m, by its adjugate.
  const double a = m[0][0], b = m[0][1], cc = m[0][2], d = m[1][1], e = m[1][2], f = m[2][2];
  const double A = d * f - e * e, B = cc * e - b * f, C = b * e - cc * d;
  const double determinant = a * A + b * B + cc * C;
  const std::array<std::array<double, 3>, 3> inverse{{{A, B, C},
                                                      {B, a * f - cc * cc, b * cc - a * e},
                                                      {C, b * cc - a * e, a * d - b * b}}};
  for(std::uint32_t i = c.first_neighbour[p]; i < c.first_neighbour[p + 1]; ++i)
  {
    const Vec3 dq = sub(c.centroid[c.neighbours[i]], c.centroid[p]);
    Vec3 kq{0, 0, 0};
    for(int r = 0; r < 3; ++r)
      for(int s = 0; s < 3; ++s)
        kq[std::size_t(r)] += inverse[std::size_t(r)][std::size_t(s)] * dq[std::size_t(s)] / determinant;
    k.push_back(kq);
  }
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_SURFACE_CLUSTERS_H
