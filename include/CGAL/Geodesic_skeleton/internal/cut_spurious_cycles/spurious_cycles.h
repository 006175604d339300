// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_SPURIOUS_CYCLES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_SPURIOUS_CYCLES_H

// The machinery of cut_spurious_cycles() (include/CGAL/Geodesic_skeleton/cut_spurious_cycles.h): not part of the API.

#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/geodesics/vertex_components.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The number of handles the mesh's surface has: the sum over its connected components of
// the genus (2 - chi) / 2 of the component with each hole capped by a disc (chi = V - E + F
// + holes). For a closed, embedded, orientable mesh whose components do not overlap, it is
// the number of tunnels of the solid it bounds. `components`: the mesh's
// vertex_components().
template <typename FaceGraph>
std::size_t capped_genus_sum(const FaceGraph& mesh, const Vertex_components& components)
{
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  const auto component = [&](auto v) { return components.component_of[std::size_t(get(vim, v))]; };
  std::vector<long> chi(components.count, 0);
  for(auto v : vertices(mesh))
    ++chi[component(v)];
  for(auto e : edges(mesh))
    --chi[component(source(e, mesh))];
  for(auto f : faces(mesh))
    ++chi[component(target(halfedge(f, mesh), mesh))];
  // Holes: cycles of border halfedges, each capped by a disc.
  for_each_border_cycle(mesh, [&](const auto& cycle) { ++chi[component(target(cycle.front(), mesh))]; });
  std::size_t genus = 0;
  for(long c : chi)
    if(c < 2)
      genus += std::size_t((2 - c) / 2);
  return genus;
}

// Components and cycle rank (E - V + C) of the graph restricted to the nodes not removed.
inline std::pair<std::size_t, std::size_t> components_and_cycles(const Skeleton_adjacency& graph,
                                                                 const std::vector<bool>& removed)
{
  boost::disjoint_sets_with_storage<> sets(graph.nodes.size());
  std::size_t nodes = 0, edges = 0;
  for(const auto& e : graph.edges)
    if(!removed[std::size_t(e.first)] && !removed[std::size_t(e.second)])
    {
      ++edges;
      sets.union_set(std::size_t(e.first), std::size_t(e.second));
    }
  std::size_t components = 0;
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    if(!removed[v])
    {
      ++nodes;
      components += sets.find_set(v) == v;
    }
  return {components, edges + components - nodes};
}

// Whether each node lies on a cycle: it has an edge that is no bridge (Tarjan's low links,
// by an iterative depth-first search).
inline std::vector<bool> nodes_on_cycles(const Skeleton_adjacency& graph)
{
  const std::size_t n = graph.nodes.size();
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> incident(n); // (neighbour, edge)
  for(std::size_t e = 0; e < graph.edges.size(); ++e)
  {
    incident[std::size_t(graph.edges[e].first)].emplace_back(std::size_t(graph.edges[e].second), e);
    incident[std::size_t(graph.edges[e].second)].emplace_back(std::size_t(graph.edges[e].first), e);
  }
  const std::size_t unseen = std::size_t(-1);
  std::vector<std::size_t> order(n, unseen), low(n, 0), parent_edge(n, unseen), cursor(n, 0);
  std::vector<bool> on_cycle(n, false);
  std::size_t clock = 0;
  for(std::size_t root = 0; root < n; ++root)
  {
    if(order[root] != unseen)
      continue;
    std::vector<std::size_t> stack{root};
    order[root] = low[root] = clock++;
    while(!stack.empty())
    {
      const std::size_t v = stack.back();
      if(cursor[v] < incident[v].size())
      {
        const auto [w, e] = incident[v][cursor[v]++];
        if(e == parent_edge[v])
          continue;
        if(order[w] == unseen)
        {
          order[w] = low[w] = clock++;
          parent_edge[w] = e;
          stack.push_back(w);
        }
        else
          low[v] = (std::min)(low[v], order[w]);
        continue;
      }
      stack.pop_back();
      if(stack.empty())
        continue;
      const std::size_t u = stack.back();
      low[u] = (std::min)(low[u], low[v]);
      if(low[v] <= order[u]) // the edge u-v is no bridge
        on_cycle[u] = on_cycle[v] = true;
    }
  }
  // A back edge's ends are on its cycle too (covered above: the tree edges of a cycle are no
  // bridges, and every node of the cycle has one of them).
  return on_cycle;
}

