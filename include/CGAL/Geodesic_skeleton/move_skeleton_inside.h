// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_MOVE_SKELETON_INSIDE_H
#define CGAL_GEODESIC_SKELETON_MOVE_SKELETON_INSIDE_H

/// \file move_skeleton_inside.h
/// Moves the points of a curve skeleton that lie outside a closed mesh just inside it.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/internal/move_skeleton_inside/closed_mesh_interior.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// A frame for move_skeleton_inside() without a voxelized surface: the world axes, from the
// low corner of the mesh's box, with default_voxel_resolution voxels along its longest side.
template <typename FaceGraph, typename VertexPointMap>
Voxel_frame world_aligned_frame(const FaceGraph& mesh, VertexPointMap vpm)
{
  Voxel_frame::Vector lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity()};
  Voxel_frame::Vector hi{-lo[0], -lo[1], -lo[2]};
  for(auto v : vertices(mesh))
  {
    const auto& p = get(vpm, v);
    const Voxel_frame::Vector q{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      throw std::invalid_argument("move_skeleton_inside: a vertex has a non-finite coordinate (NaN or infinite)");
    for(int c = 0; c < 3; ++c)
    {
      lo[c] = (std::min)(lo[c], q[c]);
      hi[c] = (std::max)(hi[c], q[c]);
    }
  }
  const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  if(!(extent > 0) || !std::isfinite(extent))
    throw std::invalid_argument("move_skeleton_inside: the mesh has no extent");
  return Voxel_frame(lo, {Voxel_frame::Vector{1., 0., 0.}, Voxel_frame::Vector{0., 1., 0.}, Voxel_frame::Vector{0., 0., 1.}},
                     extent / default_voxel_resolution);
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Moves every point of a curve skeleton that lies outside a closed triangle mesh to the
/// nearest point of the mesh's surface and a quarter voxel further in (along the direction
/// from the point to the surface; the step is halved while it would land outside, on the
/// other side of a thin part). `extract_control_skeleton()` runs it between
/// `smooth_skeleton()` and `split_into_bones()`: `to_graph()` puts the points inside, but
/// smoothing averages them along the bends of the skeleton, which in a limb a few voxels
/// thin can take one out. Since the joints and bones of `split_into_bones()` are points of
/// the curve skeleton, they are then inside too.
///
/// Inside is where the winding number of the surface is not zero, counted along grid lines
/// (`Voxelized_surface::sides()`, the inside test of the voxel stages): where two closed
/// parts overlap is inside. A point that no grid line decides stays where it is. A mesh
/// that is not a closed triangle mesh has no inside to test: nothing moves.
///
/// \tparam TriangleMesh a model of `FaceListGraph`.
/// \tparam CurveSkeleton a `boost::adjacency_list` with `vecS` vertex storage whose vertex
///         bundle has a `point` (a CGAL point type, constructible from three `double`s),
///         e.g. `Curve_skeleton<Point, MeshVertex>`.
/// \param mesh the mesh.
/// \param skeleton the curve skeleton, in the mesh's coordinates; its points outside move.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices of `mesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxelized_surface}
///     \cgalParamDescription{the mesh as `voxelize()` rasterised it (its
///                           `voxelized_surface`); the quarter voxel is one of its
///                           frame (package parameter)}
///     \cgalParamType{`const Voxelized_surface*`}
///     \cgalParamDefault{the mesh's faces in a grid along the world axes with
///                       `default_voxel_resolution` voxels along the longest side of the
///                       mesh's bounding box}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the skeleton vertices moved, in increasing order.
/// \throws std::invalid_argument without `voxelized_surface`, when a mesh vertex has a
///      non-finite coordinate or the mesh has no extent (all its vertices at one point).
///
/// \b Complexity: O(F + N + C) for F faces, N skeleton points and C pairs of a point and a
///    face whose grid cells the point's grid line meets; plus O(F) per point moved (most
///    faces skipped after a few comparisons) and O(F) per halving of the step.
template <typename TriangleMesh, typename CurveSkeleton,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::size_t> move_skeleton_inside(const TriangleMesh& mesh, CurveSkeleton& skeleton,
                                              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  if(num_vertices(skeleton) == 0 || !CGAL::is_closed(mesh) || !CGAL::is_triangle_mesh(mesh) || num_faces(mesh) == 0)
    return {};
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const Voxelized_surface* given =
      choose_parameter(get_parameter(np, internal_np::voxelized_surface_tag), static_cast<const Voxelized_surface*>(nullptr));
  if(given != nullptr)
    return internal::move_curve_points_inside(given->frame(), given->grid_lines(), skeleton,
                                              internal::depth_inside_in_voxels);
  const Voxelized_surface own(mesh, vpm, internal::world_aligned_frame(mesh, vpm), false);
  return internal::move_curve_points_inside(own.frame(), own.grid_lines(), skeleton, internal::depth_inside_in_voxels);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_MOVE_SKELETON_INSIDE_H
