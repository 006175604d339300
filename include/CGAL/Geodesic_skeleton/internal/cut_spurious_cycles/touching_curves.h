// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_TOUCHING_CURVES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_TOUCHING_CURVES_H

// The moves that pull touching curves apart, which each pass of cut_spurious_cycles()
// (include/CGAL/Geodesic_skeleton/cut_spurious_cycles.h) tries before its removals
// (spurious_cycles.h), and the passes themselves: not part of the API.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/internal/cut_spurious_cycles/distance_from_the_middle.h>
#include <CGAL/Geodesic_skeleton/internal/cut_spurious_cycles/spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/voxel_components.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The 26 neighbour offsets, face neighbours first, then edge, then corner neighbours: the
// shortest moves first.
inline const std::array<Voxel_key, 26>& offsets_by_length()
{
  static const std::array<Voxel_key, 26> offsets = [] {
    std::array<Voxel_key, 26> o = neighbourhood_26();
    std::stable_sort(o.begin(), o.end(),
                     [](const Voxel_key& a, const Voxel_key& b) { return offset_order(a) < offset_order(b); });
    return o;
  }();
  return offsets;
}

// Whether moving skeleton voxel `from` to its free neighbour `to` separates the curve
// through `from` from another curve that it only touches, cutting neither. The neighbours
// of `from` split into those next to `to` and the others, and the move
// - keeps the curve through `from`: two of the neighbours next to `to` are not next to
//   each other, so that `from` linked them, and `to` still does;
// - lets go a piece of another curve: the other neighbours are not empty, and 26-connected
//   among themselves, so that they did not need `from` to stay linked;
// - leaves every voxel that had two neighbours or more, `to` included, with two or more
//   (no new end point).
template <typename VoxelSet>
bool moves_without_cutting_a_curve(const VoxelSet& skeleton, const Voxel_key& from, const Voxel_key& to,
                                   std::vector<Voxel_key>& let_go)
{
  std::vector<Voxel_key> kept;
  let_go.clear();
  for(const Voxel_key& o : neighbourhood_26())
  {
    const Voxel_key n = from + o;
    if(!skeleton.contains(n))
      continue;
    const bool linked = are_26_adjacent(n, to);
    (linked ? kept : let_go).push_back(n);
    const int degree = skeleton_degree(skeleton, n);
    if(degree >= 2 && degree - 1 + int(linked) < 2)
      return false;
  }
  bool keeps_curve = false;
  for(std::size_t a = 0; a < kept.size() && !keeps_curve; ++a)
    for(std::size_t b = a + 1; b < kept.size() && !keeps_curve; ++b)
      keeps_curve = !are_26_adjacent(kept[a], kept[b]);
  return keeps_curve && !let_go.empty() && are_26_connected(let_go) &&
         skeleton_degree(skeleton, to) - 1 >= 2; // `from` is counted among its neighbours
}

// A move of a skeleton voxel to a free neighbour (separate_touching_curves()).
struct Voxel_move
{
  Voxel_key from, to;
  std::vector<Voxel_key> let_go; // the neighbours of `from` that `to` is not next to
};

// The moves of the voxels of `graph` (the graph of `skeleton`) on cycles (`on_cycle`) with
// three neighbours or more to their free neighbours inside `skeleton.bounding_box()` that
// pass moves_without_cutting_a_curve(), voxel by voxel, the shortest move first.
template <typename VoxelSet>
std::vector<Voxel_move> moves_cutting_no_curve(const VoxelSet& skeleton, const Skeleton_adjacency& graph,
                                               const std::vector<bool>& on_cycle)
{
  const Voxel_box box = skeleton.bounding_box();
  std::vector<Voxel_move> moves;
  Voxel_move move;
  for(std::size_t v = 0; v < graph.nodes.size(); ++v)
  {
    move.from = graph.nodes[v];
    if(!on_cycle[v] || skeleton_degree(skeleton, move.from) < 3)
      continue;
    for(const Voxel_key& offset : offsets_by_length())
    {
      move.to = move.from + offset;
      if(!skeleton.contains(move.to) && box.contains(move.to) &&
         moves_without_cutting_a_curve(skeleton, move.from, move.to, move.let_go))
        moves.push_back(move);
    }
  }
  return moves;
}

