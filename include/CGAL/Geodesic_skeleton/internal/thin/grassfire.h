// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_THIN_GRASSFIRE_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_THIN_GRASSFIRE_H

// The machinery of thin() (include/CGAL/Geodesic_skeleton/thin.h): not part of the API.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/thin/simple_point.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The ridge thresholds of the thinning's tip protection (Grassfire::on_ridge(): the largest
// growth of the MAT radius per unit step away from an end point that keeps it a tip). When
// a round's candidates are chosen, 0.6: a tip tapering at up to 37 degrees keeps its
// branch, the medial sheets of edges (0.71 per step along a right angle's bisector) burn.
// When a candidate is deleted, 0.3: only an end point on a plateau of the distance, which
// the round's own deletions exposed at a corner of the shape, goes.
constexpr double tip_growth_when_choosing = 0.6;
constexpr double tip_growth_when_deleting = 0.3;
// How far on_ridge() looks for a larger medial ball, in steps along each of the 26
// directions: two steps smooth the rounding of the discrete radii, which one step alone
// would take for growth or for its absence.
constexpr std::ptrdiff_t ridge_reach_in_steps = 2;
// How much deeper than its neighbour a stair step of a thin part may be and still burn at
// the neighbour's level (burning_level()), in voxels: the sqrt(2) - 1 of a sheet two
// voxels thick, or the sqrt(5) - 2 of one four voxels thick, not the full voxel between
// the layers of a thicker part.
constexpr double stair_step_depth = 0.5;

// The lengths of the steps to the 26 neighbours (1, sqrt 2, sqrt 3), in the order of
// neighbourhood_26().
inline std::array<double, 26> neighbour_step_lengths()
{
  std::array<double, 26> lengths{};
  const auto& n = neighbourhood_26();
  for(std::size_t b = 0; b < 26; ++b)
    lengths[b] = std::sqrt(double(offset_order(n[b])));
  return lengths;
}

// Whether the medial ball of voxel i (squared distances `d2` over a layout whose neighbour
// offsets are `offsets` and whose box reaches ridge_reach_in_steps beyond i) is not
// swallowed by a neighbour's: no voxel q one or two steps away along the 26 directions (two
// steps smooth the discrete radii) has r(q) >= r(i) + growth |q - i| (a centre of maximal
// ball, up to the discreteness of the distance field). Along the bisector of a right-angled
// edge the radius grows by 0.71 per unit step, so at growth 0.6 the medial sheets of edges
// and of blunt ends (wider than 2 x 37 degrees) are swallowed; tips tapering at up to 37
// degrees are not.
inline bool centre_of_maximal_ball(const std::uint32_t* d2, std::size_t i, const std::array<std::ptrdiff_t, 26>& offsets,
                                   const std::array<double, 26>& step_lengths, double growth)
{
  const double r = std::sqrt(double(d2[i]));
  for(std::size_t b = 0; b < 26; ++b)
    for(std::ptrdiff_t step = 1; step <= ridge_reach_in_steps; ++step)
    {
      const std::uint32_t dq = d2[std::size_t(std::ptrdiff_t(i) + step * offsets[b])];
      if(dq > d2[i] && std::sqrt(double(dq)) - r >= growth * double(step) * step_lengths[b])
        return false;
    }
  return true;
}

// The largest squared distance of a voxel in a thin part of MAT radius up to `radius`
// voxels (`thin()`'s thin_part_radius; sqrt(2) gives 2, a part about two voxels thick).
inline std::uint32_t thin_part_d2(double radius)
{
  return std::uint32_t(std::floor(radius * radius + 1e-9));
}

// Whether voxel i (of squared distances `d2`, 26 neighbours at `offsets`) is in a thin
// part: it and its 26 neighbours are within sqrt(largest_thin_d2) of the outside (a thin
// sheet, or a tube or an edge as thin; largest_thin_d2 from thin_part_d2()).
inline bool in_thin_part(const std::uint32_t* d2, std::size_t i, const std::array<std::ptrdiff_t, 26>& offsets,
                         std::uint32_t largest_thin_d2)
{
  if(d2[i] > largest_thin_d2)
    return false;
  for(std::ptrdiff_t o : offsets)
    if(d2[std::size_t(std::ptrdiff_t(i) + o)] > largest_thin_d2)
      return false;
  return true;
}

