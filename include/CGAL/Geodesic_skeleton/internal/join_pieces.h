// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_JOIN_PIECES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_JOIN_PIECES_H

// The machinery of join_pieces_joined_on_coarser_grid()
// (include/CGAL/Geodesic_skeleton/join_pieces_joined_on_coarser_grid.h): not part of the API.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>

#include <boost/pending/disjoint_sets.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A run of voxels along x: (x0..x1, y, z), x1 included.
struct Voxel_run
{
  int y, z, x0, x1;
};

// The runs of a voxel set along x, and the 26-connected piece of each.
struct Runs_and_pieces
{
  std::vector<Voxel_run> runs; // in (z, y, x) order
  std::vector<std::size_t> piece; // of each run, numbered in the order of their first runs
  std::size_t pieces = 0;
};

// The runs of `voxels` and their pieces, by a union-find over the runs: two runs in rows next
// to each other (y and z differing by at most one) are in one piece when their x ranges, one
// of them grown by a voxel, overlap. Complexity: O(V + R) time for V voxels in R runs (rows
// have few runs), O(R + rows of the box) memory, when the set visits its voxels in (z, y, x)
// order; O(V log V) time and O(V) memory to sort them otherwise.
template <typename VoxelSet>
Runs_and_pieces runs_and_pieces(const VoxelSet& voxels)
{
  Runs_and_pieces out;
  std::vector<Voxel_run>& runs = out.runs;
  const auto add = [&](const Voxel_key& k) { // in (z, y, x) order
    if(!runs.empty() && runs.back().z == k.z && runs.back().y == k.y && runs.back().x1 + 1 == k.x)
      runs.back().x1 = k.x;
    else
      runs.push_back(Voxel_run{k.y, k.z, k.x, k.x});
  };
  // A model may visit its voxels in any order (Dense_voxel_grid's is (z, y, x)).
  bool ordered = true;
  voxels.for_each([&](const Voxel_key& k) {
    const Voxel_run* last = runs.empty() ? nullptr : &runs.back();
    ordered = ordered && (last == nullptr || Voxel_key{last->x1, last->y, last->z} < k);
    add(k);
  });
  if(!ordered)
  {
    runs.clear();
    std::vector<Voxel_key> keys;
    voxels.for_each([&](const Voxel_key& k) { keys.push_back(k); });
    std::sort(keys.begin(), keys.end());
    for(const Voxel_key& k : keys)
      add(k);
  }
  // The runs of each row (one y and z) are consecutive: row_start[row] to row_start[row + 1].
  const Voxel_box box = voxels.bounding_box();
  const std::size_t ny = box.extent()[1], nz = box.extent()[2];
  const auto row_of = [&](int y, int z) { return std::size_t(z - box.min.z) * ny + std::size_t(y - box.min.y); };
  std::vector<std::size_t> row_start(ny * nz + 1, 0);
  for(const Voxel_run& r : runs)
    ++row_start[row_of(r.y, r.z) + 1];
  for(std::size_t i = 1; i < row_start.size(); ++i)
    row_start[i] += row_start[i - 1];

  boost::disjoint_sets_with_storage<> pieces(runs.size());
  for(std::size_t i = 0; i < runs.size(); ++i)
  {
    const Voxel_run& r = runs[i];
    // The rows before this one in (z, y) order that touch it.
    const int earlier[4][2] = {{r.y - 1, r.z}, {r.y - 1, r.z - 1}, {r.y, r.z - 1}, {r.y + 1, r.z - 1}};
    for(const auto& [y, z] : earlier)
    {
      if(y < box.min.y || y >= box.max.y || z < box.min.z)
        continue;
      const std::size_t row = row_of(y, z);
      for(std::size_t j = row_start[row]; j < row_start[row + 1]; ++j)
        if(runs[j].x0 <= r.x1 + 1 && r.x0 <= runs[j].x1 + 1)
          pieces.union_set(i, j);
    }
  }
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> number(runs.size(), none);
  out.piece.resize(runs.size());
  for(std::size_t i = 0; i < runs.size(); ++i)
  {
    std::size_t& n = number[pieces.find_set(i)];
    if(n == none)
      n = out.pieces++;
    out.piece[i] = n;
  }
  return out;
}

// Calls `f(k, piece)` for every voxel of the runs.
template <typename Function>
void for_each_voxel_of_runs(const Runs_and_pieces& rp, const Function& f)
{
  for(std::size_t i = 0; i < rp.runs.size(); ++i)
    for(int x = rp.runs[i].x0; x <= rp.runs[i].x1; ++x)
      f(Voxel_key{x, rp.runs[i].y, rp.runs[i].z}, rp.piece[i]);
}

