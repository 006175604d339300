// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_VOXEL_COMPONENTS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_VOXEL_COMPONENTS_H

// The 26-connected components of a list of voxels, for the curve skeletons (the pieces
// that remove_small_pieces() and prune_skeleton() measure, the branched regions of
// prune_skeleton()). A solid, with far more voxels, is searched over its box
// (solid_piece_sizes() in remove_small_pieces.h).

#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <algorithm>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The 26-connected components of the voxels `keys` (each listed once): a label per key, in
// that order, and the number of components. Labels are numbered in the order of each
// component's first key in `keys`. `contains(k)` tells whether voxel `k` is one of `keys`
// (a set's own membership test, often faster than a search of `keys`).
//
// Complexity: O(K log K) for K keys.
template <typename Contains>
std::size_t voxel_components(const std::vector<Voxel_key>& keys, const Contains& contains,
                             std::vector<std::size_t>& label)
{
  std::vector<std::size_t> order(keys.size());
  for(std::size_t i = 0; i < keys.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  auto position = [&](const Voxel_key& k) {
    const auto it = std::lower_bound(order.begin(), order.end(), k,
                                     [&](std::size_t i, const Voxel_key& key) { return keys[i] < key; });
    return *it;
  };
  const std::size_t none = std::size_t(-1);
  label.assign(keys.size(), none);
  std::size_t components = 0;
  std::vector<std::size_t> stack;
  for(std::size_t start = 0; start < keys.size(); ++start)
  {
    if(label[start] != none)
      continue;
    label[start] = components;
    stack.push_back(start);
    while(!stack.empty())
    {
      const std::size_t i = stack.back();
      stack.pop_back();
      for(const Voxel_key& o : neighbourhood_26())
      {
        const Voxel_key n = keys[i] + o;
        if(!contains(n))
          continue;
        const std::size_t j = position(n);
        if(label[j] == none)
        {
          label[j] = components;
          stack.push_back(j);
        }
      }
    }
    ++components;
  }
  return components;
}

// The 26-connected components of `points`, each sorted by key, listed in the order of
// their smallest keys (deterministic).
inline std::vector<std::vector<Voxel_key>> voxel_components(std::vector<Voxel_key> points)
{
  std::sort(points.begin(), points.end());
  std::vector<std::size_t> label;
  const std::size_t count = voxel_components(
      points, [&](const Voxel_key& k) { return std::binary_search(points.begin(), points.end(), k); }, label);
  std::vector<std::vector<Voxel_key>> components(count);
  for(std::size_t i = 0; i < points.size(); ++i)
    components[label[i]].push_back(points[i]); // in key order, as `points` is sorted
  return components;
}

// The largest `radius(k)` over each 26-connected piece of the voxel set `skeleton` (with
// `for_each()` and `contains()`), recorded for every voxel. Complexity: that of
// voxel_components(), plus K radius reads and K expected hash insertions.
template <typename VoxelSet, typename Radius>
std::unordered_map<Voxel_key, double, Voxel_key_hash> largest_radius_of_pieces(const VoxelSet& skeleton,
                                                                               const Radius& radius)
{
  std::vector<Voxel_key> keys;
  skeleton.for_each([&](const Voxel_key& k) { keys.push_back(k); });
  std::vector<std::size_t> piece;
  const std::size_t pieces = voxel_components(keys, [&](const Voxel_key& k) { return skeleton.contains(k); }, piece);
  std::vector<double> largest(pieces, 0.0);
  for(std::size_t i = 0; i < keys.size(); ++i)
    largest[piece[i]] = (std::max)(largest[piece[i]], radius(keys[i]));
  std::unordered_map<Voxel_key, double, Voxel_key_hash> of_voxel;
  of_voxel.reserve(keys.size());
  for(std::size_t i = 0; i < keys.size(); ++i)
    of_voxel.emplace(keys[i], largest[piece[i]]);
  return of_voxel;
}

// Whether the voxels of `keys` are 26-connected among themselves.
inline bool are_26_connected(const std::vector<Voxel_key>& keys)
{
  if(keys.empty())
    return true;
  std::vector<bool> reached(keys.size(), false);
  std::vector<std::size_t> stack{0};
  reached[0] = true;
  std::size_t count = 1;
  while(!stack.empty())
  {
    const std::size_t a = stack.back();
    stack.pop_back();
    for(std::size_t b = 0; b < keys.size(); ++b)
      if(!reached[b] && are_26_adjacent(keys[a], keys[b]))
      {
        reached[b] = true;
        ++count;
        stack.push_back(b);
      }
  }
  return count == keys.size();
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_VOXEL_COMPONENTS_H