// The level at which the thinning burns a voxel of squared distance d2[i]: d2[i], except
// on the stair steps of a thin slanted sheet. A sheet two voxels thick and slightly
// tilted to the grid is three voxels thick along each line where its layers shift by
// one, and the middle voxels there are at sqrt(2) from the outside, the rest at 1: those
// lines would burn last, as ridges, and keep chains across the sheet that have nothing
// to do with its shape. A thicker thin part (a larger thin_part_radius: the same sheet on
// a finer grid) has the same steps between its middle voxels at 2 and at sqrt(5). A voxel
// of a thin part with no deeper neighbour (a stair step, not the way into a thicker part)
// burns with the sheet, at the level of its deepest shallower neighbour when that is less
// than stair_step_depth shallower.
inline std::uint32_t burning_level(const std::uint32_t* d2, std::size_t i,
                                   const std::array<std::ptrdiff_t, 26>& offsets, std::uint32_t largest_thin_d2)
{
  const std::uint32_t level = d2[i];
  if(level < 2 || level > largest_thin_d2)
    return level;
  // No neighbour deeper than i (so i is in a thin part too), and sqrt(level) - sqrt(q) <
  // stair_step_depth without a square root per neighbour.
  const double step_floor = std::sqrt(double(level)) - stair_step_depth;
  const double shallowest_step_d2 = step_floor * step_floor;
  std::uint32_t step_level = 0;
  for(std::ptrdiff_t o : offsets)
  {
    const std::uint32_t q = d2[std::size_t(std::ptrdiff_t(i) + o)];
    if(q > level)
      return level;
    if(q < level && double(q) > shallowest_step_d2)
      step_level = (std::max)(step_level, q);
  }
  return step_level > 0 ? step_level : level;
}

// The working state of the thinning over a padded box: bit 0 = in the set, bit 1 = queued,
// bit 2 = deleted by the thinning, bit 3 = a candidate of the round (delete_p_simple());
// and, when asked for, the round of its level in which each deleted voxel went
// (sheet_radius()): 2 bytes more per voxel of the box.
class Grassfire
{
public:
  static constexpr std::uint8_t IN = 1, QUEUED = 2, DELETED = 4, CANDIDATE = 8;

  Grassfire(const Grid_layout& layout, std::vector<std::uint8_t> state, const std::uint32_t* d2,
            std::uint32_t largest_thin_d2, bool record_rounds)
    : m_layout(layout), m_state(std::move(state)), m_d2(d2),
      m_offsets(layout.neighbour_offsets()), m_largest_thin_d2(largest_thin_d2),
      m_offset_length(neighbour_step_lengths()), m_test(Simple_point_test::instance()),
      m_round_deleted(record_rounds ? m_state.size() : 0, 0)
  {
    for(int row = 0; row < 9; ++row) // from (x - 1, y + dy, z + dz), dy = row % 3 - 1, dz = row / 3 - 1
      m_row_offsets[row] = (row % 3 - 1) * layout.stride_y + (row / 3 - 1) * layout.stride_z - 1;
  }

  // Deletes simple points by increasing distance; returns the number deleted. A level is
  // burnt in rounds: first the round's candidates are chosen on the configuration at the
  // start of the round (simple, and not a protected end point); then those that are
  // P-simple among them are deleted at once (delete_p_simple(), whatever the order); then
  // the others are deleted one by one in index order, each if still simple and not an end
  // point that has become clearly medial (radius growth below tip_growth_when_deleting per
  // unit step, as on a plateau of the distance): an end point that the round's own
  // deletions expose at a corner of the shape is no tip, and goes. Only that last step,
  // where the set is two voxels thick and one of two voxels must go, depends on the order.
  // In a thin part (in_thin_part()) that step would erode a sheet in index order, like a
  // raster scan, and leave an arbitrary curve: there the candidates left go first by face
  // direction (delete_thin_by_direction()), and those still left wait for the next round
  // when it deleted any, so that a sheet loses one layer, then burns from its rim inwards.
  // Levels are those of burning_level().
  std::size_t run(const std::vector<std::uint32_t>& order)
  {
    for(std::uint32_t i : order)
      m_state[i] |= QUEUED;
    std::size_t removed = 0, next = 0;
    // A voxel is queued at most once at a time (the QUEUED bit): buffers of the set's size
    // hold any round and its candidates.
    std::vector<std::uint32_t> round(order.size()), candidates(order.size());
    std::size_t round_size = 0;
    while(next < order.size())
    {
      const std::uint32_t level = burning_level(order[next]);
      round_size = 0;
      while(next < order.size() && burning_level(order[next]) == level)
        round[round_size++] = order[next++];
      m_round = 0;
      while(round_size > 0)
      {
        if(m_round < std::numeric_limits<std::uint16_t>::max())
          ++m_round;
        std::size_t candidate_count = 0;
        for(std::size_t k = 0; k < round_size; ++k)
        {
          const std::uint32_t i = round[k];
          m_state[i] &= std::uint8_t(~QUEUED);
          if(!(m_state[i] & IN))
            continue;
          const std::uint32_t config = configuration(i);
          if(!protected_end(i, config, tip_growth_when_choosing) && m_test.is_simple(config))
            candidates[candidate_count++] = i;
        }
        round_size = 0;
        removed += delete_p_simple(candidates.data(), candidate_count, round, round_size);
        const std::size_t thin_removed = delete_thin_by_direction(candidates.data(), candidate_count, round, round_size);
        removed += thin_removed;
        for(std::size_t k = 0; k < candidate_count; ++k)
        {
          const std::uint32_t i = candidates[k];
          if(!(m_state[i] & IN))
            continue;
          if(thin_removed > 0 && in_thin_part(i))
          {
            queue(i, round, round_size);
            continue;
          }
          const std::uint32_t config = configuration(i);
          if(protected_end(i, config, tip_growth_when_deleting) || !m_test.is_simple(config))
            continue;
          delete_voxel(i);
          ++removed;
          queue_neighbours(i, config, round, round_size);
        }
      }
    }
    return removed;
  }

