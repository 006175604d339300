// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_ROUTE_SKELETON_ON_FINER_GRID_FINER_GRID_ROUTER_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_ROUTE_SKELETON_ON_FINER_GRID_FINER_GRID_ROUTER_H

// The machinery of route_skeleton_on_finer_grid.h: the coarser skeleton's branches as voxel
// paths, and the router that places them through the middle of the finer grid's solid.

#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/medial_path_search.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_branches.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>
#include <CGAL/Geodesic_skeleton/internal/vec3.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <array>
#include <deque>
#include <climits>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

namespace internal {

// The voxels of the straight segment from the centre of `a` to that of `b`, a 26-connected
// path: one per step along the axis of their largest difference, rounded to the nearest voxel.
inline std::vector<Voxel_key> straight_voxel_path(const Voxel_key& a, const Voxel_key& b)
{
  const int steps = (std::max)({std::abs(b.x - a.x), std::abs(b.y - a.y), std::abs(b.z - a.z)});
  std::vector<Voxel_key> path;
  path.reserve(std::size_t(steps) + 1);
  auto at = [&](int from, int to, int i) {
    return from + int(std::lround(double(to - from) * double(i) / double((std::max)(steps, 1))));
  };
  for(int i = 0; i <= steps; ++i)
    path.push_back(Voxel_key{at(a.x, b.x, i), at(a.y, b.y, i), at(a.z, b.z, i)});
  return path;
}

// The MAT radius in voxels of a voxel inside the solid whose squared distance transform is
// `squared_distance`, as mat_radius_in_voxels_map() gives it: at least 1/2.
inline double mat_radius_in_voxels(std::uint32_t squared_distance)
{
  return std::sqrt(double(squared_distance)) - 0.5;
}

// The cost of a step of the routing into voxel `next` inside the solid: its length over the
// MAT radius of `next` in voxels. A path's cost is a length in MAT radii, the same on any
// grid, and the cheapest path keeps to the middle of the solid.
inline double step_cost_through_the_middle(const Voxel_distance_field& distances, const Voxel_key& from,
                                           const Voxel_key& next)
{
  return step_length(from, next) / mat_radius_in_voxels(distances.squared_distance(next));
}

// The voxel of `to` whose cell holds the centre of voxel `k` of `from`.
inline Voxel_key voxel_in_frame(const Voxel_frame& from, const Voxel_frame& to, const Voxel_key& k)
{
  return cell_of(to.to_grid(from.centre(k)));
}

// The branches of a skeleton's graph (the one to_graph() makes) as voxel paths between its
// nodes (voxels of degree other than 2); a closed loop, or a loop through a single node,
// is cut in two halves at its voxel halfway, which becomes a node.
struct Voxel_branches
{
  std::vector<Voxel_key> nodes;
  struct Branch
  {
    int first_node = -1, last_node = -1;
    std::vector<Voxel_key> voxels; // first node to last node, both included
  };
  std::vector<Branch> branches;
  std::vector<std::vector<int>> branches_at; // per node
};

template <typename VoxelSet>
Voxel_branches voxel_branches(const VoxelSet& skeleton)
{
  const Skeleton_adjacency graph = skeleton_adjacency(skeleton);
  boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS> g(graph.nodes.size());
  for(const auto& [a, b] : graph.edges)
    boost::add_edge(std::size_t(a), std::size_t(b), g);
  Voxel_branches result;
  std::unordered_map<std::size_t, int> node_of_vertex;
  auto node = [&](std::size_t v) {
    const auto [at, added] = node_of_vertex.emplace(v, int(result.nodes.size()));
    if(added)
      result.nodes.push_back(graph.nodes[v]);
    return at->second;
  };
  auto add = [&](std::vector<std::size_t>::const_iterator first, std::vector<std::size_t>::const_iterator last) {
    Voxel_branches::Branch& branch = result.branches.emplace_back();
    branch.first_node = node(*first);
    branch.last_node = node(*(last - 1));
    for(auto v = first; v != last; ++v)
      branch.voxels.push_back(graph.nodes[*v]);
  };
  for(Skeleton_branch& branch : skeleton_branches(g))
  {
    std::vector<std::size_t>& path = branch.vertices;
    if(branch.closed)
      path.push_back(path.front());
    if(path.front() != path.back())
      add(path.begin(), path.end());
    else if(path.size() > 3)
    {
      const auto half = path.begin() + std::ptrdiff_t(path.size() / 2);
      add(path.begin(), half + 1);
      add(half, path.end());
    }
  }
  // Voxels without any edge are pieces of their own: nodes without branches.
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    if(boost::degree(v, g) == 0)
      node(v);
  result.branches_at.assign(result.nodes.size(), {});
  for(std::size_t e = 0; e < result.branches.size(); ++e)
  {
    result.branches_at[std::size_t(result.branches[e].first_node)].push_back(int(e));
    if(result.branches[e].last_node != result.branches[e].first_node)
      result.branches_at[std::size_t(result.branches[e].last_node)].push_back(int(e));
  }
  return result;
}

// How far from the coarser skeleton, in coarser voxels (26-steps), a branch is routed on the
// finer grid: the coarser skeleton is central to within a voxel, and the finer grid only
// places it more precisely.
constexpr int routing_tube_half_width = 1;

// The voxels of the coarser grid within routing_tube_half_width steps of its skeleton
// (inside its solid, or one step out of it), labelled by the part of the skeleton nearest to
// them, found by a breadth-first search from the skeleton: a branch's index, or the number
// of branches plus a node's index for the node's voxel; -1 elsewhere.
struct Nearest_branch_labels
{
  Grid_layout layout;
  std::vector<std::int32_t> label;
  std::vector<std::uint8_t> steps; // from the skeleton, where labelled