// Whether the segment [from, to] of a balanced line passes through a point where one part
// of the surface winds twice around it (|winding| >= 2 counting that part's crossings
// only): two pieces of one connected surface overlap there (a camel's front legs that
// interpenetrate), which is a gap between them as much as a point outside is. A part whose
// own crossings on the line do not sum to zero cannot tell. Separate parts that overlap
// (pieces an artist pushed into each other) wind once each: they are one solid.
// `part_of_triangle` names the part of each triangle of the surface.
inline bool passes_where_a_part_overlaps_itself(const Hit_range& hits, double from, double to,
                                                const std::vector<std::uint32_t>& part_of_triangle)
{
  // (part, winding so far, sum of all its crossings); a line meets few parts.
  struct Part_winding
  {
    std::uint32_t part;
    int winding, total;
  };
  std::vector<Part_winding> parts;
  const auto of = [&](std::uint32_t part) -> Part_winding& {
    for(Part_winding& p : parts)
      if(p.part == part)
        return p;
    parts.push_back(Part_winding{part, 0, 0});
    return parts.back();
  };
  for(const Line_hit& h : hits)
    of(part_of_triangle[h.triangle]).total += h.sign;
  const auto overlaps = [](const Part_winding& p) { return p.total == 0 && std::abs(p.winding) >= 2; };
  const Line_hit* h = hits.begin();
  for(; h != hits.end() && h->at < from; ++h) // the windings at `from`
    of(part_of_triangle[h->triangle]).winding += h->sign;
  if(std::any_of(parts.begin(), parts.end(), overlaps))
    return true;
  for(; h != hits.end() && h->at < to; ++h) // and where they change on the segment
  {
    Part_winding& p = of(part_of_triangle[h->triangle]);
    p.winding += h->sign;
    if(overlaps(p))
      return true;
  }
  return false;
}

// Whether the straight steps between the centres of 26-adjacent voxels leave the inside of
// the surface `g` (grid coordinates). A step is walked along the grid axes, through the
// centres of the voxels between (one, two or three unit moves, in every order); it leaves
// the inside when every such walk meets a point of winding number zero, or a point where a
// part of the surface overlaps itself (passes_where_a_part_overlaps_itself(), when the
// part of each triangle is known). A unit move whose line cannot decide (its crossings do
// not sum to zero) counts as inside. `part_of_triangle()` returns the part of each
// triangle, or null when they are not known; it is called only when a move passes where
// the surface winds twice or more (most meshes never overlap, and naming the parts costs
// a pass over the mesh).
class Inside_steps
{
public:
  Inside_steps(const Grid_line_crossings& g, std::function<const std::vector<std::uint32_t>*()> part_of_triangle)
    : m_g(g), m_part_of_triangle(std::move(part_of_triangle))
  {}