  // Deletes at once the candidates that are P-simple for P the candidates (see
  // Simple_point_test::is_p_simple()): the part of a round whose outcome does not depend on
  // the order of the voxels, so that on a mirrored or rotated grid it deletes the mirrored
  // or rotated voxels. Returns the number deleted; the candidates left are deleted one by
  // one after it.
  std::size_t delete_p_simple(const std::uint32_t* candidates, std::size_t candidate_count,
                              std::vector<std::uint32_t>& round, std::size_t& round_size)
  {
    for(std::size_t k = 0; k < candidate_count; ++k)
      m_state[candidates[k]] |= CANDIDATE;
    m_p_simple.clear();
    for(std::size_t k = 0; k < candidate_count; ++k)
    {
      const std::uint32_t i = candidates[k];
      const std::pair<std::uint32_t, std::uint32_t> config = configurations(i);
      // A candidate is simple (it was chosen on this very state): without a neighbour in P
      // it is P-simple.
      if(config.second == 0 || m_test.is_p_simple(config.first, config.second))
        m_p_simple.emplace_back(i, config.first);
    }
    for(std::size_t k = 0; k < candidate_count; ++k)
      m_state[candidates[k]] &= std::uint8_t(~CANDIDATE);
    for(const auto& deleted : m_p_simple)
      delete_voxel(deleted.first);
    for(const auto& deleted : m_p_simple)
      queue_neighbours(deleted.first, deleted.second, round, round_size);
    return m_p_simple.size();
  }

  // The candidates of a thin part (in_thin_part()) that are still in the set, deleted
  // direction by direction: for each of the six face directions in turn, those open on
  // that side (their face neighbour there is outside), still simple and not protected end
  // points, are deleted at once where P-simple among them. A sheet two voxels thick so
  // loses the layer facing one way whole, whatever the order of its voxels, and a sheet
  // one voxel thick its rim. Returns the number deleted.
  std::size_t delete_thin_by_direction(const std::uint32_t* candidates, std::size_t candidate_count,
                                       std::vector<std::uint32_t>& round, std::size_t& round_size)
  {
    m_thin_candidates.clear();
    for(std::size_t k = 0; k < candidate_count; ++k)
      if((m_state[candidates[k]] & IN) && in_thin_part(candidates[k]))
        m_thin_candidates.push_back(candidates[k]);
    std::size_t removed = 0;
    for(std::ptrdiff_t face : {m_layout.stride_z, -m_layout.stride_z, m_layout.stride_y, -m_layout.stride_y,
                               std::ptrdiff_t(1), std::ptrdiff_t(-1)})
    {
      m_open.clear();
      for(std::uint32_t i : m_thin_candidates)
      {
        if(!(m_state[i] & IN) || (m_state[std::size_t(std::ptrdiff_t(i) + face)] & IN))
          continue;
        const std::uint32_t config = configuration(i);
        if(!protected_end(i, config, tip_growth_when_deleting) && m_test.is_simple(config))
          m_open.push_back(i);
      }
      removed += delete_p_simple(m_open.data(), m_open.size(), round, round_size);
    }
    return removed;
  }

  bool in_thin_part(std::size_t i) const { return internal::in_thin_part(m_d2, i, m_offsets, m_largest_thin_d2); }
  std::uint32_t burning_level(std::size_t i) const
  {
    return internal::burning_level(m_d2, i, m_offsets, m_largest_thin_d2);
  }

