// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_BONE_WEIGHTS_H
#define CGAL_GEODESIC_SKELETON_BONE_WEIGHTS_H

/// \file Bone_weights.h
/// The skinning weights of one mesh vertex: a few (bone, weight) pairs.

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The skinning weights of one mesh vertex: at most `capacity` (8) pairs of a bone (an
/// number, see `numbered_bones()`) and its weight, by decreasing weight. The value
/// type of the `weight_output` property map of `compute_skinning_weights()`: a fixed-size
/// object (no allocation per vertex, 68 bytes). Weights are `float`, the precision of glTF.
struct Bone_weights
{
  /// The most pairs a vertex can hold.
  static constexpr std::size_t capacity = 8;

  /// The bones, `bone[0 .. size())` meaningful.
  std::array<std::uint32_t, capacity> bone{};
  /// Their weights, non-negative, in the same order.
  std::array<float, capacity> weight{};

  /// The number of pairs.
  std::size_t size() const { return m_size; }
  /// Whether there is no pair.
  bool empty() const { return m_size == 0; }
  /// Removes every pair.
  void clear() { m_size = 0; }
  /// Appends a pair. \throws std::length_error when `capacity` pairs are held already.
  void push_back(std::uint32_t b, float w)
  {
    if(m_size == capacity)
      throw std::length_error("Bone_weights: a vertex holds at most 8 bones");
    bone[m_size] = b;
    weight[m_size] = w;
    ++m_size;
  }
  /// The sum of the weights (1 for the output of `compute_skinning_weights()`, up to rounding).
  double total() const
  {
    double sum = 0;
    for(std::size_t i = 0; i < m_size; ++i)
      sum += weight[i];
    return sum;
  }

private:
  std::uint8_t m_size = 0;
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_BONE_WEIGHTS_H
