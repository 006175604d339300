// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_MEDIAL_PATH_SEARCH_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_MEDIAL_PATH_SEARCH_H

// The search for a path through the middle of the solid that two voxel stages share: the
// finer-grid routing (route_skeleton_on_finer_grid(), steps over the MAT radius, A*) and the
// sheet lobes (reach_sheet_lobes(), steps over the squared radius, Dijkstra). The skinning's
// voxel distances are another search: from many seeds at once, over the whole solid, with
// integer steps in a bucket queue, and no path to recover.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The cheapest 26-connected path in a box of voxels, with its working arrays kept from one
// search to the next (each search clears what it touched). `Cost` is the type the path costs
// are summed in.
template <typename Cost>
class Medial_path_search
{
public:
  // The cheapest path from `start` to the first voxel that `is_goal(k)` accepts, within the
  // box of `layout`; `step_cost(k, o, next, i)` gives the cost of the step from `k` by offset
  // `o` of neighbourhood_26() into `next` (index `i` in the layout), or nothing where `next`
  // may not be entered; `estimate(k)` is a consistent lower bound of the cost from `k` to a
  // goal (A*; a zero estimate makes it Dijkstra's search). Voxels of equal bound are taken in
  // key order. Returns the path from `start` to its goal, both included, or nothing.
  // Complexity: O(n log n) for the n voxels it reaches.
  template <typename IsGoal, typename StepCost, typename Estimate>
  std::vector<Voxel_key> cheapest_path(const Grid_layout& layout, const Voxel_key& start, const IsGoal& is_goal,
                                       const StepCost& step_cost, const Estimate& estimate)
  {
    if(m_cells.size() < layout.volume())
      m_cells.resize(layout.volume());
    // Within one layout the index order is the key order.
    using Queued = std::pair<double, std::size_t>;
    std::priority_queue<Queued, std::vector<Queued>, std::greater<Queued>> queue;
    const std::size_t first = layout.index(start);
    m_touched.assign(1, first);
    m_cells[first].cost = Cost(0);
    m_cells[first].reached = true;
    queue.push({estimate(start), first});
    std::vector<Voxel_key> path;
    const auto& offsets = neighbourhood_26();
    while(!queue.empty())
    {
      const std::size_t at = queue.top().second;
      queue.pop();
      Cell& from = m_cells[at];
      if(from.closed)
        continue; // reached more cheaply since it was queued
      from.closed = true;
      const Voxel_key k = layout.key(at);
      if(is_goal(k))
      {
        path = path_to(k, layout);
        break;
      }
      for(std::uint8_t o = 0; o < offsets.size(); ++o)
      {
        const Voxel_key next = k + offsets[o];
        if(!layout.box.contains(next))
          continue;
        const std::size_t i = layout.index(next);
        Cell& cell = m_cells[i];
        if(cell.closed)
          continue;
        const std::optional<Cost> step = step_cost(k, o, next, i);
        if(!step)
          continue;
        const Cost through_k = m_cells[at].cost + *step;
        if(!cell.reached || through_k < cell.cost)
        {
          if(!cell.reached)
            m_touched.push_back(i);
          cell.reached = true;
          cell.cost = through_k;
          cell.step_in = std::uint8_t(o + 1);
          queue.push({through_k + estimate(next), i});
        }
      }
    }
    for(std::size_t i : m_touched)
      m_cells[i] = Cell{};
    return path;
  }

private:
  struct Cell
  {
    Cost cost = Cost(0);
    std::uint8_t step_in = 0; // the offset the search reached it by, plus 1; 0 for none
    bool reached = false;
    bool closed = false;
  };

  std::vector<Voxel_key> path_to(const Voxel_key& goal, const Grid_layout& layout) const
  {
    std::vector<Voxel_key> path;
    const auto& offsets = neighbourhood_26();
    for(Voxel_key v = goal;;)
    {
      path.push_back(v);
      const std::uint8_t step_plus_one = m_cells[layout.index(v)].step_in;
      if(step_plus_one == 0)
        break;
      const Voxel_key& step = offsets[step_plus_one - 1];
      v = Voxel_key{v.x - step.x, v.y - step.y, v.z - step.z};
    }
    std::reverse(path.begin(), path.end());
    return path;
  }

  std::vector<Cell> m_cells;          // by index in the layout of the search
  std::vector<std::size_t> m_touched; // the cells the current search reached
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_MEDIAL_PATH_SEARCH_H
