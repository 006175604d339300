// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SIMPLE_POINT_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SIMPLE_POINT_H

#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <array>
#include <bitset>
#include <cstdint>
#include <cstdlib>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Number of set bits of a neighbourhood mask.
inline int bit_count(std::uint32_t mask) { return int(std::bitset<32>(mask).count()); }

// Index of the lowest set bit of a non-zero mask.
inline int lowest_bit(std::uint32_t mask)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctz(mask);
#else
  int i = 0;
  while(!(mask & 1u))
  {
    mask >>= 1;
    ++i;
  }
  return i;
#endif
}

// The simple-point test of digital topology with 26-connectivity for the object and
// 6-connectivity for the background (Bertrand and Malandain 1994): a voxel x of the
// object X is simple, i.e. removing it changes neither the components, nor the cavities,
// nor the tunnels, iff
//   T26(x, X)  = number of 26-components of X ∩ N26*(x)                       = 1, and
//   T6(x, ~X)  = number of 6-components of ~X ∩ N18*(x) 6-adjacent to x       = 1.
// A configuration is the 26-bit mask of the object in N26*(x), bit i for the neighbour
// neighbourhood_26()[i]. Components are grown on the masks with precomputed adjacency
// masks, so a test costs at most 26 + 18 mask steps: constant time, no table of 2^26.
class Simple_point_test
{
public:
  static const Simple_point_test& instance()
  {
    static const Simple_point_test test;
    return test;
  }

  bool is_simple(std::uint32_t object) const
  {
    if(object == 0)
      return false; // an isolated voxel: removing it removes a component
    const std::uint32_t background18 = ~object & m_n18;
    const std::uint32_t background_faces = background18 & m_faces;
    if(background_faces == 0)
      return false; // an interior voxel: removing it makes a cavity
    // T6: the 6-component of the background in N18* grown from one face neighbour must
    // hold every background face neighbour.
    if(!grow(background_faces & (~background_faces + 1u), background18, m_adjacent6,
             background_faces))
      return false;
    // T26: the object in N26* is one 26-component.
    return grow(object & (~object + 1u), object, m_adjacent26, object);
  }

  // T6(x, ~X) = 1: the background in N18*(x) 6-adjacent to x is one 6-component. False
  // for a voxel without background face neighbour (its removal would open a cavity), and
  // where its removal would open a tunnel.
  bool background_is_one_piece(std::uint32_t object) const
  {
    const std::uint32_t background18 = ~object & m_n18;
    const std::uint32_t background_faces = background18 & m_faces;
    return background_faces != 0 && grow(background_faces & (~background_faces + 1u), background18,
                                         m_adjacent6, background_faces);
  }

  // T26(x, X) >= 2: the object in N26*(x) falls into two 26-components or more.
  bool object_is_split(std::uint32_t object) const
  {
    return object != 0 && !grow(object & (~object + 1u), object, m_adjacent26, object);
  }

  // Whether bit i is a face neighbour.
  std::uint32_t face_mask() const { return m_faces; }

private:
  Simple_point_test()
  {
    const auto& n = neighbourhood_26();
    for(int i = 0; i < 26; ++i)
    {
      if(offset_order(n[i]) == 1)
        m_faces |= 1u << i;
      if(offset_order(n[i]) <= 2)
        m_n18 |= 1u << i;
      for(int j = 0; j < 26; ++j)
      {
        if(i == j || !are_26_adjacent(n[i], n[j]))
          continue;
        m_adjacent26[i] |= 1u << j;
        const int manhattan = std::abs(n[i].x - n[j].x) + std::abs(n[i].y - n[j].y) +
                              std::abs(n[i].z - n[j].z);
        if(manhattan == 1 && offset_order(n[i]) <= 2 && offset_order(n[j]) <= 2)
          m_adjacent6[i] |= 1u << j;
      }
    }
  }

  // Grows the component of `seed` inside `set` along `adjacent`; returns whether it covers
  // `must_reach` (stops as soon as it does).
  static bool grow(std::uint32_t seed, std::uint32_t set, const std::array<std::uint32_t, 26>& adjacent,
                   std::uint32_t must_reach)
  {
    std::uint32_t component = seed, frontier = seed;
    while(frontier != 0)
    {
      if((component & must_reach) == must_reach)
        return true;
      std::uint32_t next = 0;
      while(frontier != 0)
      {
        const int i = lowest_bit(frontier);
        frontier &= frontier - 1;
        next |= adjacent[i];
      }
      frontier = next & set & ~component;
      component |= frontier;
    }
    return (component & must_reach) == must_reach;
  }

  std::uint32_t m_faces = 0, m_n18 = 0;
  std::array<std::uint32_t, 26> m_adjacent26{}, m_adjacent6{};
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SIMPLE_POINT_H
