// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_SPARSE_VOXEL_SET_H
#define CGAL_GEODESIC_SKELETON_SPARSE_VOXEL_SET_H

/// \file Sparse_voxel_set.h
/// A model of `VoxelSet`: a hash set of voxel keys.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <cstddef>
#include <unordered_set>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// \cgalModels `VoxelSet`
///
/// A set of voxels stored as a hash set of keys: memory grows with the number of voxels
/// (about 40 bytes each), not with the size of their box, and any key can be inserted.
/// Membership, insertion and removal are expected O(1); iteration order is unspecified.
/// Best for thin sets (a curve skeleton) or sets scattered in a large region.
class Sparse_voxel_set
{
public:
  Sparse_voxel_set() = default;

  /// Empties the set and sets its frame; `box` is a hint (the set reserves room for a
  /// tenth of its volume, at most a million voxels), not a limit.
  void reset(const Voxel_frame& frame, const Voxel_box& box)
  {
    m_frame = frame;
    m_voxels.clear();
    m_box = Voxel_box{};
    const std::size_t hint = box.volume() / 10;
    m_voxels.reserve(hint < 1000000 ? hint : 1000000);
  }
  /// Empties the set, keeping its frame.
  void clear()
  {
    m_voxels.clear();
    m_box = Voxel_box{};
  }

  /// The frame, which maps voxel keys to world points.
  const Voxel_frame& frame() const { return m_frame; }
  /// A box containing every voxel of the set: the bounding box of every voxel inserted
  /// since the last `reset()` or `clear()` (removals do not shrink it).
  const Voxel_box& bounding_box() const { return m_box; }
  /// The number of voxels in the set.
  std::size_t size() const { return m_voxels.size(); }
  /// Whether the set has no voxel.
  bool empty() const { return m_voxels.empty(); }

  /// Whether `k` is in the set (any key may be asked).
  bool contains(const Voxel_key& k) const { return m_voxels.count(k) != 0; }
  /// Inserts `k`; returns whether it was absent.
  bool insert(const Voxel_key& k)
  {
    const bool inserted = m_voxels.insert(k).second;
    if(inserted)
      m_box.extend(k);
    return inserted;
  }
  /// Removes `k`; returns whether it was present.
  bool erase(const Voxel_key& k) { return m_voxels.erase(k) != 0; }

  /// Calls `f(k)` for every voxel `k` of the set, in an unspecified order. `f` must not
  /// modify the set.
  template <typename Function>
  void for_each(Function f) const
  {
    for(const Voxel_key& k : m_voxels)
      f(k);
  }

private:
  Voxel_frame m_frame;
  Voxel_box m_box;
  std::unordered_set<Voxel_key, Voxel_key_hash> m_voxels;
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_SPARSE_VOXEL_SET_H
