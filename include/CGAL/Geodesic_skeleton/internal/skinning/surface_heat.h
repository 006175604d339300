// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_SURFACE_HEAT_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_SURFACE_HEAT_H

// The diffusion step of compute_skinning_weights(): bone heat over the surface (after Baran
// and Popovic, Automatic Rigging and Animation of 3D Characters, SIGGRAPH 2007), solved on
// the surface clustered in half-voxel cells (surface_clusters.h). Each cluster c is heated
// at distance d(c) by one bone, or by a few tied bones that share its heat equally; with
// p_b(c) the share of bone b, the weight of bone b solves
//   (L + diag(c A / d^2)) w_b = diag(c A / d^2) p_b,
// with L the cotangent Laplacian of the clustered surface and A the clusters' areas. The
// weights are in [0, 1] and sum to 1 at every cluster (L has non-negative edge weights: the
// maximum principle), and the matrix is positive definite whatever the mesh (every diagonal
// entry has a positive heat term), so the solve never fails where bone heat does. Each
// vertex reads its cluster's weights plus their gradient times its offset from the
// cluster's centroid. All lengths are in voxels, so the weights do not depend on the mesh's
// scale.

#include <CGAL/Geodesic_skeleton/Bone_weights.h>
#include <CGAL/Geodesic_skeleton/internal/parallel_parts.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/surface_clusters.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// What heats each vertex: its bone, the distance to it (voxels), and the other bones at the
// same distance (`none` past the last), which share the heat equally.
struct Heat_sources
{
  static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  static constexpr std::size_t most_tied = 3;
  using Tied_bones = std::array<std::uint32_t, most_tied>;
  static Tied_bones no_tied_bones()
  {
    Tied_bones t;
    t.fill(none);
    return t;
  }

  std::vector<std::uint32_t> bone;
  std::vector<double> distance;
  std::vector<Tied_bones> tied;

  // The bones that heat vertex `v`, and how many they are.
  std::size_t heating_bones(std::size_t v, std::array<std::uint32_t, most_tied + 1>& bones) const
  {
    bones[0] = bone[v];
    std::size_t count = 1;
    for(std::uint32_t b : tied[v])
      if(b != none)
        bones[count++] = b;
    return count;
  }
};

// Keeps the `k` largest weights of a vertex.
inline void keep_largest(Bone_weights& weights, std::size_t k, std::uint32_t bone, float weight)
{
  if(weights.size() < k)
  {
    weights.push_back(bone, weight);
    return;
  }
  std::size_t smallest = 0;
  for(std::size_t i = 1; i < weights.size(); ++i)
    if(weights.weight[i] < weights.weight[smallest])
      smallest = i;
  if(weight > weights.weight[smallest])
  {
    weights.bone[smallest] = bone;
    weights.weight[smallest] = weight;
  }
}

