// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// Documentation only: this file is never compiled.

/*!
\ingroup PkgGeodesicSkeletonConcepts
\cgalConcept

The concept `VoxelDistanceField` describes the squared Euclidean distance transform of a
solid voxel set, stored densely over a box: what `distance_transform()` returns and what
`thin()`, `remove_small_pieces()` and `to_graph()` read (the radius function of the voxel
medial axis). The solid is the set of voxels of positive distance.

Distances are in squared voxels, from the centre of a voxel of the solid to the centre of
the nearest voxel outside it; a voxel outside the box or outside the solid has distance 0.
The field is read only: the stages never modify it.

\cgalHasModel `CGAL::Geodesic_skeleton::Voxel_distance_field`
*/
class VoxelDistanceField
{
public:
  /// The frame of the voxel set the field was computed from.
  const CGAL::Geodesic_skeleton::Voxel_frame& frame() const;

  /// The box over which the distances are stored; every voxel of the solid is in it.
  const CGAL::Geodesic_skeleton::Voxel_box& box() const;

  /// The squared distance of `k` (squared voxels); 0 when `k` is outside the solid or
  /// outside `box()`. O(1).
  std::uint32_t squared_distance(const CGAL::Geodesic_skeleton::Voxel_key& k) const;

  /// Whether `k` is in the solid: `squared_distance(k) != 0`. O(1).
  bool inside(const CGAL::Geodesic_skeleton::Voxel_key& k) const;

  /// The radius of the medial ball at `k` in world units,
  /// `frame().voxel_size() * (sqrt(squared_distance(k)) - 1/2)`, or 0 when `k` is not in
  /// the solid. O(1).
  double radius(const CGAL::Geodesic_skeleton::Voxel_key& k) const;

  /// The squared distances over `box()`, x fastest, then y, then z (`box().volume()`
  /// values): the stages that sweep the whole box read them in rows rather than key by key.
  const std::vector<std::uint32_t>& values() const;
};