  std::int32_t at(const Voxel_key& k) const { return layout.box.contains(k) ? label[layout.index(k)] : -1; }
  int steps_at(const Voxel_key& k) const { return layout.box.contains(k) ? steps[layout.index(k)] : 0; }
};

inline Nearest_branch_labels nearest_branch_labels(const Voxel_branches& skeleton,
                                                   const Voxel_distance_field& distances)
{
  Nearest_branch_labels labels{Grid_layout(distances.box().grown(1)), {}, {}};
  labels.label.assign(labels.layout.volume(), -1);
  labels.steps.assign(labels.layout.volume(), 0);
  std::deque<std::pair<Voxel_key, int>> queue; // voxel, steps from the skeleton
  auto reach = [&](const Voxel_key& k, std::int32_t label, int steps) {
    const std::size_t i = labels.layout.index(k);
    if(labels.label[i] >= 0)
      return;
    labels.label[i] = label;
    labels.steps[i] = std::uint8_t(steps);
    queue.emplace_back(k, steps);
  };
  const std::int32_t node_label = std::int32_t(skeleton.branches.size());
  for(std::size_t n = 0; n < skeleton.nodes.size(); ++n)
    reach(skeleton.nodes[n], node_label + std::int32_t(n), 0);
  for(std::size_t e = 0; e < skeleton.branches.size(); ++e)
    for(const Voxel_key& k : skeleton.branches[e].voxels)
      reach(k, std::int32_t(e), 0);
  while(!queue.empty())
  {
    const auto [k, steps] = queue.front();
    queue.pop_front();
    if(!distances.inside(k) || steps == routing_tube_half_width)
      continue; // one step out of the solid, or out of the tube, no further
    for(const Voxel_key& offset : neighbourhood_26())
      if(labels.layout.box.contains(k + offset))
        reach(k + offset, labels.at(k), steps + 1);
  }
  return labels;
}

// The routing of route_skeleton_on_finer_grid(): the branches are routed from the most
// central node of each piece outwards, each from its far node to the part of the finer
// skeleton that is already routed around its near node.
class Finer_grid_router
{
public:
  Finer_grid_router(const Voxel_branches& coarse, const Voxel_distance_field& coarse_distances,
                    const Voxel_distance_field& fine_distances, Coarser_voxel_map& coarser_voxel)
    : m_coarse(coarse), m_coarse_frame(coarse_distances.frame()), m_fine(fine_distances),
      m_labels(nearest_branch_labels(coarse, coarse_distances)),
      m_allowed(coarse.branches.size() + coarse.nodes.size(), -1),
      m_coarser_voxel(coarser_voxel)
  {
    for(const Voxel_key& k : coarse.nodes)
    {
      m_fine_node.push_back(most_central_fine_voxel(k));
      m_node_radius.push_back(mat_radius_in_voxels(m_fine.squared_distance(m_fine_node.back())));
    }
    // The largest MAT radius of each label's voxels, on the finer grid (a voxel of the
    // coarser one and a half more, in finer voxels): it bounds the search's estimate.
    const double ratio = m_coarse_frame.voxel_size() / m_fine.frame().voxel_size();
    m_largest_radius_of_label.assign(m_allowed.size(), 0.0);
    for(std::size_t i = 0; i < m_labels.label.size(); ++i)
      if(m_labels.label[i] >= 0)
      {
        double& largest = m_largest_radius_of_label[std::size_t(m_labels.label[i])];
        largest = (std::max)(largest, std::sqrt(double(coarse_distances.squared_distance(m_labels.layout.key(i)))));
      }
    for(double& r : m_largest_radius_of_label)
      r = (r + 1.5) * ratio;
  }

