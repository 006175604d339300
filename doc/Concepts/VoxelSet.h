// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Documentation only: this file is never compiled.

/*!
\ingroup PkgGeodesicSkeletonConcepts
\cgalConcept

The concept `VoxelSet` describes a finite set of voxels placed in space: the input and
output of the voxel stages of the package (`voxelize()`, `distance_transform()`,
`thin()`, `reach_sheet_lobes()`, `remove_small_pieces()`, `cut_spurious_cycles()`,
`prune_skeleton()`, `classify_skeleton_points()`, `to_graph()`). Every voxel algorithm of the package is
written against this concept only, so it runs on a dense grid and on a sparse set alike
(the package's tests instantiate every stage with an archetype that has the members below
and nothing more).

<b>Dense copies.</b> The concept gives no access to a model's storage, so the stages that
sweep a whole box copy the set into a dense array over its `bounding_box()`, whatever the
model: `distance_transform()` (the field's array), `thin()` (one byte per voxel of the box
grown by two), `cut_spurious_cycles()` and `to_graph()` (an index per voxel of the box);
`voxelize()` computes the solid in dense arrays over the grid's box and inserts it into
the set voxel by voxel. `reach_sheet_lobes()` reads the skeleton through `for_each()`, `contains()` and
`size()`, keeps labels in dense arrays over the distance field's box, and inserts the
voxels of its paths. A sparse model therefore saves memory between the stages, not in
them. `remove_small_pieces()`, `prune_skeleton()` and `classify_skeleton_points()` read
the set through `for_each()` and `contains()` only.

A voxel is a `Voxel_key` (integer coordinates `x`, `y`, `z`); its 26-neighbourhood is
given by `neighbourhood_26()` (header `Voxel_key.h`), independent of the model. The
set carries a `Voxel_frame` (origin, orthonormal axes, voxel size) that maps voxel keys to
points of the mesh's own coordinates and back.

Algorithms never modify a set while iterating over it; they collect the keys first.

\cgalHasModel `CGAL::Geodesic_skeleton::Dense_voxel_grid` (one byte per voxel of a box)
\cgalHasModel `CGAL::Geodesic_skeleton::Sparse_voxel_set` (a hash set of keys)
*/
class VoxelSet
{
public:
  /// \name Creation and placement
  /// @{

  /// Default constructible: an empty set with the identity frame.
  VoxelSet();

  /// Empties the set and gives it `frame`. After the call the set accepts every key of
  /// `box`; a model may accept more (a sparse set accepts any key) or use `box` only as a
  /// size hint. May throw `std::bad_alloc`.
  void reset(const CGAL::Geodesic_skeleton::Voxel_frame& frame,
             const CGAL::Geodesic_skeleton::Voxel_box& box);

  /// Empties the set, keeping its frame.
  void clear();

  /// The frame: `frame().centre(k)` is the centre of voxel `k` in world coordinates.
  const CGAL::Geodesic_skeleton::Voxel_frame& frame() const;

  /// A box that contains every voxel of the set (not necessarily the smallest one).
  CGAL::Geodesic_skeleton::Voxel_box bounding_box() const;

  /// @}

  /// \name Membership, insertion, removal (expected O(1) each)
  /// @{

  /// The number of voxels in the set.
  std::size_t size() const;

  /// Whether `k` is in the set. Any key may be asked, inside the box or not.
  bool contains(const CGAL::Geodesic_skeleton::Voxel_key& k) const;

  /// Inserts `k` and returns whether it was absent. May throw `std::out_of_range` for a
  /// key outside the box given to `reset()`.
  bool insert(const CGAL::Geodesic_skeleton::Voxel_key& k);

  /// Removes `k` and returns whether it was present.
  bool erase(const CGAL::Geodesic_skeleton::Voxel_key& k);

  /// @}

  /// \name Iteration
  /// @{

  /// Calls `f(k)` once for every voxel `k` of the set, in a model-defined order; `f` must
  /// not modify the set. O(size()) for a sparse model, O(bounding_box().volume()) for a
  /// dense one.
  template <typename Function>
  void for_each(Function f) const;

  /// @}
};