// The faces of `mesh` as triangles of vertex indices (a polygon as a fan).
template <typename FaceGraph, typename VertexIndexMap>
std::vector<std::array<std::uint32_t, 3>> triangles_of(const FaceGraph& mesh, const VertexIndexMap& vim)
{
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(num_faces(mesh)); // one per face of a triangle mesh
  std::vector<std::uint32_t> corners;
  for(auto f : faces(mesh))
  {
    const auto h = halfedge(f, mesh), h1 = next(h, mesh), h2 = next(h1, mesh);
    if(next(h2, mesh) == h) // a triangle: its corners in the order halfedges_around_face() gives
    {
      triangles.push_back({std::uint32_t(get(vim, target(h, mesh))), std::uint32_t(get(vim, target(h1, mesh))),
                           std::uint32_t(get(vim, target(h2, mesh)))});
      continue;
    }
    corners.clear();
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
      corners.push_back(std::uint32_t(get(vim, target(h, mesh))));
    for(std::size_t i = 1; i + 1 < corners.size(); ++i)
      triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
  return triangles;
}

// The cotangent of a triangle's angle at `apex`, clamped to [0, 1000]: negative cotangents
// (obtuse angles) would break the maximum principle, and degenerate triangles would give
// infinite ones.
inline double clamped_cotangent(const Vec3& apex, const Vec3& a, const Vec3& b)
{
  const Vec3 u = sub(a, apex), v = sub(b, apex);
  const double cross_norm = norm3(cross3(u, v));
  const double dot_uv = dot3(u, v);
  if(!(cross_norm > 0))
    return 0;
  return std::clamp(dot_uv / cross_norm, 0., 1000.);
}

// The lower triangle of L + diag(heat) (all that a solver of symmetric systems reads): the
// cotangent Laplacian (L(i, i) = the sum of the edge weights of i, L(i, j) = -w_ij) of
// triangles given as vertex index triples over `points`, screened by `heat`, one value per
// point.
inline Eigen::SparseMatrix<double> screened_cotangent_laplacian(const std::vector<Vec3>& points,
                                                                const std::vector<std::array<std::uint32_t, 3>>& triangles,
                                                                const std::vector<double>& heat)
{
  const std::size_t n = points.size();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(3 * triangles.size() + n);
  std::vector<double> diagonal(n, 0.);
  for(const auto& t : triangles)
    for(int corner = 0; corner < 3; ++corner)
    {
      const std::uint32_t apex = t[std::size_t(corner)], i = t[std::size_t((corner + 1) % 3)],
                          j = t[std::size_t((corner + 2) % 3)];
      const double w = 0.5 * clamped_cotangent(points[apex], points[i], points[j]);
      if(w == 0)
        continue;
      entries.emplace_back(std::max(i, j), std::min(i, j), -w);
      diagonal[i] += w;
      diagonal[j] += w;
    }
  for(std::size_t v = 0; v < n; ++v)
    entries.emplace_back(Eigen::Index(v), Eigen::Index(v), diagonal[v] + heat[v]);
  const Eigen::Index size = Eigen::Index(n);
  Eigen::SparseMatrix<double> matrix(size, size);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

// Solves A X = B with the factorisation P A P^T = L D L^T of `solver` (an Eigen
// SimplicialLDLT), for the `width` columns of B given row by row in `x` (x[i * width + c] is
// B(i, c)), which receives X likewise. It does what the solver's solve() does, in the same
// order of operations, but in one pass over the factor for all the columns, where solve()
// makes one per column: the factor is read `width` times less.
template <typename Solver>
void solve_in_rows(const Solver& solver, std::vector<double>& x, std::size_t width)
{
  const auto& factor = solver.matrixL().nestedExpression(); // L, unit diagonal, by columns
  const auto& diagonal = solver.vectorD();
  const auto& to_factor = solver.permutationP().indices();
  const auto& from_factor = solver.permutationPinv().indices();
  using Factor = std::decay_t<decltype(factor)>;
  const std::size_t n = std::size_t(factor.cols());
  std::vector<double> y(x.size());
  auto row = [width](std::vector<double>& m, std::size_t i) { return m.data() + i * width; };
  for(std::size_t i = 0; i < n; ++i)
    std::copy_n(row(x, i), width, row(y, std::size_t(to_factor[Eigen::Index(i)])));
  for(std::size_t j = 0; j < n; ++j) // L z = y, column by column
  {
    const double* yj = row(y, j);
    if(std::all_of(yj, yj + width, [](double v) { return v == 0; }))
      continue;
    for(typename Factor::InnerIterator it(factor, Eigen::Index(j)); it; ++it)
      if(const std::size_t i = std::size_t(it.index()); i > j)
      {
        double* yi = row(y, i);
        for(std::size_t c = 0; c < width; ++c)
          yi[c] -= yj[c] * it.value();
      }
  }
  for(std::size_t j = 0; j < n; ++j) // D^-1
  {
    const double inverse = 1. / diagonal[Eigen::Index(j)];
    double* yj = row(y, j);
    for(std::size_t c = 0; c < width; ++c)
      yj[c] = inverse * yj[c];
  }
  for(std::size_t j = n; j-- > 0;) // L^T z = y, row by row of L^T
  {
    double* yj = row(y, j);
    for(typename Factor::InnerIterator it(factor, Eigen::Index(j)); it; ++it)
      if(const std::size_t i = std::size_t(it.index()); i > j)
      {
        const double* yi = row(y, i);
        for(std::size_t c = 0; c < width; ++c)
          yj[c] -= it.value() * yi[c];
      }
  }
  for(std::size_t i = 0; i < n; ++i)
    std::copy_n(row(y, i), width, row(x, std::size_t(from_factor[Eigen::Index(i)])));
}

// The weights of each cluster, bone by bone: bone `bone[i]` has `weight[i]` for i in
// [first[c], first[c + 1]), by increasing bone.
struct Cluster_weights
{
  std::vector<std::uint32_t> first, bone;
  std::vector<double> weight;
};

// The heat system of the clustered surface before the heat is known: the lower triangle of
// its cotangent Laplacian, and the ordering and analysis of its sparse Cholesky
// factorisation. Its pattern is the surface's, whatever the heat (which only adds to the
// diagonal), so it may be made before the heat sources are found.
struct Heat_system
{
  Eigen::SparseMatrix<double> matrix;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
};

// The heat system of the clustered surface `clusters`. About O(C^1.5) for C clusters.
inline void analyse_heat_system(const Surface_clusters& clusters, Heat_system& system)
{
  system.matrix = screened_cotangent_laplacian(clusters.centroid, clusters.triangles,
                                               std::vector<double>(clusters.number_of_clusters(), 0.));
  system.solver.analyzePattern(system.matrix);
}

// Solves the screened heat system on the clustered surface (surface_clusters.h) for every
// bone, the clusters heated by `sources` with the heat `heat` (added to `system`'s matrix),
// keeping the weights above `kept` of each cluster.
inline bool solve_cluster_heat(const Surface_clusters& clusters, const std::vector<double>& heat,
                               const Heat_sources& sources, std::size_t bones, double kept,
                               Heat_system& system, Cluster_weights& out, unsigned threads)
{
  const std::size_t n = clusters.number_of_clusters();
  // The heat on the diagonal: the first entry of each column of the lower triangle, which
  // screened_cotangent_laplacian() writes in every column (setFromTriplets() sorts them).
  Eigen::SparseMatrix<double>& matrix = system.matrix;
  for(Eigen::Index j = 0; j < matrix.outerSize(); ++j)
    matrix.valuePtr()[matrix.outerIndexPtr()[j]] += heat[std::size_t(j)];
  system.solver.factorize(matrix);
  const auto& solver = system.solver;
  if(solver.info() != Eigen::Success)
    return false;
  // The clusters each bone heats, with its share of their heat.
  std::vector<std::vector<std::pair<std::uint32_t, double>>> heated(bones);
  std::array<std::uint32_t, Heat_sources::most_tied + 1> heating{};
  for(std::size_t c = 0; c < n; ++c)
  {
    const std::size_t count = sources.heating_bones(c, heating);
    for(std::size_t i = 0; i < count; ++i)
      heated[heating[i]].emplace_back(std::uint32_t(c), heat[c] / double(count));
  }
  // A few bones per solve: one pass over the factor serves them all; the batches' solves run
  // side by side, one per thread.
  constexpr std::size_t block = 8;
  std::vector<std::vector<std::uint32_t>> batches;
  for(std::size_t first = 0; first < bones;)
  {
    std::vector<std::uint32_t> batch;
    for(; first < bones && batch.size() < block; ++first)
      if(!heated[first].empty())
        batch.push_back(std::uint32_t(first));
    if(!batch.empty())
      batches.push_back(std::move(batch));
  }
  // Per batch, the weights kept, as (cluster, bone) and weight; a batch's solve needs a
  // buffer of n x 8 values, so as many of them exist at once as there are threads.
  struct Kept
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;
    std::vector<double> values;
  };
  std::vector<Kept> kept_of(batches.size());
  for_each_part(batches.size(), batches.size(), threads, [&](std::size_t b, std::size_t, std::size_t) {
    const std::vector<std::uint32_t>& batch = batches[b];
    const std::size_t width = batch.size();
    std::vector<double> x(n * width, 0.);
    for(std::size_t column = 0; column < width; ++column)
      for(const auto& [c, h] : heated[batch[column]])
        x[c * width + column] = h;
    solve_in_rows(solver, x, width);
    for(std::size_t c = 0; c < n; ++c)
      for(std::size_t column = 0; column < width; ++column)
        if(const double w = x[c * width + column]; w > kept)
        {
          kept_of[b].entries.emplace_back(std::uint32_t(c), batch[column]);
          kept_of[b].values.push_back(w);
        }
  });
  // By cluster, batch after batch (a counting sort keeps the bones' increasing order).
  std::vector<std::uint32_t> count(n + 1, 0);
  for(const Kept& k : kept_of)
    for(const auto& e : k.entries)
      ++count[e.first + 1];
  for(std::size_t c = 0; c < n; ++c)
    count[c + 1] += count[c];
  out.first = count;
  out.bone.resize(count[n]);
  out.weight.resize(count[n]);
  for(const Kept& k : kept_of)
    for(std::size_t i = 0; i < k.entries.size(); ++i)
    {
      const std::uint32_t slot = count[k.entries[i].first]++;
      out.bone[slot] = k.entries[i].second;
      out.weight[slot] = k.values[i];
    }
  return true;
}

// A cluster's weight of one bone as a linear function around its centroid.
struct Linear_weight
{
  std::uint32_t bone;
  double weight;
  Vec3 gradient;
};

// The weights of each cluster as linear functions: those of cluster c are
// `weights[first[c]]` to `weights[first[c + 1] - 1]`.
struct Linear_cluster_weights
{
  std::vector<std::uint32_t> first;
  std::vector<Linear_weight> weights;
};

// Each cluster's weights (of `bones` bones) that reach `negligible` at one of its vertices
// (`points`), with their least-squares gradients (0 for a cluster of one vertex, its
// centroid), but not those under the `k`-th largest at every vertex of the cluster: they are
// never kept.
inline Linear_cluster_weights linear_cluster_weights(const std::vector<Vec3>& points, const Surface_clusters& clusters,
                                                     const Cluster_weights& cluster_weights, std::size_t bones,
                                                     std::size_t k, double negligible, unsigned threads)
{
  const std::size_t m = clusters.number_of_clusters();
  // The farthest vertex from the centroid, taken by parts of the vertices (a largest value
  // does not depend on the order).
  const std::size_t vertex_parts = index_parts(points.size(), threads);
  std::vector<std::vector<double>> part_reach(vertex_parts);
  for_each_part(points.size(), vertex_parts, threads, [&](std::size_t part, std::size_t begin, std::size_t end) {
    std::vector<double>& reach = part_reach[part];
    reach.assign(m, 0.);
    for(std::size_t v = begin; v < end; ++v)
    {
      const std::uint32_t c = clusters.cluster_of[v];
      reach[c] = std::max(reach[c], squared_distance3(points[v], clusters.centroid[c]));
    }
  });
  std::vector<double> reach = std::move(part_reach[0]);
  for(std::size_t part = 1; part < vertex_parts; ++part)
    for(std::size_t c = 0; c < m; ++c)
      reach[c] = std::max(reach[c], part_reach[part][c]);
  part_reach.clear();
  // The clusters in parts, one per thread, each its weights on its own, then joined in order.
  const std::size_t parts = index_parts(m, threads);
  std::vector<std::vector<Linear_weight>> part_weights(parts);
  Linear_cluster_weights out;
  out.first.assign(m + 1, 0);
  for_each_part(m, parts, threads, [&](std::size_t part, std::size_t begin_cluster, std::size_t end_cluster) {
    std::vector<Linear_weight>& linear = part_weights[part];
    std::vector<Vec3> k_of_neighbour, gradient;
    std::vector<double> at_neighbour(bones, 0.); // a neighbour's weights by bone, 0 where it has none
    std::vector<double> lowest;
    for(std::uint32_t c = std::uint32_t(begin_cluster); c < end_cluster; ++c)
    {
      const std::size_t first = linear.size();
      k_of_neighbour.clear();
      if(clusters.size[c] > 1)
        gradient_weights(clusters, c, k_of_neighbour);
      const double r = std::sqrt(reach[c]);
      const std::uint32_t* neighbour = clusters.neighbours.data() + clusters.first_neighbour[c];
      const std::uint32_t begin_weight = cluster_weights.first[c], end_weight = cluster_weights.first[c + 1];
      // The gradients a neighbour at a time, each summed over the neighbours in their order.
      gradient.assign(end_weight - begin_weight, Vec3{0, 0, 0});
      for(std::uint32_t j = 0; j < k_of_neighbour.size(); ++j)
      {
        const std::uint32_t q = neighbour[j];
        for(std::uint32_t t = cluster_weights.first[q]; t < cluster_weights.first[q + 1]; ++t)
          at_neighbour[cluster_weights.bone[t]] = cluster_weights.weight[t];
        for(std::uint32_t i = begin_weight; i < end_weight; ++i)
        {
          const double difference = at_neighbour[cluster_weights.bone[i]] - cluster_weights.weight[i];
          for(std::size_t x = 0; x < 3; ++x)
            gradient[i - begin_weight][x] += k_of_neighbour[j][x] * difference;
        }
        for(std::uint32_t t = cluster_weights.first[q]; t < cluster_weights.first[q + 1]; ++t)
          at_neighbour[cluster_weights.bone[t]] = 0.;
      }
      for(std::uint32_t i = begin_weight; i < end_weight; ++i)
        if(const double w = cluster_weights.weight[i]; w + norm3(gradient[i - begin_weight]) * r > negligible)
          linear.push_back({cluster_weights.bone[i], w, gradient[i - begin_weight]});
      const auto begin = linear.begin() + std::ptrdiff_t(first);
      if(std::size_t(linear.end() - begin) > k)
      {
        lowest.clear();
        for(auto it = begin; it != linear.end(); ++it)
          lowest.push_back(it->weight - norm3(it->gradient) * r);
        std::nth_element(lowest.begin(), lowest.begin() + std::ptrdiff_t(k - 1), lowest.end(), std::greater<double>());
        const double kth_lowest = lowest[k - 1];
        linear.erase(std::remove_if(begin, linear.end(),
                                    [&](const Linear_weight& lw) { return lw.weight + norm3(lw.gradient) * r < kth_lowest; }),
                     linear.end());
      }
      out.first[c + 1] = std::uint32_t(linear.size() - first); // a count, made an offset below
    }
  });
  for(std::size_t c = 0; c < m; ++c)
    out.first[c + 1] += out.first[c];
  out.weights.reserve(out.first[m]);
  for(const std::vector<Linear_weight>& linear : part_weights)
    out.weights.insert(out.weights.end(), linear.begin(), linear.end());
  return out;
}

// Diffuses the bones' heat over the surface and keeps, per vertex, the `k` largest weights
// (not yet normalised) of `bones` bones, with c = 1 (bone heat's). The heat is solved on
// the surface clustered in half-voxel cells (surface_clusters.h), each cluster heated by its
// source (`sources`, per cluster) in proportion to its area `areas` (square voxels); each
// vertex (`points`, grid coordinates) reads the weights of its cluster with their gradient
// there. Distances below `nearest_distance` voxels count as that (a cluster on a bone),
// areas below `smallest_area` square voxels as that (a cluster of degenerate triangles only,
// or of none, still feels its heat source). Each vertex's weights are then handed to
// `finish(v)`, by the thread that read them. Returns false when the factorisation fails (it
// should not: the matrix is positive definite), leaving `weights` untouched and `finish`
// uncalled. The solves and the loops over clusters and vertices run on up to `threads`
// threads, with the same result for any number.
template <typename Finish>
bool diffuse_bone_heat(const std::vector<Vec3>& points, const Surface_clusters& clusters,
                       const std::vector<double>& areas, const Heat_sources& sources, std::size_t bones, std::size_t k,
                       Heat_system& system, std::vector<Bone_weights>& weights, unsigned threads, const Finish& finish)
{
  constexpr double heat_constant = 1, nearest_distance = 0.1, smallest_area = 1e-6, negligible = 1e-4;
  const std::size_t m = clusters.number_of_clusters();
  std::vector<double> heat(m);
  for(std::size_t c = 0; c < m; ++c)
  {
    const double d = std::max(sources.distance[c], nearest_distance);
    heat[c] = heat_constant * std::max(areas[c], smallest_area) / (d * d);
  }
  Cluster_weights cluster_weights;
  // A cluster keeps weights well under what a vertex keeps: its gradient may raise them.
  if(!solve_cluster_heat(clusters, heat, sources, bones, 0.01 * negligible, system, cluster_weights, threads))
    return false;
  // The clusters' weights are few, the vertices many: each vertex reads its cluster's.
  const Linear_cluster_weights linear =
      linear_cluster_weights(points, clusters, cluster_weights, bones, k, negligible, threads);
  for_each_index(points.size(), threads, [&](std::size_t v) {
    const std::uint32_t c = clusters.cluster_of[v];
    const Vec3 offset = sub(points[v], clusters.centroid[c]);
    for(std::uint32_t i = linear.first[c]; i < linear.first[c + 1]; ++i)
    {
      const Linear_weight& lw = linear.weights[i];
      if(const double at_v = std::min(1., lw.weight + dot3(lw.gradient, offset)); at_v > negligible)
        keep_largest(weights[v], k, lw.bone, float(at_v));
    }
    finish(v);
  });
  return true;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_SURFACE_HEAT_H