  // Decides every step of `steps` (pairs of adjacent voxels) at once.
  std::vector<bool> leave_inside(const std::vector<std::pair<Voxel_key, Voxel_key>>& steps)
  {
    // Every walk of every step, as the unit moves it makes: (axis, u, v, start along axis).
    using Move = std::array<int, 4>;
    std::vector<std::pair<Move, std::uint32_t>> uses; // (move, walk)
    std::vector<std::uint32_t> walk_step;             // the step of each walk
    for(std::size_t s = 0; s < steps.size(); ++s)
    {
      const Voxel_key& from = steps[s].first;
      const int o[3] = {steps[s].second.x - from.x, steps[s].second.y - from.y, steps[s].second.z - from.z};
      std::array<int, 3> axes{};
      int count = 0;
      for(int a = 0; a < 3; ++a)
        if(o[a] != 0)
          axes[std::size_t(count++)] = a;
      do
      {
        const std::uint32_t walk = std::uint32_t(walk_step.size());
        walk_step.push_back(std::uint32_t(s));
        int at[3] = {from.x, from.y, from.z};
        for(int k = 0; k < count; ++k)
        {
          const int a = axes[std::size_t(k)];
          uses.emplace_back(Move{a, at[(a + 1) % 3], at[(a + 2) % 3], (std::min)(at[a], at[a] + o[a])}, walk);
          at[a] += o[a];
        }
      } while(std::next_permutation(axes.begin(), axes.begin() + count));
    }
    std::vector<Move> moves;
    moves.reserve(uses.size());
    for(const auto& use : uses)
      moves.push_back(use.first);
    std::sort(moves.begin(), moves.end());
    moves.erase(std::unique(moves.begin(), moves.end()), moves.end());

    // Decide each unit move on its line (the moves are sorted by axis first).
    std::vector<bool> move_leaves(moves.size(), false);
    for(int axis = 0; axis < 3; ++axis)
    {
      const auto first = std::lower_bound(moves.begin(), moves.end(), Move{axis, INT_MIN, INT_MIN, INT_MIN});
      const auto last = std::lower_bound(moves.begin(), moves.end(), Move{axis + 1, INT_MIN, INT_MIN, INT_MIN});
      std::vector<std::array<double, 2>> lines;
      for(auto m = first; m != last; ++m)
        lines.push_back({(*m)[1] + 0.5, (*m)[2] + 0.5});
      const auto hits = m_g.crossings(axis, lines);
      for(std::size_t l = 0; l < lines.size(); ++l)
      {
        if(!is_balanced(hits[l]))
          continue;
        const std::size_t m = std::size_t(first - moves.begin()) + l;
        const double from = moves[m][3] + 0.5, to = from + 1;
        int winding = winding_before(hits[l], from);
        bool leaves = winding == 0, overlapped = std::abs(winding) >= 2;
        for(const Line_hit& h : hits[l])
          if(h.at >= from && h.at < to)
          {
            winding += h.sign;
            leaves = leaves || winding == 0;
            overlapped = overlapped || std::abs(winding) >= 2;
          }
        if(!leaves && overlapped)
          if(const std::vector<std::uint32_t>* parts = m_part_of_triangle())
            leaves = passes_where_a_part_overlaps_itself(hits[l], from, to, *parts);
        move_leaves[m] = leaves;
      }
    }
    // A walk leaves when one of its moves does; a step, when all its walks do.
    std::vector<bool> walk_leaves(walk_step.size(), false);
    for(const auto& use : uses)
      if(move_leaves[std::size_t(std::lower_bound(moves.begin(), moves.end(), use.first) - moves.begin())])
        walk_leaves[use.second] = true;
    std::vector<bool> leaves(steps.size(), true);
    for(std::size_t w = 0; w < walk_step.size(); ++w)
      if(!walk_leaves[w])
        leaves[walk_step[w]] = false;
    return leaves;
  }

private:
  const Grid_line_crossings& m_g;
  std::function<const std::vector<std::uint32_t>*()> m_part_of_triangle;
};

// The components and cycle rank of the skeleton's graph without the `removed` nodes of
// `graph`, the graph built anew on the voxels left: a removed voxel can free an edge that a
// junction triangle through it hid, and that edge can close again the cycle the removal
// opened, which the restriction of `graph` would not show. `node_of(k)` is the index in
// `graph` of voxel k, or -1.
template <typename NodeOf>
std::pair<std::size_t, std::size_t> components_and_cycles_left(const Skeleton_adjacency& graph,
                                                               const std::vector<bool>& removed,
                                                               const NodeOf& node_of)
{
  std::vector<Voxel_key> left;
  std::vector<std::int32_t> index_left(graph.nodes.size(), -1);
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    if(!removed[v])
    {
      index_left[v] = std::int32_t(left.size());
      left.push_back(graph.nodes[v]);
    }
  const Skeleton_adjacency rebuilt = skeleton_adjacency(std::move(left), [&](const Voxel_key& k) {
    const std::int32_t v = node_of(k);
    return v >= 0 ? index_left[std::size_t(v)] : std::int32_t(-1);
  });
  return components_and_cycles(rebuilt, std::vector<bool>(rebuilt.nodes.size(), false));
}