// The steps whose leaving the mesh decides whether a move crosses a gap: from `from` to
// each voxel it lets go, then from `to` to each of its skeleton neighbours but `from`.
template <typename VoxelSet>
std::vector<std::pair<Voxel_key, Voxel_key>> steps_of_move(const VoxelSet& skeleton, const Voxel_move& m)
{
  std::vector<std::pair<Voxel_key, Voxel_key>> steps;
  for(const Voxel_key& n : m.let_go)
    steps.emplace_back(m.from, n);
  for(const Voxel_key& o : neighbourhood_26())
    if(m.to + o != m.from && skeleton.contains(m.to + o))
      steps.emplace_back(m.to, m.to + o);
  return steps;
}

// What one pass of cut_spurious_cycles() tests against the mesh, in one pass over it
// (Inside_steps): the steps of the graph between voxels on cycles (for cut_trials()), and
// the moves that cut no curve (moves_cutting_no_curve()), kept when they cross a gap of the
// mesh: every step from `from` to the voxels it lets go leaves the mesh, and no step from
// `to` to its skeleton neighbours but `from` does, so that `from` touched the other curve
// across the gap that two parts that nearly touch leave between them, and `to` is inside
// the part of `from`.
struct Cycle_evidence
{
  Cycle_steps cycle;
  std::vector<Voxel_move> moves_across_a_gap;
};

template <typename VoxelSet, typename MeshLines>
Cycle_evidence cycle_evidence(const VoxelSet& skeleton, const Skeleton_adjacency& graph, MeshLines& mesh_lines)
{
  const std::vector<bool> on_cycle = nodes_on_cycles(graph);
  Cycle_evidence e{cycle_steps(graph, on_cycle), {}};
  std::vector<Voxel_move> moves = moves_cutting_no_curve(skeleton, graph, on_cycle);
  std::vector<std::pair<Voxel_key, Voxel_key>> steps = e.cycle.steps;
  std::vector<std::size_t> first_step{steps.size()};
  for(const Voxel_move& m : moves)
  {
    const auto move_steps = steps_of_move(skeleton, m);
    steps.insert(steps.end(), move_steps.begin(), move_steps.end());
    first_step.push_back(steps.size());
  }
  const std::vector<bool> leaves =
      Inside_steps(mesh_lines(), [&] { return mesh_lines.triangle_parts(); }).leave_inside(steps);
  e.cycle.leaves.assign(leaves.begin(), leaves.begin() + std::ptrdiff_t(e.cycle.steps.size()));
  for(std::size_t k = 0; k < moves.size(); ++k)
  {
    bool crosses = true;
    for(std::size_t s = first_step[k]; s < first_step[k + 1] && crosses; ++s)
      crosses = leaves[s] == (s - first_step[k] < moves[k].let_go.size());
    if(crosses)
      e.moves_across_a_gap.push_back(std::move(moves[k]));
  }
  return e;
}

// Whether `a` and `b` are within two voxels of each other along every axis: then a move at
// one changes the neighbourhood that the tests of a move at the other looked at.
inline bool near_each_other(const Voxel_key& a, const Voxel_key& b)
{
  return std::abs(a.x - b.x) <= 2 && std::abs(a.y - b.y) <= 2 && std::abs(a.z - b.z) <= 2;
}