  // Queues voxel i of the set to burn in the next round, unless it is queued already.
  void queue(std::uint32_t i, std::vector<std::uint32_t>& round, std::size_t& round_size)
  {
    if(!(m_state[i] & QUEUED))
    {
      m_state[i] |= QUEUED;
      round[round_size++] = i;
    }
  }

  // Queues the neighbours in the set of a deleted voxel i (the bits of `config`) to burn again.
  void queue_neighbours(std::uint32_t i, std::uint32_t config, std::vector<std::uint32_t>& round,
                        std::size_t& round_size)
  {
    for(std::uint32_t in = config; in != 0; in &= in - 1)
    {
      const std::size_t j = std::size_t(std::ptrdiff_t(i) + m_offsets[std::size_t(lowest_bit(in))]);
      if(m_state[j] & IN)
        queue(std::uint32_t(j), round, round_size);
    }
  }

  void delete_voxel(std::size_t i)
  {
    m_state[i] = DELETED;
    if(!m_round_deleted.empty())
      m_round_deleted[i] = m_round;
  }

  bool deleted(std::size_t i) const { return (m_state[i] & DELETED) != 0; }

  // The sheet radius of a voxel i left by run(), in voxels: the latest round of its level
  // in which a 26-neighbour at the same distance was deleted (0 when none was). A level
  // burns in rounds, each a step of the fire inwards; where the distance to the outside is
  // flat, as inside a thin sheet, the level is the whole sheet and its rounds burn it from
  // its rim, like a fire in the plane, so this is the distance from i to the sheet's rim
  // measured in the sheet (its half width, where i is on the sheet's middle line), which the
  // MAT radius (the half thickness) does not tell. Elsewhere a level is a shell that burns
  // in a round or two, and this is 0 or about 1. Needs the rounds recorded (constructor).
  //
  // With a `depth_band`, the rounds of the neighbours at a distance within `depth_band`
  // voxels of i's count too: the middle of a thick sheet slanted in the grid falls on
  // levels less than half a voxel apart, side by side in strips, and each level's rounds
  // measure its own strips only.
  double sheet_radius(std::size_t i, double depth_band = 0) const
  {
    CGAL_precondition(!m_round_deleted.empty());
    std::uint16_t latest = 0;
    const double depth_of_i = std::sqrt(double(burning_level(i)));
    for(int b = 0; b < 26; ++b)
    {
      const std::size_t j = std::size_t(std::ptrdiff_t(i) + m_offsets[b]);
      if((m_state[j] & DELETED) && std::abs(std::sqrt(double(burning_level(j))) - depth_of_i) <= depth_band)
        latest = (std::max)(latest, m_round_deleted[j]);
    }
    return double(latest);
  }

  // The 26-neighbourhood of i as a configuration (bit b for neighbourhood_26()[b]): the hot
  // loop of the thinning. Read as the nine rows of three voxels of the 3 x 3 x 3 cube (in
  // the (z, y, x) order of neighbourhood_26()), then the centre's bit taken out.
  std::uint32_t configuration(std::size_t i) const
  {
    const std::uint8_t* centre = m_state.data() + i;
    std::uint32_t cube = 0;
    for(int row = 0; row < 9; ++row)
    {
      const std::uint8_t* r = centre + m_row_offsets[row];
      cube |= (std::uint32_t(r[0] & IN) | std::uint32_t(r[1] & IN) << 1 | std::uint32_t(r[2] & IN) << 2)
              << (3 * row);
    }
    return (cube & 0x1FFFu) | ((cube >> 14) << 13);
  }
  // The configurations of the neighbours in the set and of those in the round's candidates
  // (bit 3), read in one pass.
  std::pair<std::uint32_t, std::uint32_t> configurations(std::size_t i) const
  {
    const std::uint8_t* centre = m_state.data() + i;
    std::uint32_t in = 0, candidate = 0;
    for(int row = 0; row < 9; ++row)
    {
      const std::uint8_t* r = centre + m_row_offsets[row];
      const std::uint32_t bits = std::uint32_t(r[0]) | std::uint32_t(r[1]) << 8 | std::uint32_t(r[2]) << 16;
      in |= ((bits & 1u) | (bits >> 7 & 2u) | (bits >> 14 & 4u)) << (3 * row);
      candidate |= ((bits >> 3 & 1u) | (bits >> 10 & 2u) | (bits >> 17 & 4u)) << (3 * row);
    }
    return {(in & 0x1FFFu) | ((in >> 14) << 13), (candidate & 0x1FFFu) | ((candidate >> 14) << 13)};
  }