// The steps of a skeleton's graph between two voxels on cycles (its edges between nodes on
// cycles), each with whether it leaves the mesh (Inside_steps::leave_inside()).
struct Cycle_steps
{
  std::vector<std::pair<Voxel_key, Voxel_key>> steps;
  std::vector<std::size_t> edge; // the edge of the graph of each step
  std::vector<bool> leaves;      // filled by the caller, one per step
};

inline Cycle_steps cycle_steps(const Skeleton_adjacency& graph, const std::vector<bool>& on_cycle)
{
  Cycle_steps c;
  for(std::size_t e = 0; e < graph.edges.size(); ++e)
  {
    const auto [a, b] = graph.edges[e];
    if(on_cycle[std::size_t(a)] && on_cycle[std::size_t(b)])
    {
      c.steps.emplace_back(graph.nodes[std::size_t(a)], graph.nodes[std::size_t(b)]);
      c.edge.push_back(e);
    }
  }
  return c;
}

// What a pass of the cut tries removing, in order: single voxels of `graph` on cycles with a
// step out of the mesh's inside (`cycle`, from cycle_steps() with its `leaves` filled): those
// whose every step leaves, i.e. whose centre is outside, first; then the others, by the
// number of steps out (a voxel of the cycle on a side of the gap; cut_pass() orders both
// again); then runs of such voxels (connected groups, shortest first), for where removing one
// voxel would split the skeleton.
struct Cut_trials
{
  std::vector<std::vector<std::size_t>> trials;
  std::size_t centre_outside = 0; // trials [0, centre_outside) are the voxels whose centre is outside
  std::size_t singles = 0;        // and [centre_outside, singles) the other single voxels
};

inline Cut_trials cut_trials(const Skeleton_adjacency& graph, const Cycle_steps& cycle)
{
  const auto& steps = cycle.steps;
  const auto& step_edge = cycle.edge;
  const std::vector<bool>& leaves = cycle.leaves;
  std::vector<int> leaving_steps(graph.nodes.size(), 0), steps_on_cycles(graph.nodes.size(), 0);
  for(std::size_t k = 0; k < steps.size(); ++k)
    for(int end : {graph.edges[step_edge[k]].first, graph.edges[step_edge[k]].second})
    {
      ++steps_on_cycles[std::size_t(end)];
      leaving_steps[std::size_t(end)] += leaves[k];
    }

  std::vector<std::size_t> singles;
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    if(leaving_steps[v] > 0)
      singles.push_back(v);
  const auto centre_outside = [&](std::size_t v) { return leaving_steps[v] == steps_on_cycles[v]; };
  std::stable_sort(singles.begin(), singles.end(), [&](std::size_t a, std::size_t b) {
    return centre_outside(a) != centre_outside(b) ? centre_outside(a) : leaving_steps[a] > leaving_steps[b];
  });
  Cut_trials result;
  std::vector<std::vector<std::size_t>>& trials = result.trials;
  for(std::size_t v : singles)
  {
    result.centre_outside += centre_outside(v);
    trials.push_back({v});
  }
  result.singles = trials.size();
  boost::disjoint_sets_with_storage<> runs_of(graph.nodes.size());
  for(const auto& e : graph.edges)
    if(leaving_steps[std::size_t(e.first)] > 0 && leaving_steps[std::size_t(e.second)] > 0)
      runs_of.union_set(std::size_t(e.first), std::size_t(e.second));
  std::vector<std::vector<std::size_t>> runs;
  {
    std::vector<std::size_t> run_index(graph.nodes.size(), std::size_t(-1));
    for(std::size_t v : singles)
    {
      std::size_t& r = run_index[runs_of.find_set(v)];
      if(r == std::size_t(-1))
      {
        r = runs.size();
        runs.emplace_back();
      }
      runs[r].push_back(v);
    }
  }
  std::stable_sort(runs.begin(), runs.end(),
                   [](const auto& a, const auto& b) { return a.size() < b.size(); });
  for(auto& run : runs)
    if(run.size() > 1)
      trials.push_back(std::move(run));
  return result;
}