// Where two curves of a voxel skeleton touch (legs pressed together), a voxel of one curve
// is 26-adjacent to voxels of the other, and the contact closes a cycle. Removing the voxel
// would cut its curve in two; moving it to a free neighbour that still links its own curve
// but not the other one opens the cycle and keeps both curves whole. This tries `moves` in
// order, keeping each that lowers the number of cycles (counted on the graph of the
// skeleton as moved) without changing the number of `components`, while there are more
// `cycles` than `handles`. A move near a voxel that a kept move changed is left for the
// next pass: its tests looked at the skeleton before. Returns the number of cycles left.
template <typename VoxelSet>
std::size_t separate_touching_curves(VoxelSet& skeleton, const std::vector<Voxel_move>& moves, std::size_t cycles,
                                     std::size_t components, std::size_t handles)
{
  std::vector<Voxel_key> kept;
  for(const Voxel_move& m : moves)
  {
    if(cycles <= handles)
      break;
    if(std::any_of(kept.begin(), kept.end(), [&](const Voxel_key& k) {
         return near_each_other(k, m.from) || near_each_other(k, m.to);
       }))
      continue;
    skeleton.erase(m.from);
    skeleton.insert(m.to);
    const Skeleton_adjacency after = skeleton_adjacency(skeleton);
    const auto [c, b1] = components_and_cycles(after, std::vector<bool>(after.nodes.size(), false));
    if(c == components && b1 < cycles)
    {
      cycles = b1;
      kept.push_back(m.from);
      kept.push_back(m.to);
      continue;
    }
    skeleton.erase(m.to);
    skeleton.insert(m.from);
  }
  return cycles;
}

// cut_spurious_cycles() with its inside tests against `mesh_lines` (a Stage_surface:
// called, it returns the mesh's Grid_line_crossings in the frame of the skeleton, and its
// triangle_parts() the mesh component of each triangle; used only when there are more
// cycles than handles). Each pass tests the skeleton's graph against the mesh once
// (cycle_evidence()); then a move that pulls touching curves apart is tried first
// (separate_touching_curves(), which cuts no curve), and when one is kept, the pass starts
// again on the skeleton as moved; else voxels with a step out of the mesh are removed
// (cut_pass(), those farthest along the surface from the middle of the model first).
// Passes are repeated while they open cycles: a change can free edges whose steps the next
// pass tests.
template <typename VoxelSet, typename FaceGraph, typename MeshLines>
std::size_t cut_spurious_cycles_impl(VoxelSet& skeleton, const FaceGraph& mesh, MeshLines& mesh_lines)
{
  if(skeleton.size() == 0 || num_faces(mesh) == 0)
    return 0;
  // The graph is indexed over the skeleton's box as it is: a move can take a voxel out of
  // the box of the pass before (by one voxel per pass).
  const auto indexed_as_it_is = [&] {
    return indexed_skeleton_adjacency(skeleton, Grid_layout(require_nonempty_box(skeleton, 0, "cut_spurious_cycles")));
  };
  Indexed_skeleton_adjacency indexed = indexed_as_it_is();
  const auto [components, initial_cycles] =
      components_and_cycles(indexed.graph, std::vector<bool>(indexed.graph.nodes.size(), false));
  if(initial_cycles == 0)
    return 0;
  const std::size_t handles = capped_genus_sum(mesh, mesh_lines.vertex_components());
  std::optional<Surface_distance_from_the_middle> from_the_middle; // built when a pass first cuts
  const auto distances_from_the_middle = [&](const std::vector<Voxel_key>& voxels) {
    if(!from_the_middle)
      from_the_middle.emplace(mesh, mesh_lines.vertex_point_map(), mesh_lines.vertex_components(), skeleton.frame());
    return (*from_the_middle)(voxels);
  };
  std::size_t cycles = initial_cycles;
  while(cycles > handles)
  {
    const Cycle_evidence evidence = cycle_evidence(skeleton, indexed.graph, mesh_lines);
    std::size_t left = separate_touching_curves(skeleton, evidence.moves_across_a_gap, cycles, components, handles);
    if(left == cycles)
      left = cut_pass(skeleton, indexed, cycles, cut_trials(indexed.graph, evidence.cycle), handles,
                      distances_from_the_middle);
    if(left >= cycles)
      break;
    cycles = left;
    if(cycles > handles) // another pass, over the graph of the skeleton as changed
      indexed = indexed_as_it_is();
  }
  return initial_cycles - cycles;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_CUT_SPURIOUS_CYCLES_TOUCHING_CURVES_H
