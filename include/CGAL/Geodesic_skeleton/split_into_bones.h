// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_SPLIT_INTO_BONES_H
#define CGAL_GEODESIC_SKELETON_SPLIT_INTO_BONES_H

/// \file split_into_bones.h
/// The split of a smoothed curve skeleton into the joints and bones of a control skeleton
/// (paper, section III.B.ii and Algorithm 2).

#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/internal/split_into_bones/split_with_maps.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_vertex_maps.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The `smallest_radius` that `extract_control_skeleton()` gives `split_into_bones()` on a
/// grid of `resolution` voxels of `voxel_size` along the longest extent: half a voxel of
/// the default grid, (`voxel_size` `resolution`) / (2 `default_voxel_resolution`), the
/// smallest MAT radius at the default resolution. A finer grid measures thin parts thinner,
/// and the joints of a thin part should not multiply with the resolution; at the default
/// resolution it is half a voxel, below every MAT radius.
/// \param voxel_size the edge length of a voxel of the grid (world units).
/// \param resolution the resolution of that grid (`resolution` named parameter).
/// \pre `voxel_size` >= 0 and `resolution` > 0.
///
/// \b Complexity: O(1).
inline double default_smallest_radius(double voxel_size, int resolution)
{
  return voxel_size * double(resolution) / (2. * double(default_voxel_resolution));
}

/// \ingroup PkgGeodesicSkeletonRef
/// The `joint_spacing` that `extract_control_skeleton()` gives `split_into_bones()` on a grid
/// of `resolution` voxels of `voxel_size` along the longest principal extent of the mesh:
/// `factor` times that extent (`voxel_size` `resolution`), so that a character gets as many
/// joints at any size and any resolution.
/// \param voxel_size the edge length of a voxel of the grid (world units).
/// \param resolution the resolution of that grid (`resolution` named parameter).
/// \param factor the spacing in extents (`joint_spacing_factor`, default 0.1).
/// \pre `voxel_size` >= 0, `resolution` > 0 and `factor` >= 0.
///
/// \b Complexity: O(1).
inline double default_joint_spacing(double voxel_size, int resolution,
                                    double factor = parameter_ranges::joint_spacing_factor.default_value)
{
  return factor * voxel_size * double(resolution);
}

