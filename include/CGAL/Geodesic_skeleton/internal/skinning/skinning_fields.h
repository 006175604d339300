// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_FIELDS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_FIELDS_H

// The machinery of compute_skinning_weights(): the solid voxels indexed compactly, the
// bones rasterised into them, geodesic distance fields through them (Dijkstra, 26
// neighbours, steps 1, sqrt 2, sqrt 3, in voxels), and the fields read at the surface
// clusters through the eight voxel centres around each cluster's centroid.

#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Distances through the voxels are integers, in hundredths of a voxel: the steps to the 26
// neighbours are 100, 141 and 173 (1, sqrt 2 and sqrt 3 to 0.3 %), so that the searches can
// use a bucket queue (Dial's algorithm: O(1) per step) instead of a heap.
using Voxel_distance = std::uint32_t;
constexpr Voxel_distance unreached = std::numeric_limits<Voxel_distance>::max();
constexpr double voxels_per_unit = 0.01;
constexpr std::size_t longest_step = 173;

// The solid voxels of a grid, numbered 0..n-1, in a dense layout of the solid's box grown
// by one voxel, so that every solid voxel has its 26 neighbours in the layout.
struct Solid_voxels
{
  Grid_layout layout;
  std::vector<std::int32_t> solid_of_cell;  // -1 for a cell outside the solid
  std::vector<std::uint32_t> cell_of_solid; // the inverse
  std::array<std::ptrdiff_t, 26> offsets{};
  std::array<Voxel_distance, 26> steps{};

  explicit Solid_voxels(const Dense_voxel_grid& grid) : layout(grid.bounding_box().grown(1))
  {
    solid_of_cell.assign(layout.volume(), -1);
    cell_of_solid.reserve(grid.size());
    grid.for_each([&](const Voxel_key& k) {
      const std::size_t cell = layout.index(k);
      solid_of_cell[cell] = std::int32_t(cell_of_solid.size());
      cell_of_solid.push_back(std::uint32_t(cell));
    });
    offsets = layout.neighbour_offsets();
    for(std::size_t i = 0; i < 26; ++i)
      steps[i] = Voxel_distance(std::lround(100 * std::sqrt(double(offset_order(neighbourhood_26()[i])))));
  }
  std::size_t size() const { return cell_of_solid.size(); }
  // The solid voxel of `k`, or -1 (also for a key outside the layout).
  std::int32_t solid(const Voxel_key& k) const
  {
    return layout.box.contains(k) ? solid_of_cell[layout.index(k)] : -1;
  }
};

// The buckets of voxel_dijkstra(), kept from one search to the next: bucket d % ring holds
// the voxels inserted at distance d; every step is shorter than the ring, so the buckets
// ahead never wrap onto the current one.
struct Bucket_queue
{
  static constexpr std::size_t ring = longest_step + 1;
  std::array<std::vector<std::uint32_t>, ring> buckets;
  std::vector<std::uint32_t> current;
};

// Multi-source Dijkstra from `seeds` (distance 0) through the solid voxels, with a bucket
// queue (empty on entry and on return). `distance` has one entry per solid voxel, all `unreached` on entry: the voxels this
// call reaches are appended to `reached` (the caller resets them). A settled voxel u of
// distance d is expanded only when `expand(u, d)` holds.
template <typename Expand>
void voxel_dijkstra(const Solid_voxels& solid, const std::vector<std::uint32_t>& seeds,
                    std::vector<Voxel_distance>& distance, std::vector<std::uint32_t>& reached,
                    Bucket_queue& queue, Expand expand)
{
  constexpr std::size_t ring = Bucket_queue::ring;
  auto& buckets = queue.buckets;
  std::vector<std::uint32_t>& current = queue.current;
  std::size_t pending = 0;
  for(std::uint32_t s : seeds)
    if(distance[s] != 0)
    {
      if(distance[s] == unreached)
        reached.push_back(s);
      distance[s] = 0;
      buckets[0].push_back(s);
      ++pending;
    }
  for(Voxel_distance d = 0; pending > 0; ++d)
  {
    std::vector<std::uint32_t>& bucket = buckets[d % ring];
    current.swap(bucket);
    bucket.clear();
    pending -= current.size();
    for(std::uint32_t u : current)
    {
      if(distance[u] != d || !expand(u, d))
        continue; // a stale entry (the voxel was reached by a shorter path), or a voxel the field stops at
      const std::size_t cell = solid.cell_of_solid[u];
      for(std::size_t n = 0; n < 26; ++n)
      {
        const std::int32_t v = solid.solid_of_cell[std::size_t(std::ptrdiff_t(cell) + solid.offsets[n])];
        if(v < 0)
          continue;
        const Voxel_distance dv = d + solid.steps[n];
        if(dv < distance[std::size_t(v)])
        {
          if(distance[std::size_t(v)] == unreached)
            reached.push_back(std::uint32_t(v));
          distance[std::size_t(v)] = dv;
          buckets[dv % ring].push_back(std::uint32_t(v));
          ++pending;
        }
      }
    }
    current.clear();
  }
}