// The piece of every voxel of a (coarse) voxel set, read by key.
class Voxel_pieces
{
public:
  template <typename VoxelSet>
  explicit Voxel_pieces(const VoxelSet& voxels) : m_layout(voxels.bounding_box()), m_piece(m_layout.volume(), -1)
  {
    for_each_voxel_of_runs(runs_and_pieces(voxels), [&](const Voxel_key& k, std::size_t piece) {
      m_piece[m_layout.index(k)] = std::int32_t(piece);
    });
  }
  // The piece of voxel `k`, or -1 when `k` is not in the set.
  std::int32_t operator()(const Voxel_key& k) const
  {
    return m_layout.box.contains(k) ? m_piece[m_layout.index(k)] : -1;
  }

private:
  Grid_layout m_layout;
  std::vector<std::int32_t> m_piece;
};

// The voxel of grid `to` that holds the centre of each voxel of grid `from`, by the affine
// map between their grid coordinates. A finer grid of half the voxels, both centred on the
// mesh, puts every other centre on a face between two voxels of the coarser one; rounding
// in world coordinates would pick either, and differently when the mesh moves. A nudge of
// 1e-7 voxel along each axis always picks the upper one.
class Voxel_of_centre
{
public:
  Voxel_of_centre(const Voxel_frame& from, const Voxel_frame& to)
  {
    m_offset = to.to_grid(from.to_world(Voxel_frame::Vector{0.5, 0.5, 0.5}));
    for(int i = 0; i < 3; ++i)
    {
      Voxel_frame::Vector unit{0.5, 0.5, 0.5};
      unit[i] += 1;
      const Voxel_frame::Vector g = to.to_grid(from.to_world(unit));
      for(int j = 0; j < 3; ++j)
        m_step[i][j] = g[j] - m_offset[j];
    }
  }
  Voxel_key operator()(const Voxel_key& k) const
  {
    int c[3];
    for(int j = 0; j < 3; ++j)
      c[j] = int(std::floor(m_offset[j] + k.x * m_step[0][j] + k.y * m_step[1][j] + k.z * m_step[2][j] + 1e-7));
    return Voxel_key{c[0], c[1], c[2]};
  }

private:
  Voxel_frame::Vector m_offset;
  Voxel_frame::Vector m_step[3]; // the change of the coordinates for a step along each axis of `from`
};

// Where the pieces of a finer solid lie on a coarser grid.
struct Pieces_on_coarser_grid
{
  static constexpr std::int32_t no_piece = -1, several = -2;
  Grid_layout cells;                       // the coarse voxels around the coarse solid
  std::vector<std::int32_t> piece_in_cell; // of the voxel centres in each: no_piece, one, or several
  std::vector<std::size_t> coarse_of;      // the coarse piece of each piece (none: std::size_t(-1))

  std::int32_t piece_in(const Voxel_key& cell) const
  {
    return cells.box.contains(cell) ? piece_in_cell[cells.index(cell)] : no_piece;
  }
  // Whether a piece other than the one in `cell` has a voxel centre in it or next to it.
  bool another_piece_near(const Voxel_key& cell) const
  {
    const std::int32_t here = piece_in(cell);
    if(here == several)
      return true;
    for(const Voxel_key& o : neighbourhood_26())
    {
      const std::int32_t there = piece_in(cell + o);
      if(there != no_piece && there != here)
        return true;
    }
    return false;
  }
};

// Which pieces of `fine` have voxel centres in each coarse voxel, and the coarse piece of
// each piece: the piece of `coarse_solid` that holds the most of its voxel centres (ties: the
// first). Complexity: O(V + C) for the V voxels of `fine` and the C voxels of the coarse box.
template <typename CoarseVoxelSet, typename CellOf>
Pieces_on_coarser_grid pieces_on_coarser_grid(const Runs_and_pieces& fine, const CoarseVoxelSet& coarse_solid,
                                              const CellOf& cell_of)
{
  Pieces_on_coarser_grid on;
  // A voxel centre of the finer solid is within a coarse voxel of the coarse solid.
  on.cells = Grid_layout(coarse_solid.bounding_box().grown(2));
  on.piece_in_cell.assign(on.cells.volume(), Pieces_on_coarser_grid::no_piece);
  const Voxel_pieces coarse_piece(coarse_solid);
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> votes(fine.pieces); // (coarse piece, voxels)
  for_each_voxel_of_runs(fine, [&](const Voxel_key& k, std::size_t piece) {
    const Voxel_key cell = cell_of(k);
    if(!on.cells.box.contains(cell))
      return;
    std::int32_t& in_cell = on.piece_in_cell[on.cells.index(cell)];
    if(in_cell == Pieces_on_coarser_grid::no_piece)
      in_cell = std::int32_t(piece);
    else if(in_cell != std::int32_t(piece))
      in_cell = Pieces_on_coarser_grid::several;
    const std::int32_t coarse = coarse_piece(cell);
    if(coarse < 0)
      return;
    auto& v = votes[piece];
    auto it = std::find_if(v.begin(), v.end(), [&](const auto& e) { return e.first == std::size_t(coarse); });
    if(it == v.end())
      v.emplace_back(std::size_t(coarse), 1);
    else
      ++it->second;
  });
  on.coarse_of.assign(fine.pieces, std::size_t(-1));
  for(std::size_t p = 0; p < fine.pieces; ++p)
  {
    std::sort(votes[p].begin(), votes[p].end());
    std::size_t most = 0;
    for(const auto& [coarse, count] : votes[p])
      if(count > most)
      {
        most = count;
        on.coarse_of[p] = coarse;
      }
  }
  return on;
}