/// \ingroup PkgGeodesicSkeletonRef
/// Splits a (smoothed) curve skeleton into the joints and bones of an animation control
/// skeleton, a rooted tree per connected component.
///
/// The end points and junctions of the curve skeleton are the initial joints; each branch
/// between them is split recursively where the chord-to-point distance accumulation
/// (`chord_to_point_distance_accumulation()`) peaks at `bend_threshold` or more, or where
/// it strays from its chord by more than `straightness_tolerance` MAT radii (each radius
/// taken as at least the radius of the rig's level of detail below), leaving only
/// bones longer than `minimum_bone_length_factor` MAT radii (each radius taken as at least
/// `smallest_radius`, and as at least the vertex's `sheet_half_width` where the vertex
/// bundle has one) and longer than `minimum_bone_length_of_piece_factor` times the largest MAT
/// radius of its connected component (the rig's level of detail; at least the largest
/// `piece_radius` of the component's vertices), clearly longer: a part
/// exactly twice that length stays whole, whatever the rounding; a straight bone longer than
/// `maximum_bone_length_factor` times the largest MAT radius of its connected component
/// (the body's thickness; a straight limb has no bend to cut at) is cut
/// into bones of about equal length, each cut at the narrowest point near its
/// equal-length position (an elbow, a knee, a wrist); each component is rooted at
/// its most central junction; when the shape has handles, the bones left off the trees (one
/// per independent cycle) are in the graph bundle's `Control_skeleton_property::cut_bones`.
/// As artists place joints, the joints of the tips move back along their bones
/// (`tip_joint_setback`; 0 keeps them at the tips) and, where asked (`joint_spacing`), long
/// bones are cut at a spacing.
/// The steps are described in the manual, section
/// \ref manual_split_into_bones.
///
/// The points and radii are read through property maps, so the skeleton of
/// `CGAL::extract_mean_curvature_flow_skeleton()` splits as well, with a `mat_radius_map`
/// that the caller gives (manual, section \ref manual_bones): every length of the split is
/// in MAT radii, so a radius is required, and a call on a skeleton without `radius` member
/// and without `mat_radius_map` does not compile (a `static_assert` names
/// `mat_radius_map`).
///
/// \tparam CurveSkeleton an undirected `boost::adjacency_list` with `vecS` vertex storage
///         (its vertex descriptors are the indices 0 to N-1), e.g. `Curve_skeleton<Point, MeshVertex>`
///         or `CGAL::Mean_curvature_flow_skeletonization<TriangleMesh>::Skeleton`, usually
///         after `smooth_skeleton()`. Its vertex bundle has a `point` member (a CGAL point)
///         unless a `vertex_point_map` is given, and a `radius` member (`double`, world
///         units) unless a `mat_radius_map` is given. When it also has the members
///         `sheet_half_width` and `piece_radius` (`double`, world units, each finite and at
///         least 0), as `Curve_skeleton_vertex` has, the split reads them: where a vertex's
///         sheet half width is larger than its radius, the lengths of the split (chords,
///         straightness, shortest and longest bone) are measured in it (a sheet's chain gets
///         the joints of a limb as wide, not as thin; the joints keep their own radius), and
///         the largest MAT radius of a connected component (R: the rig's level of detail,
///         the longest straight bone, the floor of the straightness) is at least the largest
///         piece radius of its vertices (a chain that pruning kept beside a sheet, a bar
///         beside a plate, gets the sheet's level of detail).
/// \tparam Point the point type of the output.
/// \param skeleton the curve skeleton.
/// \param control receives the control skeleton (cleared first), a forest whose vertices
///        are numbered parents first and whose edges are added in the order of their child
///        joints; empty for an empty skeleton. `Control_joint::skeleton_vertex` is the vertex descriptor (index) of
///        the joint's vertex in `skeleton`.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the point of each skeleton vertex}
///     \cgalParamType{a model of `ReadablePropertyMap` with the skeleton's vertex descriptor
///                    as key type and a CGAL point type as value type}
///     \cgalParamDefault{`get(&Bundle::point, skeleton)`, the vertex bundle's `point` member}
///   \cgalParamNEnd
///   \cgalParamNBegin{mat_radius_map}
///     \cgalParamDescription{the MAT radius at each skeleton vertex, in world units; the
///                           joints' radii and every length of the split (chords,
///                           straightness, shortest bone) come from it (package parameter)}
///     \cgalParamType{a model of `ReadablePropertyMap` with the skeleton's vertex descriptor
///                    as key type and `double` as value type}
///     \cgalParamDefault{`get(&Bundle::radius, skeleton)` when the vertex bundle has a
///                       `radius` member, as `Curve_skeleton_vertex` has; otherwise
///                       required}
///   \cgalParamNEnd
///   \cgalParamNBegin{bend_threshold}
///     \cgalParamDescription{the accumulation, in chord lengths, that makes a bend a joint,
///                           in [0, 1] (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.08: a corner turning by 30 degrees reaches it (with the
///                       accumulation's default `number_of_chords`); 20 degrees give
///                       0.054, a right angle 0.204}
///   \cgalParamNEnd
///   \cgalParamNBegin{straightness_tolerance}
///     \cgalParamDescription{how far a bone may stray from its chord, in MAT radii, in
///                           [0, 100]; the radius is taken as at least
///                           `minimum_bone_length_of_piece_factor` / `minimum_bone_length_factor`
///                           times the largest MAT radius of the bone's connected component
///                           (the radius whose shortest bone is the rig's level of detail; a
///                           quarter of it by default; no floor when
///                           `minimum_bone_length_factor` is 0) (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.5}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_bone_length_factor}
///     \cgalParamDescription{the length, in MAT radii, that every bone a split leaves is
///                           longer than, in [0, 1000] (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_bone_length_factor}
///     \cgalParamDescription{the longest straight bone, in units of the largest MAT radius
///                           of its connected component of the skeleton (R), in [0, 1000]: a
///                           longer one is cut into ceil(length / (factor * R)) bones of
///                           about equal length (at most 4 per branch, each straight part
///                           its share in proportion to its length, rounded up),
///                           each cut at the smallest MAT radius within a quarter of a bone's
///                           length of its equal-length position; 0 turns this off (package
///                           parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_bone_length_of_piece_factor}
///     \cgalParamDescription{the length that every bone a split leaves is longer than, in
///                           units of the largest MAT radius of its connected component of the skeleton (R), in
///                           [0, 1000]: the rig's level of detail. Near a tip the MAT radius is
///                           small and a finer grid resolves bends there that a coarser one
///                           smooths away; bones shorter than a fraction of the body's
///                           thickness would come and go with the resolution. 0 turns this
///                           off (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.5}
///   \cgalParamNEnd
///   \cgalParamNBegin{smallest_radius}
///     \cgalParamDescription{the smallest radius that the lengths of the split (chords,
///                           straightness, shortest and longest bone) are measured in, in
///                           world units, in [0, inf]: a smaller MAT radius counts as this one
///                           there, so that a part thinner than it gets the joints of a part
///                           this thick; the joints keep their own radius (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0 (the MAT radius as it is); `extract_control_skeleton()` passes
///                       half a voxel of the default grid}
///   \cgalParamNEnd
///   \cgalParamNBegin{chord_length_factors}
///     \cgalParamDescription{the chord lengths of the accumulation, in MAT radii, each in
///                           [0.001, 1000] (package parameter)}
///     \cgalParamType{`std::vector<double>`}
///     \cgalParamDefault{{3, 6}}
///   \cgalParamNEnd
///   \cgalParamNBegin{tip_joint_setback}
///     \cgalParamDescription{where a chain ends, as artists end it (at the wrist, the head
///                           joint, the last tail joint, not at the tip): the joint at a tip of
///                           the skeleton (a vertex of degree 1) moves back along its bone by
///                           this share of the bone's length, to the nearest vertex of the
///                           branch, in [0, 0.45]; the vertices beyond it are in no bone. A lone
///                           bone with two tips is set back from both (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.3, as `extract_control_skeleton()` uses it (0: joints at the tips)}
///   \cgalParamNEnd
///   \cgalParamNBegin{joint_spacing}
///     \cgalParamDescription{the length, in world units, that bones are cut into after the
///                           split and the set-back, in [0, inf]: a bone of length l becomes
///                           round(l / spacing) bones of about equal length (one when that is 0),
///                           cut at the vertices nearest the equal-length positions; artists
///                           put joints along a spine or a straight limb that no bend marks.
///                           0 turns this off (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0; `extract_control_skeleton()` passes `joint_spacing_factor` times
///                       the mesh's longest principal extent}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws std::invalid_argument when a parameter is out of range, a point has a non-finite
///         coordinate, or the radius map, a vertex's `sheet_half_width` or its
///         `piece_radius` is negative or not finite.
///
/// \b Complexity: O(N log N * c) for N skeleton vertices and c chords per point in
/// practice (each recursion level scans its part), plus O(J B log B) to root the J joints
/// and B bones.
template <typename CurveSkeleton, typename Point,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void split_into_bones(const CurveSkeleton& skeleton, Control_skeleton<Point>& control,
                      const NamedParameters& np = CGAL::parameters::default_values())
{
  static_assert(internal::has_radius_map<CurveSkeleton, NamedParameters>(),
                "split_into_bones: the skeleton's vertex bundle has no `radius` member (e.g. the "
                "skeleton of CGAL::Mean_curvature_flow_skeletonization): give its MAT radii with "
                "the named parameter mat_radius_map");
  const internal::Bone_splitting_settings settings = internal::bone_splitting_settings(np);
  control = Control_skeleton<Point>();
  if constexpr(internal::has_radius_map<CurveSkeleton, NamedParameters>())
    internal::split_into_bones_with_maps(skeleton, internal::skeleton_point_map(skeleton, np),
                                         internal::skeleton_radius_map(skeleton, np),
                                         internal::split_length_maps(skeleton), settings, control);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_SPLIT_INTO_BONES_H