  // Routes every branch into `skeleton`; returns the number routed along the coarser
  // skeleton's own voxels, for want of a path through the finer solid.
  template <typename VoxelSet>
  std::size_t route(VoxelSet& skeleton)
  {
    std::vector<bool> node_reached(m_coarse.nodes.size(), false), branch_routed(m_coarse.branches.size(), false);
    std::size_t along_coarser = 0;
    for(int root : roots())
    {
      if(node_reached[std::size_t(root)])
        continue;
      node_reached[std::size_t(root)] = true;
      add(skeleton, m_fine_node[std::size_t(root)], m_coarse.nodes[std::size_t(root)]);
      std::deque<int> nodes{root};
      while(!nodes.empty())
      {
        const int near = nodes.front();
        nodes.pop_front();
        for(int e : m_coarse.branches_at[std::size_t(near)])
        {
          if(branch_routed[std::size_t(e)])
            continue;
          branch_routed[std::size_t(e)] = true;
          const Voxel_branches::Branch& branch = m_coarse.branches[std::size_t(e)];
          const int far = branch.first_node == near ? branch.last_node : branch.first_node;
          along_coarser += route_branch(skeleton, e, far, near) ? 0 : 1;
          if(!node_reached[std::size_t(far)])
          {
            node_reached[std::size_t(far)] = true;
            nodes.push_back(far);
          }
        }
      }
    }
    remove_spurs(skeleton);
    return along_coarser;
  }

private:
  // What the router knows of a voxel of the window of the branch it routes; all zero at first.
  struct Cell
  {
    std::int32_t label_plus_two; // the label of its coarser voxel plus 2, once read; 0 before
    std::uint8_t off_skeleton;   // that voxel's steps from the coarser skeleton
    bool near_skeleton;          // a skeleton voxel or a neighbour of one
    bool avoided;                // next to a leg of the branch that is not on the skeleton yet
  };

  // Confines the search of the next branch to a window of the finer grid around the tube of
  // its coarser voxels and the balls of its nodes, and marks there the voxels next to the
  // skeleton routed so far. Arrays over the whole finer box would cost more to clear than
  // the searches do.
  template <typename VoxelSet>
  void open_window(const VoxelSet& skeleton, const std::vector<Voxel_key>& coarse_path, int far, int near)
  {
    const double ratio = m_coarse_frame.voxel_size() / m_fine.frame().voxel_size();
    const int margin = int(std::ceil((routing_tube_half_width + 1.5) * ratio)) + 1;
    Voxel_box window{Voxel_key{INT_MAX, INT_MAX, INT_MAX}, Voxel_key{INT_MIN, INT_MIN, INT_MIN}};
    auto cover = [&](const Voxel_key& k, int reach) {
      window.min = Voxel_key{(std::min)(window.min.x, k.x - reach), (std::min)(window.min.y, k.y - reach),
                             (std::min)(window.min.z, k.z - reach)};
      window.max = Voxel_key{(std::max)(window.max.x, k.x + reach + 1), (std::max)(window.max.y, k.y + reach + 1),
                             (std::max)(window.max.z, k.z + reach + 1)};
    };
    for(const Voxel_key& k : coarse_path)
      cover(voxel_in_frame(m_coarse_frame, m_fine.frame(), k), margin);
    for(int node : {far, near})
      cover(m_fine_node[std::size_t(node)], int(std::ceil(m_node_radius[std::size_t(node)])) + 3);
    const Voxel_box& box = m_fine.box();
    window.min = Voxel_key{(std::max)(window.min.x, box.min.x), (std::max)(window.min.y, box.min.y),
                           (std::max)(window.min.z, box.min.z)};
    window.max = Voxel_key{(std::min)(window.max.x, box.max.x), (std::min)(window.max.y, box.max.y),
                           (std::min)(window.max.z, box.max.z)};
    m_layout = Grid_layout(window);
    m_cells.assign(window.empty() ? 0 : m_layout.volume(), Cell{});
    skeleton.for_each([&](const Voxel_key& k) {
      for(const Voxel_key& offset : neighbourhood_26())
        if(window.contains(k + offset))
          m_cells[m_layout.index(k + offset)].near_skeleton = true;
      if(window.contains(k))
        m_cells[m_layout.index(k)].near_skeleton = true;
    });
  }

