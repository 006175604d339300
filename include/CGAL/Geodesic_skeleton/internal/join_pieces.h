// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_JOIN_PIECES_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_JOIN_PIECES_H

// The machinery of join_pieces_joined_on_coarser_grid()
// (include/CGAL/Geodesic_skeleton/join_pieces_joined_on_coarser_grid.h): not part of the API.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The number of 26-connected pieces of a voxel set, by a union-find over its runs of
// voxels along x: two runs in rows next to each other (y and z differing by at most one)
// are in one piece when their x ranges, one of them grown by a voxel, overlap.
// Complexity: O(V + R) time for V voxels in R runs (rows have few runs), O(R) memory.
template <typename VoxelSet>
std::size_t count_pieces(const VoxelSet& voxels)
{
  struct Run
  {
    int y, z, x0, x1; // x1 inclusive
  };
  std::vector<Run> runs;
  voxels.for_each([&](const Voxel_key& k) { // in (z, y, x) order
    if(!runs.empty() && runs.back().z == k.z && runs.back().y == k.y && runs.back().x1 + 1 == k.x)
      runs.back().x1 = k.x;
    else
      runs.push_back(Run{k.y, k.z, k.x, k.x});
  });
  // The runs of each row, a row being the runs of one (y, z), in order.
  const Voxel_box box = voxels.bounding_box();
  const std::size_t ny = std::size_t(box.max.y - box.min.y), nz = std::size_t(box.max.z - box.min.z);
  std::vector<std::size_t> row_start(ny * nz + 1, 0);
  for(const Run& r : runs)
    ++row_start[std::size_t(r.z - box.min.z) * ny + std::size_t(r.y - box.min.y) + 1];
  for(std::size_t i = 1; i < row_start.size(); ++i)
    row_start[i] += row_start[i - 1];

  std::vector<std::size_t> root(runs.size());
  for(std::size_t i = 0; i < runs.size(); ++i)
    root[i] = i;
  const auto find_root = [&](std::size_t i) {
    while(root[i] != i)
      i = root[i] = root[root[i]];
    return i;
  };
  std::size_t pieces = runs.size();
  for(std::size_t i = 0; i < runs.size(); ++i)
  {
    const Run& r = runs[i];
    // The rows before this one in (z, y) order that touch it.
    const int earlier[4][2] = {{r.y - 1, r.z}, {r.y - 1, r.z - 1}, {r.y, r.z - 1}, {r.y + 1, r.z - 1}};
    for(const auto& [y, z] : earlier)
    {
      if(y < box.min.y || y >= box.max.y || z < box.min.z)
        continue;
      const std::size_t row = std::size_t(z - box.min.z) * ny + std::size_t(y - box.min.y);
      for(std::size_t j = row_start[row]; j < row_start[row + 1]; ++j)
        if(runs[j].x0 <= r.x1 + 1 && r.x0 <= runs[j].x1 + 1)
        {
          const std::size_t a = find_root(i), b = find_root(j);
          if(a != b)
          {
            root[a] = b;
            --pieces;
          }
        }
    }
  }
  return pieces;
}

// The 26-connected pieces of a voxel set, searched through a dense array of bytes over its
// box grown by one voxel (no bounds checks): `visit(k, piece, on_boundary)` is called once
// for every voxel k, with the number of its piece (in the order of the pieces' first voxels
// in key order) and whether a 26-neighbour of it is not in the set. Returns the number of
// pieces. Complexity: O(V) time and V bytes for the V voxels of the grown box.
template <typename VoxelSet, typename Visit>
std::size_t search_pieces(const VoxelSet& voxels, const Visit& visit)
{
  const Grid_layout layout(voxels.bounding_box().grown(1));
  enum : std::uint8_t { ABSENT, UNSEEN, SEEN };
  std::vector<std::uint8_t> cell(layout.volume(), ABSENT);
  voxels.for_each([&](const Voxel_key& k) { cell[layout.index(k)] = UNSEEN; });
  const std::array<std::ptrdiff_t, 26> offsets = layout.neighbour_offsets();
  std::vector<std::size_t> stack;
  std::size_t pieces = 0;
  voxels.for_each([&](const Voxel_key& start) {
    const std::size_t first = layout.index(start);
    if(cell[first] != UNSEEN)
      return;
    cell[first] = SEEN;
    stack.push_back(first);
    while(!stack.empty())
    {
      const std::size_t i = stack.back();
      stack.pop_back();
      bool on_boundary = false;
      for(const std::ptrdiff_t o : offsets)
      {
        std::uint8_t& n = cell[std::size_t(std::ptrdiff_t(i) + o)];
        on_boundary |= n == ABSENT;
        if(n == UNSEEN)
        {
          n = SEEN;
          stack.push_back(std::size_t(std::ptrdiff_t(i) + o));
        }
      }
      visit(layout.key(i), pieces, on_boundary);
    }
    ++pieces;
  });
  return pieces;
}

// A voxel on the boundary of a piece of the solid (a 26-neighbour is not in the solid).
struct Piece_boundary_voxel
{
  Voxel_key key;
  std::size_t piece;
};

// The piece of every voxel of a (coarse) voxel set, read by key.
class Voxel_pieces
{
public:
  template <typename VoxelSet>
  explicit Voxel_pieces(const VoxelSet& voxels) : m_layout(voxels.bounding_box()), m_piece(m_layout.volume(), -1)
  {
    search_pieces(voxels, [&](const Voxel_key& k, std::size_t piece, bool) {
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

// A shortest link found between two pieces: its length (voxels) and its two end voxels
// (indices into the boundary list).
struct Piece_link
{
  double length;
  std::size_t from, to; // from's piece < to's piece
};

inline bool shorter_link(const Piece_link& a, const Piece_link& b)
{
  return std::tie(a.length, a.from, a.to) < std::tie(b.length, b.from, b.to);
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