// A voxel of a piece in a coarse voxel where another piece comes near: a candidate end of
// a link.
struct Contact_voxel
{
  Voxel_key key;
  std::size_t piece;
  Voxel_key cell; // the coarse voxel of its centre
};

// The voxels on the boundary of the pieces `fine` of `solid` (a 26-neighbour is not in it)
// whose coarse voxel has another piece in it or next to it, in the order of the runs.
template <typename VoxelSet, typename CellOf>
std::vector<Contact_voxel> contact_voxels(const VoxelSet& solid, const Runs_and_pieces& fine,
                                          const Pieces_on_coarser_grid& on, const CellOf& cell_of)
{
  std::vector<std::uint8_t> near(on.cells.volume(), 0); // 0: not asked yet, 1: near, 2: not near
  std::vector<Contact_voxel> contacts;
  for_each_voxel_of_runs(fine, [&](const Voxel_key& k, std::size_t piece) {
    const Voxel_key cell = cell_of(k);
    if(!on.cells.box.contains(cell) || on.coarse_of[piece] == std::size_t(-1))
      return;
    std::uint8_t& n = near[on.cells.index(cell)];
    if(n == 0)
      n = on.another_piece_near(cell) ? 1 : 2;
    if(n == 2)
      return;
    for(const Voxel_key& o : neighbourhood_26())
      if(!solid.contains(k + o))
      {
        contacts.push_back(Contact_voxel{k, piece, cell});
        return;
      }
  });
  return contacts;
}

// A shortest link found between two pieces: its length (voxels) and its two end voxels
// (indices into the contact voxels).
struct Piece_link
{
  double length;
  std::size_t from, to; // from's piece < to's piece
};

inline bool shorter_link(const Piece_link& a, const Piece_link& b)
{
  return std::tie(a.length, a.from, a.to) < std::tie(b.length, b.from, b.to);
}

// The shortest link between each two pieces of one coarse piece whose contact voxels lie in
// the same or neighbouring coarse voxels, shortest first.
inline std::vector<Piece_link> shortest_links(const std::vector<Contact_voxel>& contacts,
                                              const std::vector<std::size_t>& coarse_of)
{
  std::unordered_map<Voxel_key, std::vector<std::size_t>, Voxel_key_hash> in_cell;
  for(std::size_t i = 0; i < contacts.size(); ++i)
    in_cell[contacts[i].cell].push_back(i);
  std::map<std::pair<std::size_t, std::size_t>, Piece_link> shortest;
  const auto link_pieces_of = [&](const std::vector<std::size_t>& here, const std::vector<std::size_t>& there) {
    for(std::size_t a : here)
      for(std::size_t b : there)
      {
        const std::size_t pa = contacts[a].piece, pb = contacts[b].piece;
        if(pa >= pb || coarse_of[pa] != coarse_of[pb])
          continue;
        const Voxel_key& ka = contacts[a].key;
        const Voxel_key& kb = contacts[b].key;
        const double length = std::sqrt(double(squared_distance_between(ka, kb)));
        const Piece_link link{length, a, b};
        const auto [it, inserted] = shortest.emplace(std::make_pair(pa, pb), link);
        if(!inserted && shorter_link(link, it->second))
          it->second = link;
      }
  };
  for(const auto& [cell, here] : in_cell)
  {
    link_pieces_of(here, here);
    for(const Voxel_key& o : neighbourhood_26())
    {
      const auto there = in_cell.find(cell + o);
      if(there != in_cell.end())
        link_pieces_of(here, there->second);
    }
  }
  std::vector<Piece_link> links;
  for(const auto& entry : shortest)
    links.push_back(entry.second);
  std::sort(links.begin(), links.end(), shorter_link);
  return links;
}

// The voxels of the segment from voxel `a` to voxel `b`, one per step along the axis on
// which they are farthest apart (a 26-connected line, the fewest voxels that join them).
inline std::vector<Voxel_key> voxels_of_segment(const Voxel_key& a, const Voxel_key& b)
{
  const int steps = (std::max)({std::abs(b.x - a.x), std::abs(b.y - a.y), std::abs(b.z - a.z)});
  const auto at = [&](int from, int to, int s) {
    return steps == 0 ? from : from + int(std::floor(double(to - from) * s / steps + 0.5));
  };
  std::vector<Voxel_key> line;
  for(int s = 0; s <= steps; ++s)
    line.push_back(Voxel_key{at(a.x, b.x, s), at(a.y, b.y, s), at(a.z, b.z, s)});
  return line;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_JOIN_PIECES_H