  // The label of the coarser voxel of the finer voxel `k` (and its steps from the coarser
  // skeleton, cached beside it).
  std::int32_t label_of(std::size_t i, const Voxel_key& k)
  {
    if(m_cells[i].label_plus_two == 0)
    {
      const Voxel_key coarse = voxel_in_frame(m_fine.frame(), m_coarse_frame, k);
      m_cells[i].label_plus_two = m_labels.at(coarse) + 2;
      m_cells[i].off_skeleton = std::uint8_t(m_labels.steps_at(coarse));
    }
    return m_cells[i].label_plus_two - 2;
  }

  // Removes, end point by end point, the branches of the routed skeleton that end elsewhere
  // than at an end node of the coarser skeleton: where the branches around a junction
  // joined the skeleton short of the junction's node, the last voxels to it are a spur.
  template <typename VoxelSet>
  void remove_spurs(VoxelSet& skeleton) const
  {
    std::vector<Voxel_key> kept_ends;
    for(std::size_t n = 0; n < m_coarse.nodes.size(); ++n)
      if(m_coarse.branches_at[n].size() <= 1)
        kept_ends.push_back(m_fine_node[n]);
    std::sort(kept_ends.begin(), kept_ends.end());
    for(;;)
    {
      bool removed = false;
      for(const Voxel_key& end : graph_end_points(skeleton))
        if(!std::binary_search(kept_ends.begin(), kept_ends.end(), end))
          removed |= skeleton.erase(end);
      if(!removed)
        return;
    }
  }

  // The voxel of the finer grid inside the solid and within the cell of the coarser voxel
  // `k` (or, failing that, at its centre) with the largest MAT radius.
  Voxel_key most_central_fine_voxel(const Voxel_key& k) const
  {
    const Voxel_key centre = voxel_in_frame(m_coarse_frame, m_fine.frame(), k);
    const int reach = (std::max)(1, int(std::ceil(m_coarse_frame.voxel_size() / m_fine.frame().voxel_size() / 2)));
    Voxel_key best = centre;
    for(int dz = -reach; dz <= reach; ++dz)
      for(int dy = -reach; dy <= reach; ++dy)
        for(int dx = -reach; dx <= reach; ++dx)
        {
          const Voxel_key f{centre.x + dx, centre.y + dy, centre.z + dz};
          if(voxel_in_frame(m_fine.frame(), m_coarse_frame, f) == k &&
             m_fine.squared_distance(f) > m_fine.squared_distance(best))
            best = f;
        }
    return best;
  }