  // A curve end point on the medial axis (and not half of a 2-voxel piece), for a ridge
  // threshold `growth` (see on_ridge()).
  bool protected_end(std::size_t i, std::uint32_t config, double growth) const
  {
    return bit_count(config) == 1 && on_ridge(i, growth) &&
           !is_end_point(sole_neighbour(i, config));
  }

  std::size_t sole_neighbour(std::size_t i, std::uint32_t config) const
  {
    return std::size_t(std::ptrdiff_t(i) + m_offsets[lowest_bit(config)]);
  }
  bool is_end_point(std::size_t i) const { return bit_count(configuration(i)) == 1; }

  // Whether the medial ball of i is not swallowed by a neighbour's (centre_of_maximal_ball()).
  // Ends of curves are kept only there, so that a branch ends where the shape's end is
  // rounded (about a radius from the tip) and the erosion does not leave hairs behind; the
  // medial sheets of edges and blunt ends burn away.
  bool on_ridge(std::size_t i, double growth) const
  {
    return centre_of_maximal_ball(m_d2, i, m_offsets, m_offset_length, growth);
  }

private:
  const Grid_layout& m_layout;
  std::vector<std::uint8_t> m_state;
  const std::uint32_t* m_d2;
  std::array<std::ptrdiff_t, 26> m_offsets;
  std::uint32_t m_largest_thin_d2; // of a voxel in a thin part (thin_part_d2())
  std::array<std::ptrdiff_t, 9> m_row_offsets{};
  std::array<double, 26> m_offset_length{};
  const Simple_point_test& m_test;
  std::vector<std::uint16_t> m_round_deleted; // by voxel: its level's round when deleted (from 1); empty when not recorded
  std::uint16_t m_round = 0;                  // the round of the level burning (from 1)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> m_p_simple; // delete_p_simple()'s voxels and configurations
  std::vector<std::uint32_t> m_thin_candidates, m_open;           // delete_thin_by_direction()'s
};

// The indices of the voxels of `state` (bit 0) sorted by increasing burning level
// (burning_level(), over `layout`, with thin parts up to squared distance
// `largest_thin_d2`), then index: a counting sort when the range of levels
// is small, else a comparison sort.
inline std::vector<std::uint32_t> sorted_by_burning_level(const std::vector<std::uint8_t>& state,
                                                          const std::uint32_t* d2, const Grid_layout& layout,
                                                          std::uint32_t largest_thin_d2)
{
  // The levels are computed again in each pass rather than stored: 4 bytes per voxel of
  // the set less at the thinning's peak.
  const std::array<std::ptrdiff_t, 26> offsets = layout.neighbour_offsets();
  const auto level_of = [&](std::uint32_t i) { return burning_level(d2, i, offsets, largest_thin_d2); };
  std::vector<std::uint32_t> order;
  std::uint32_t max_level = 0;
  for(std::size_t i = 0; i < state.size(); ++i)
    if(state[i] & 1)
    {
      order.push_back(std::uint32_t(i));
      max_level = (std::max)(max_level, level_of(std::uint32_t(i)));
    }
  if(std::size_t(max_level) <= 4 * order.size() + 1024)
  {
    std::vector<std::uint32_t> start(std::size_t(max_level) + 2, 0), sorted(order.size());
    for(std::uint32_t i : order)
      ++start[level_of(i) + 1];
    for(std::size_t v = 1; v < start.size(); ++v)
      start[v] += start[v - 1];
    for(std::uint32_t i : order)
      sorted[start[level_of(i)]++] = i;
    return sorted;
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return level_of(a) < level_of(b); });
  return order;
}

// The squared distances of `field` (a model of VoxelDistanceField) over `layout` (0
// outside the field's box), row by row.
template <typename VoxelDistanceField>
std::vector<std::uint32_t> distances_over(const VoxelDistanceField& field, const Grid_layout& layout)
{
  std::vector<std::uint32_t> out(layout.volume(), 0u);
  const Voxel_box& from = field.box();
  const Grid_layout source(from);
  const int x0 = (std::max)(from.min.x, layout.box.min.x), x1 = (std::min)(from.max.x, layout.box.max.x);
  if(x0 >= x1)
    return out;
  for(int z = (std::max)(from.min.z, layout.box.min.z); z < (std::min)(from.max.z, layout.box.max.z); ++z)
    for(int y = (std::max)(from.min.y, layout.box.min.y); y < (std::min)(from.max.y, layout.box.max.y); ++y)
      std::copy_n(field.values().begin() + std::ptrdiff_t(source.index(Voxel_key{x0, y, z})),
                  x1 - x0, out.begin() + std::ptrdiff_t(layout.index(Voxel_key{x0, y, z})));
  return out;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_THIN_GRASSFIRE_H
