// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_DENSE_VOXEL_GRID_H
#define CGAL_GEODESIC_SKELETON_DENSE_VOXEL_GRID_H

/// \file Dense_voxel_grid.h
/// A model of `VoxelSet`: one byte per voxel of a fixed box.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/byte_runs.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// \cgalModels `VoxelSet`
///
/// A set of voxels stored as one byte per voxel of a box fixed by `reset()` (x fastest,
/// then y, then z). Membership, insertion and removal are O(1) array accesses; iteration
/// visits the whole box, in increasing `(z, y, x)` order.
/// Memory: one byte per voxel of the box, whatever the number of voxels in the set. Best
/// for solids (`voxelize()`'s output); prefer `Sparse_voxel_set` for a thin skeleton in a
/// big box.
class Dense_voxel_grid
{
public:
  Dense_voxel_grid() = default;

  /// Empties the set and sets its frame and box; only keys inside `box` can be inserted.
  /// \throws std::bad_alloc when the box does not fit in memory.
  void reset(const Voxel_frame& frame, const Voxel_box& box)
  {
    m_frame = frame;
    m_box = box.empty() ? Voxel_box{} : box;
    const auto e = m_box.extent();
    m_stride_y = e[0];
    m_stride_z = e[0] * e[1];
    m_cells.assign(m_box.volume(), 0);
    m_size = 0;
  }
  /// Empties the set, keeping its frame and box.
  void clear()
  {
    std::fill(m_cells.begin(), m_cells.end(), std::uint8_t(0));
    m_size = 0;
  }

  /// The frame, which maps voxel keys to world points.
  const Voxel_frame& frame() const { return m_frame; }
  /// The box given to `reset()`, which contains every voxel of the set.
  const Voxel_box& bounding_box() const { return m_box; }
  /// The number of voxels in the set.
  std::size_t size() const { return m_size; }
  /// Whether the set has no voxel.
  bool empty() const { return m_size == 0; }

  /// Whether `k` is in the set (any key may be asked).
  bool contains(const Voxel_key& k) const { return m_box.contains(k) && m_cells[index(k)] != 0; }

  /// Inserts `k`; returns whether it was absent.
  /// \throws std::out_of_range when `k` is outside the box given to `reset()`.
  bool insert(const Voxel_key& k)
  {
    if(!m_box.contains(k))
    {
      std::ostringstream msg;
      msg << "Dense_voxel_grid::insert: voxel " << k << " is outside the grid's box "
          << m_box.min << " - " << m_box.max << " (call reset() with a larger box)";
      throw std::out_of_range(msg.str());
    }
    std::uint8_t& cell = m_cells[index(k)];
    if(cell != 0)
      return false;
    cell = 1;
    ++m_size;
    return true;
  }
  /// Removes `k`; returns whether it was present.
  bool erase(const Voxel_key& k)
  {
    if(!m_box.contains(k))
      return false;
    std::uint8_t& cell = m_cells[index(k)];
    if(cell == 0)
      return false;
    cell = 0;
    --m_size;
    return true;
  }

  /// Calls `f(k)` for every voxel `k` of the set, in increasing `(z, y, x)` order. `f`
  /// must not modify the set.
  template <typename Function>
  void for_each(Function f) const
  {
    if(m_size == 0)
      return;
    const std::size_t nx = m_stride_y;
    const std::uint8_t* row = m_cells.data();
    for(int z = m_box.min.z; z < m_box.max.z; ++z)
      for(int y = m_box.min.y; y < m_box.max.y; ++y, row += nx)
        for(std::size_t x = internal::first_nonzero(row, 0, nx); x < nx; x = internal::first_nonzero(row, x + 1, nx))
          f(Voxel_key{m_box.min.x + int(x), y, z});
  }

private:
  std::size_t index(const Voxel_key& k) const
  {
    return std::size_t(k.x - m_box.min.x) + std::size_t(k.y - m_box.min.y) * m_stride_y +
           std::size_t(k.z - m_box.min.z) * m_stride_z;
  }

  Voxel_frame m_frame;
  Voxel_box m_box;
  std::size_t m_stride_y = 0, m_stride_z = 0;
  std::vector<std::uint8_t> m_cells;
  std::size_t m_size = 0;
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_DENSE_VOXEL_GRID_H