// The vector to `p` from the point of `polyline` (at least one point) nearest to it.
inline Vec3 offset_from_polyline(const Vec3& p, const std::vector<Vec3>& polyline)
{
  Vec3 best = sub(p, polyline.front());
  double best_length = dot3(best, best);
  for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
    if(const Vec3 o = sub(p, closest_point_on_segment(p, polyline[i], polyline[i + 1])); dot3(o, o) < best_length)
    {
      best = o;
      best_length = dot3(o, o);
    }
  return best;
}

// The distance from `p` to a polyline of at least one point.
inline double distance_to_polyline(const Vec3& p, const std::vector<Vec3>& polyline)
{
  return norm3(offset_from_polyline(p, polyline));
}

// The voxels of `solid` that a polyline (grid coordinates) runs through, sampled every
// quarter voxel; when it runs through none (a bone outside the mesh), the solid voxel whose
// centre is nearest to it.
inline std::vector<std::uint32_t> rasterize_polyline(const Solid_voxels& solid, const std::vector<Vec3>& polyline)
{
  std::vector<std::uint32_t> voxels;
  auto add = [&](const Vec3& g) {
    const std::int32_t s = solid.solid(cell_of(g));
    if(s >= 0)
      voxels.push_back(std::uint32_t(s));
  };
  add(polyline.front());
  for(std::size_t i = 0; i + 1 < polyline.size(); ++i)
  {
    const Vec3 d = sub(polyline[i + 1], polyline[i]);
    const std::size_t samples = std::size_t(std::ceil(norm3(d) * 4)) + 1;
    for(std::size_t j = 1; j <= samples; ++j)
    {
      const double t = double(j) / double(samples);
      add(Vec3{polyline[i][0] + t * d[0], polyline[i][1] + t * d[1], polyline[i][2] + t * d[2]});
    }
  }
  std::sort(voxels.begin(), voxels.end());
  voxels.erase(std::unique(voxels.begin(), voxels.end()), voxels.end());
  if(!voxels.empty())
    return voxels;
  double best = HUGE_VAL;
  std::uint32_t nearest = 0;
  for(std::uint32_t s = 0; s < solid.size(); ++s)
  {
    const Voxel_key k = solid.layout.key(solid.cell_of_solid[s]);
    const double d = distance_to_polyline(Vec3{k.x + 0.5, k.y + 0.5, k.z + 0.5}, polyline);
    if(d < best)
    {
      best = d;
      nearest = s;
    }
  }
  voxels.push_back(nearest);
  return voxels;
}

// Points (the surface clusters' centroids) grouped by the cell of voxel centres they lie
// in: the cell of base b has the centres of the voxels b + {0, 1}^3 at its corners. A
// distance field known at the voxel centres is read at a point as the least (value at a
// corner + distance from the point to that corner), over the corners that have a value.
// Only the cells that hold points are numbered (their slots), and each solid voxel knows
// the slots it is a corner of: nothing is as large as the grid's box, which is most of the
// cost for a small mesh.
struct Point_cells
{
  std::vector<Vec3> grid_point;          // each point in grid coordinates
  std::vector<std::uint32_t> cell;       // per slot: the base cell (layout index), ascending
  std::vector<std::uint32_t> first;      // per slot: its points in `points[first[s] .. first[s + 1])`
  std::vector<std::uint32_t> points;     // point indices, grouped by slot
  std::vector<std::uint32_t> outside;    // points whose cell is not inside the layout
  std::vector<std::uint32_t> first_slot; // per solid voxel: its slots in `slots[first_slot[u] .. first_slot[u + 1])`
  std::vector<std::uint32_t> slots;
  std::array<std::ptrdiff_t, 8> corner_offsets{};
  std::array<Vec3, 8> corner_centre{};   // the corners' centres relative to the base voxel's corner