// Sorts the single voxels of `cut` farthest from the middle first, those whose centre is
// outside, then the others (stable: ties keep their order). Asks for no distance when
// neither group has two voxels to order.
template <typename DistancesFromTheMiddle>
void order_farthest_from_the_middle(Cut_trials& cut, const Skeleton_adjacency& graph,
                                    DistancesFromTheMiddle& distances_from_the_middle)
{
  if(cut.centre_outside < 2 && cut.singles - cut.centre_outside < 2)
    return;
  std::vector<Voxel_key> voxels;
  for(std::size_t t = 0; t < cut.singles; ++t)
    voxels.push_back(graph.nodes[cut.trials[t].front()]);
  const std::vector<double> distance = distances_from_the_middle(voxels);
  std::vector<std::pair<double, std::vector<std::size_t>>> ranked;
  for(std::size_t t = 0; t < cut.singles; ++t)
    ranked.emplace_back(distance[t], std::move(cut.trials[t]));
  const auto farther = [](const auto& a, const auto& b) { return a.first > b.first; };
  std::stable_sort(ranked.begin(), ranked.begin() + std::ptrdiff_t(cut.centre_outside), farther);
  std::stable_sort(ranked.begin() + std::ptrdiff_t(cut.centre_outside), ranked.end(), farther);
  for(std::size_t t = 0; t < cut.singles; ++t)
    cut.trials[t] = std::move(ranked[t].second);
}

// One pass of the cut over `indexed`, the skeleton's graph as it is, which has `cycles`
// cycles, more than `handles`: tries `cut` (cut_trials() of that graph) in order, keeping
// each removal that lowers the number of cycles (counted on the graph rebuilt without the
// removed voxels) without splitting a component, while there are more cycles than
// `handles`. Returns the number of cycles left.
//
// The single voxels are tried farthest first by `distances_from_the_middle(voxels)` (how
// far along the mesh's surface each voxel lies from the middle of the model), those whose
// centre is outside before the others, ties in cut_trials()' order. What touches another
// part is most often the tip of a limb or of a tail, and a thin part pokes out of its own
// surface all along, so that voxels of its curve are outside at its root as well as where
// its tip touches: the tip's lie farther along the surface, and the part stays hung from
// its root.
template <typename VoxelSet, typename DistancesFromTheMiddle>
std::size_t cut_pass(VoxelSet& skeleton, const Indexed_skeleton_adjacency& indexed, std::size_t cycles,
                     Cut_trials cut, std::size_t handles, DistancesFromTheMiddle distances_from_the_middle)
{
  const Skeleton_adjacency& graph = indexed.graph;
  std::vector<bool> removed(graph.nodes.size(), false);
  const std::size_t components = components_and_cycles(graph, removed).first;
  const auto node_of = [&](const Voxel_key& k) { return indexed.node_of(k); };
  order_farthest_from_the_middle(cut, graph, distances_from_the_middle);
  for(std::size_t t = 0; t < cut.trials.size() && cycles > handles; ++t)
  {
    const std::vector<std::size_t>& trial = cut.trials[t];
    std::vector<std::size_t> fresh;
    for(std::size_t v : trial)
      if(!removed[v])
      {
        fresh.push_back(v);
        removed[v] = true;
      }
    if(fresh.empty())
      continue;
    const auto [c, b1] = components_and_cycles_left(graph, removed, node_of);
    if(c == components && b1 < cycles)
      cycles = b1;
    else
      for(std::size_t v : fresh)
        removed[v] = false;
  }
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
    if(removed[v])
      skeleton.erase(graph.nodes[v]);
  return cycles;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_SPURIOUS_CYCLES_H