  // The nodes in order of decreasing MAT radius: the first of each piece is its root.
  std::vector<int> roots() const
  {
    std::vector<int> order(m_coarse.nodes.size());
    for(std::size_t n = 0; n < order.size(); ++n)
      order[n] = int(n);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      return m_fine.squared_distance(m_fine_node[std::size_t(a)]) > m_fine.squared_distance(m_fine_node[std::size_t(b)]);
    });
    return order;
  }

  template <typename VoxelSet>
  void add(VoxelSet& skeleton, const Voxel_key& fine, const Voxel_key& coarse)
  {
    if(!skeleton.insert(fine))
      return;
    m_coarser_voxel.emplace(fine, coarse);
  }

  // Whether the voxels of `skeleton` among the 26 neighbours of `k` are one 26-connected group.
  template <typename VoxelSet>
  static bool touches_once(const VoxelSet& skeleton, const Voxel_key& k)
  {
    std::vector<Voxel_key> touched;
    for(const Voxel_key& offset : neighbourhood_26())
      if(skeleton.contains(k + offset))
        touched.push_back(k + offset);
    return are_26_connected(touched);
  }

  bool near_node(const Voxel_key& k, int node) const
  {
    const double reach = m_node_radius[std::size_t(node)] + 2;
    return double(squared_distance_between(k, m_fine_node[std::size_t(node)])) <= reach * reach;
  }

  // Routes branch `e` from node `far` to the finer skeleton around node `near`: through the
  // middle of the finer solid, within the part of the coarser solid nearest to the branch
  // and its two nodes, and touching the skeleton only around its two nodes; or, when no such
  // path is found, along the coarser branch's own voxels. A branch of more than 4 voxels is
  // routed in two legs, through the finer voxel of its middle, so that it cannot cut across
  // from node to node where the two lie close (the arcs of a figure eight, whose two
  // junctions are a few voxels apart).
  template <typename VoxelSet>
  bool route_branch(VoxelSet& skeleton, int e, int far, int near)
  {
    const Voxel_branches::Branch& branch = m_coarse.branches[std::size_t(e)];
    for(int label : {e, int(m_coarse.branches.size()) + far, int(m_coarse.branches.size()) + near})
      m_allowed[std::size_t(label)] = e;
    std::vector<Voxel_key> coarse_path = branch.voxels; // from far to near
    if(branch.first_node != far)
      std::reverse(coarse_path.begin(), coarse_path.end());
    const Voxel_key start = m_fine_node[std::size_t(far)];
    const double start_reach = m_node_radius[std::size_t(far)] + 2;
    std::vector<Voxel_key> path;
    if(coarse_path.size() > 4)
    {
      const std::size_t middle = coarse_path.size() / 2;
      const Voxel_key through = most_central_fine_voxel(coarse_path[middle]);
      const std::vector<Voxel_key> first_leg =
          route_leg(skeleton, e, far, near, start, start_reach, [&](const Voxel_key& k) { return k == through; });
      // The second leg keeps away from the first, which joins the skeleton with it.
      if(!first_leg.empty())
        path = route_leg(skeleton, e, far, near, through, 2, goal_around(skeleton, near), false, &first_leg);
      if(!path.empty())
      {
        add_path(skeleton, first_leg, {coarse_path.begin(), coarse_path.begin() + std::ptrdiff_t(middle) + 1});
        add_path(skeleton, path, {coarse_path.begin() + std::ptrdiff_t(middle), coarse_path.end()});
      }
    }
    else if(!skeleton.contains(start))
    {
      path = route_leg(skeleton, e, far, near, start, start_reach, goal_around(skeleton, near));
      if(!path.empty())
        add_path(skeleton, path, coarse_path);
    }
    else
    {
      // A short branch between two nodes on the skeleton already (the waist of a figure
      // eight): from node to node, next to the skeleton around both.
      const Voxel_key goal = m_fine_node[std::size_t(near)];
      path = route_leg(skeleton, e, far, near, start, start_reach,
                       [&](const Voxel_key& k) { return squared_distance_between(k, goal) <= 3; }, true);
      if(!path.empty())
        add_path(skeleton, path, coarse_path);
    }
    if(path.empty())
      add_along_coarser_branch(skeleton, coarse_path);
    return !path.empty();
  }

  // The goal of a branch routed to node `near`: its finer voxel, or a voxel next to the
  // skeleton around it that touches the skeleton in one place, so that the branch closes no
  // cycle there.
  template <typename VoxelSet>
  auto goal_around(const VoxelSet& skeleton, int near) const
  {
    const Voxel_key goal = m_fine_node[std::size_t(near)];
    return [this, &skeleton, near, goal](const Voxel_key& k) {
      return k == goal || (m_cells[m_layout.index(k)].near_skeleton && near_node(k, near) && touches_once(skeleton, k));
    };
  }

  // One search of branch `e` from `start` to a voxel that `is_goal` accepts, in the window of
  // the branch (reopened, for the skeleton as it is now). No voxel of the path but its goal
  // touches the skeleton, except within `start_reach` of `start` when `start` is on it (or
  // on `avoid`), and around the near node when `near_may_touch`; none touches the voxels of
  // `avoid` (a leg not yet on the skeleton) but within `start_reach` of `start`. Returns the
  // path from `start` to the goal, or nothing.
  template <typename VoxelSet, typename IsGoal>
  std::vector<Voxel_key> route_leg(const VoxelSet& skeleton, int e, int far, int near, const Voxel_key& start,
                                   double start_reach, const IsGoal& is_goal, bool near_may_touch = false,
                                   const std::vector<Voxel_key>* avoid = nullptr)
  {
    const Voxel_branches::Branch& branch = m_coarse.branches[std::size_t(e)];
    open_window(skeleton, branch.voxels, far, near);
    if(!m_layout.box.contains(start))
      return {};
    const bool start_on_skeleton = skeleton.contains(start) || avoid != nullptr;
    if(avoid != nullptr)
      for(const Voxel_key& k : *avoid)
        for(const Voxel_key& offset : neighbourhood_26())
          if(m_layout.box.contains(k + offset) &&
             double(squared_distance_between(k + offset, start)) > start_reach * start_reach)
            m_cells[m_layout.index(k + offset)].avoided = true;
    auto passable = [&](std::size_t i, const Voxel_key& k) {
      if(!m_fine.inside(k))
        return false;
      const std::int32_t label = label_of(i, k);
      if(label < 0 || m_allowed[std::size_t(label)] != e || m_cells[i].avoided)
        return false;
      return !m_cells[i].near_skeleton || is_goal(k) || (near_may_touch && near_node(k, near)) ||
             (start_on_skeleton && double(squared_distance_between(k, start)) <= start_reach * start_reach);
    };
    const Voxel_key goal = m_fine_node[std::size_t(near)];
    const double reach = m_node_radius[std::size_t(near)] + 2;
    const std::size_t node_label = m_coarse.branches.size();
    const double largest_radius = (std::max)({m_largest_radius_of_label[std::size_t(e)],
                                              m_largest_radius_of_label[node_label + std::size_t(far)],
                                              m_largest_radius_of_label[node_label + std::size_t(near)], 1.0});
    // A lower bound of the cost to the near node's goals; through the middle of a cycle's
    // branch, the middle is farther, and the bound holds still.
    auto estimate = [&](const Voxel_key& k) {
      return (std::max)(0.0, std::sqrt(double(squared_distance_between(k, goal))) - reach) / largest_radius;
    };
    // Each step costs its length over the MAT radius of the voxel it enters, twice that off
    // the coarser skeleton's voxels: where the MAT radius is flat (across a sheet, along a
    // slab) the branch keeps to where the coarser grid put it.
    auto step_cost = [&](const Voxel_key& k, std::uint8_t, const Voxel_key& next, std::size_t i) {
      return passable(i, next)
                 ? std::optional<float>(float(step_cost_through_the_middle(m_fine, k, next) * (1 + m_cells[i].off_skeleton)))
                 : std::nullopt;
    };
    return m_search.cheapest_path(m_layout, start, is_goal, step_cost, estimate);
  }

  // Adds the voxels of `path`, each standing for the voxel of `coarse_path` at the same
  // share of its length.
  template <typename VoxelSet>
  void add_path(VoxelSet& skeleton, const std::vector<Voxel_key>& path, const std::vector<Voxel_key>& coarse_path)
  {
    for(std::size_t i = 0; i < path.size(); ++i)
    {
      const std::size_t along = path.size() == 1 ? 0 : i * (coarse_path.size() - 1) / (path.size() - 1);
      add(skeleton, path[i], coarse_path[along]);
    }
  }

  // The straight voxel paths between the finer voxels of consecutive voxels of the coarser
  // branch, each standing for the nearer of the two.
  template <typename VoxelSet>
  void add_along_coarser_branch(VoxelSet& skeleton, const std::vector<Voxel_key>& coarse_path)
  {
    for(std::size_t i = 0; i + 1 < coarse_path.size(); ++i)
    {
      const std::vector<Voxel_key> segment =
          straight_voxel_path(fine_voxel(coarse_path[i]), fine_voxel(coarse_path[i + 1]));
      for(std::size_t j = 0; j < segment.size(); ++j)
        add(skeleton, segment[j], coarse_path[2 * j < segment.size() ? i : i + 1]);
    }
  }

  Voxel_key fine_voxel(const Voxel_key& coarse) const
  {
    const auto node = std::find(m_coarse.nodes.begin(), m_coarse.nodes.end(), coarse);
    return node != m_coarse.nodes.end() ? m_fine_node[std::size_t(node - m_coarse.nodes.begin())]
                                        : voxel_in_frame(m_coarse_frame, m_fine.frame(), coarse);
  }

  const Voxel_branches& m_coarse;
  const Voxel_frame& m_coarse_frame;
  const Voxel_distance_field& m_fine;
  const Nearest_branch_labels m_labels;
  Grid_layout m_layout{Voxel_box{}};         // the window of the branch being routed
  std::vector<Cell> m_cells;                 // per voxel of the window
  Medial_path_search<float> m_search;
  std::vector<int> m_allowed;                // per label: the branch being routed that may pass it
  std::vector<Voxel_key> m_fine_node;
  std::vector<double> m_node_radius;
  std::vector<double> m_largest_radius_of_label;

  Coarser_voxel_map& m_coarser_voxel;
};

} // namespace internal

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_ROUTE_SKELETON_ON_FINER_GRID_FINER_GRID_ROUTER_H
