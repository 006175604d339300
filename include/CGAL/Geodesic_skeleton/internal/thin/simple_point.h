// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_SIMPLE_POINT_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_SIMPLE_POINT_H

#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <array>
#include <cstdint>
#include <cstdlib>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// Number of set bits of a neighbourhood mask (by halves, quarters, ...: without a library
// call where the target has no popcount instruction).
inline int bit_count(std::uint32_t mask)
{
  mask = mask - ((mask >> 1) & 0x55555555u);
  mask = (mask & 0x33333333u) + ((mask >> 2) & 0x33333333u);
  mask = (mask + (mask >> 4)) & 0x0F0F0F0Fu;
  return int((mask * 0x01010101u) >> 24);
}

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
// neighbourhood_26()[i]. The tests grow components on the 3 x 3 x 3 cube as a 27-bit mask
// (bit dx + 3 dy + 9 dz for the offset (dx, dy, dz) + 1), where one step of growth along
// all neighbours is a handful of shifts: a test costs a few such steps, constant time, no
// table of 2^26.
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
    const std::uint32_t cube = to_cube(object);
    const std::uint32_t background18 = ~cube & n18;
    const std::uint32_t background_faces = background18 & faces;
    if(background_faces == 0)
      return false; // an interior voxel: removing it makes a cavity
    // T6: the 6-component of the background in N18* grown from one face neighbour must
    // hold every background face neighbour.
    if(!grows_to(background_faces & (~background_faces + 1u), background18, background_faces, grow6))
      return false;
    // T26: the object in N26* is one 26-component.
    return grows_to(cube & (~cube + 1u), cube, cube, grow26);
  }

  // T6(x, ~X) = 1: the background in N18*(x) 6-adjacent to x is one 6-component. False
  // for a voxel without background face neighbour (its removal would open a cavity), and
  // where its removal would open a tunnel.
  bool background_is_one_piece(std::uint32_t object) const
  {
    const std::uint32_t background18 = ~to_cube(object) & n18;
    const std::uint32_t background_faces = background18 & faces;
    return background_faces != 0 &&
           grows_to(background_faces & (~background_faces + 1u), background18, background_faces, grow6);
  }

  // T26(x, X) >= 2: the object in N26*(x) falls into two 26-components or more.
  bool object_is_split(std::uint32_t object) const
  {
    const std::uint32_t cube = to_cube(object);
    return cube != 0 && !grows_to(cube & (~cube + 1u), cube, cube, grow26);
  }

  // Whether x stays simple whatever subset of its neighbours in P is deleted with it
  // (a P-simple point, Bertrand 1995), for `object` the configuration of X and `in_p` that
  // of P (a subset of `object`). The local characterization, with X \ P the object kept:
  //   1. the kept object in N26*(x) is one 26-component;
  //   2. T6(x, ~X) = 1;
  //   3. every neighbour in P is 26-adjacent to a kept neighbour;
  //   4. every face neighbour y in P keeps T6(x, ~X ∪ {y}) = 1.
  // All P-simple points of P can be deleted at once without changing the topology, and
  // which of them are P-simple does not depend on any order.
  bool is_p_simple(std::uint32_t object, std::uint32_t in_p) const
  {
    const std::uint32_t kept = to_cube(object & ~in_p), p = to_cube(in_p);
    if(kept == 0 || !grows_to(kept & (~kept + 1u), kept, kept, grow26) || (grow26(kept) & p) != p)
      return false;
    // The background's 6-component in N18* that holds a face neighbour: condition 2 holds
    // iff it holds them all; then a face neighbour y in P keeps one component 6-adjacent to
    // x iff y touches it (y itself is 6-adjacent to x, so alone it would be a second one).
    const std::uint32_t cube = to_cube(object), background18 = ~cube & n18;
    const std::uint32_t background_faces = background18 & faces;
    if(background_faces == 0)
      return false;
    const std::uint32_t component = grown_component(background_faces & (~background_faces + 1u), background18, grow6);
    if((component & background_faces) != background_faces)
      return false;
    for(std::uint32_t face = p & faces; face != 0; face &= face - 1)
      if((grow6(face & (~face + 1u)) & component) == 0)
        return false;
    return true;
  }

private:
  Simple_point_test() = default;

  // Masks of the cube: every voxel; those not at x = 0, not at x = 2 (then y), where a
  // shift by one step along +x, -x (then y) may land; the 18-neighbourhood and the 6 face
  // neighbours of the centre (bit 13, never set in a configuration).
  static constexpr std::uint32_t all = (1u << 27) - 1;
  static constexpr std::uint32_t at_x0 = 0x1249249u;              // bits 0, 3, 6, ..., 24
  static constexpr std::uint32_t at_y0 = 0x01C0E07u;              // bits 0-2, 9-11, 18-20
  static constexpr std::uint32_t not_x0 = all & ~at_x0, not_x2 = all & ~(at_x0 << 2);
  static constexpr std::uint32_t not_y0 = all & ~at_y0, not_y2 = all & ~(at_y0 << 6);
  static constexpr std::uint32_t corners = (1u << 0) | (1u << 2) | (1u << 6) | (1u << 8) | (1u << 18) |
                                           (1u << 20) | (1u << 24) | (1u << 26);
  static constexpr std::uint32_t n18 = all & ~corners & ~(1u << 13);
  static constexpr std::uint32_t faces = (1u << 4) | (1u << 10) | (1u << 12) | (1u << 14) | (1u << 16) | (1u << 22);

  // A configuration (26 bits in neighbourhood_26() order) as a cube mask: the centre's bit
  // 13 inserted.
  static std::uint32_t to_cube(std::uint32_t object) { return (object & 0x1FFFu) | ((object & ~0x1FFFu) << 1); }

  // One growth step: the set and its 6-neighbours (grow6), or its 26-neighbours (grow26),
  // inside the cube.
  static std::uint32_t grow6(std::uint32_t s)
  {
    return s | ((s << 1) & not_x0) | ((s >> 1) & not_x2) | ((s << 3) & not_y0) | ((s >> 3) & not_y2) |
           ((s << 9) & all) | (s >> 9);
  }
  static std::uint32_t grow26(std::uint32_t s)
  {
    s |= ((s << 1) & not_x0) | ((s >> 1) & not_x2);
    s |= ((s << 3) & not_y0) | ((s >> 3) & not_y2);
    return s | ((s << 9) & all) | (s >> 9);
  }

  // The whole component of `seed` inside `set`.
  template <typename Grow>
  static std::uint32_t grown_component(std::uint32_t seed, std::uint32_t set, Grow grow)
  {
    for(std::uint32_t component = seed;;)
    {
      const std::uint32_t grown = grow(component) & set;
      if(grown == component)
        return component;
      component = grown;
    }
  }

  // Grows the component of `seed` inside `set`; returns whether it covers `must_reach`
  // (stops as soon as it does, or when it stops growing).
  template <typename Grow>
  static bool grows_to(std::uint32_t seed, std::uint32_t set, std::uint32_t must_reach, Grow grow)
  {
    std::uint32_t component = seed;
    while((component & must_reach) != must_reach)
    {
      const std::uint32_t grown = grow(component) & set;
      if(grown == component)
        return false;
      component = grown;
    }
    return true;
  }
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_SIMPLE_POINT_H