  Point_cells(const Solid_voxels& solid, std::vector<Vec3> points_in_grid) : grid_point(std::move(points_in_grid))
  {
    const Grid_layout& layout = solid.layout;
    for(int i = 0; i < 8; ++i)
    {
      const int dx = i & 1, dy = (i >> 1) & 1, dz = (i >> 2) & 1;
      corner_offsets[std::size_t(i)] = dx + dy * layout.stride_y + dz * layout.stride_z;
      corner_centre[std::size_t(i)] = Vec3{dx + 0.5, dy + 0.5, dz + 0.5};
    }
    // The points by base cell, in index order within a cell.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by_cell;
    by_cell.reserve(grid_point.size());
    for(std::size_t v = 0; v < grid_point.size(); ++v)
    {
      // The cell of centres is the voxel cell of the point moved by half a voxel (the mesh's
      // extreme vertices lie on such cell boundaries: the grid's box is placed by them).
      const Vec3& g = grid_point[v];
      const Voxel_key k = cell_of(Vec3{g[0] - 0.5, g[1] - 0.5, g[2] - 0.5});
      if(layout.box.contains(k) && k.x + 1 < layout.box.max.x && k.y + 1 < layout.box.max.y &&
         k.z + 1 < layout.box.max.z)
        by_cell.emplace_back(std::uint32_t(layout.index(k)), std::uint32_t(v));
      else
        outside.push_back(std::uint32_t(v));
    }
    std::sort(by_cell.begin(), by_cell.end());
    points.reserve(by_cell.size());
    for(std::size_t i = 0; i < by_cell.size(); ++i)
    {
      if(i == 0 || by_cell[i].first != by_cell[i - 1].first)
      {
        cell.push_back(by_cell[i].first);
        first.push_back(std::uint32_t(i));
      }
      points.push_back(by_cell[i].second);
    }
    first.push_back(std::uint32_t(by_cell.size()));
    // The slots of each solid voxel.
    first_slot.assign(solid.size() + 1, 0);
    for_each_corner_voxel(solid, [&](std::uint32_t, std::uint32_t u) { ++first_slot[u + 1]; });
    for(std::size_t u = 0; u < solid.size(); ++u)
      first_slot[u + 1] += first_slot[u];
    slots.resize(first_slot.back());
    std::vector<std::uint32_t> next(first_slot.begin(), first_slot.end() - 1);
    for_each_corner_voxel(solid, [&](std::uint32_t slot, std::uint32_t u) { slots[next[u]++] = slot; });
  }

  std::size_t number_of_slots() const { return cell.size(); }

  // Calls f(point, value) for every point of slot `slot` at which the field `distance`
  // (per solid voxel) has a value, that value in voxels.
  template <typename Function>
  void read_slot(const Solid_voxels& solid, std::uint32_t slot, const std::vector<Voxel_distance>& distance,
                 Function f) const
  {
    const std::size_t base = cell[slot];
    std::array<double, 8> corner;
    bool any = false;
    for(std::size_t i = 0; i < 8; ++i)
    {
      const std::int32_t s = solid.solid_of_cell[std::size_t(std::ptrdiff_t(base) + corner_offsets[i])];
      const bool has_value = s >= 0 && distance[std::size_t(s)] != unreached;
      corner[i] = has_value ? distance[std::size_t(s)] * voxels_per_unit : HUGE_VAL;
      any = any || has_value;
    }
    if(!any)
      return;
    const Voxel_key b = solid.layout.key(base);
    for(std::uint32_t k = first[slot]; k < first[slot + 1]; ++k)
    {
      const std::uint32_t v = points[k];
      const Vec3 local{grid_point[v][0] - b.x, grid_point[v][1] - b.y, grid_point[v][2] - b.z};
      double best = HUGE_VAL;
      for(std::size_t i = 0; i < 8; ++i)
        if(corner[i] != HUGE_VAL)
          best = std::min(best, corner[i] + norm3(sub(local, corner_centre[i])));
      f(v, best);
    }
  }

private:
  // f(slot, u) for each solid corner voxel u of each slot's cell.
  template <typename Function>
  void for_each_corner_voxel(const Solid_voxels& solid, Function f) const
  {
    for(std::uint32_t slot = 0; slot < cell.size(); ++slot)
      for(std::ptrdiff_t offset : corner_offsets)
        if(const std::int32_t u = solid.solid_of_cell[std::size_t(std::ptrdiff_t(cell[slot]) + offset)]; u >= 0)
          f(slot, std::uint32_t(u));
  }
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SKINNING_FIELDS_H
