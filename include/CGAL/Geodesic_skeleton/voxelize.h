// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_VOXELIZE_H
#define CGAL_GEODESIC_SKELETON_VOXELIZE_H

/// \file voxelize.h
/// The solid interior of a mesh as a set of voxels, in a grid aligned with the mesh's
/// principal axes.

#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/solid_voxels.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <stdexcept>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Fills `voxels` with the solid interior of `mesh`: the voxels of a grid aligned with the
/// principal axes of the mesh that are not reachable from outside the mesh (default), or,
/// with `keep_surface_voxels(false)`, only those whose centre is inside the mesh plus the
/// voxels needed to keep the parts thinner than a voxel.
///
/// The grid has voxels of 1 / `resolution` of the longest principal extent of the mesh (an
/// odd number of them along each axis, the mesh centred), so a
/// rotated or translated mesh gives the same voxel keys and `voxels.frame()` maps them to
/// the moved mesh. Every voxel that a face touches is marked and the outside is
/// flood-filled from the border of the grid; the rest is the solid, which contains the
/// whole mesh and sticks out of it by up to a voxel. Each hole of an open mesh is closed
/// by a fan for the rasterisation, but the rim of a sheet (a cape or a wing made as one
/// layer of faces: a border cycle whose fan has at least 3/4 of the area of its connected
/// component), which stays open, its sheet the layer of voxels its faces touch, unless
/// every component has such a rim. The method (the principal frame, the rasterisation, the
/// peeling of `keep_surface_voxels(false)` with its guarantees and limits, open meshes) is
/// described in the manual, section \ref manual_voxelize.
///
/// \tparam FaceGraph a model of `FaceListGraph` (`Surface_mesh`, `Polyhedron_3`, ...); its
///         faces may be polygons (they are split into fans of triangles), it may be open,
///         non-manifold, self-intersecting, or have several components.
/// \tparam VoxelSet a model of `VoxelSet` (`Dense_voxel_grid`, `Sparse_voxel_set`). Whatever
///         the model, the solid is computed in dense arrays over the grid's box, then
///         inserted into `voxels` voxel by voxel.
/// \param mesh the mesh.
/// \param voxels receives the solid (reset first); its frame is the grid's frame and its
///        box the tight box of the solid.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices of `mesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{resolution}
///     \cgalParamDescription{the longest principal extent of the mesh in voxels (the
///                           voxel's edge is that extent / `resolution`; the grid has an odd
///                           number of voxels, so one more along it when `resolution` is
///                           even), in [4, 8192] (package parameter)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{`default_voxel_resolution`, 64}
///   \cgalParamNEnd
///   \cgalParamNBegin{fill_holes}
///     \cgalParamDescription{whether the border cycles of the mesh (but the rims of
///                           sheets, as above) are closed by fans before rasterising
///                           (package parameter)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{keep_surface_voxels}
///     \cgalParamDescription{whether every voxel that the surface touches is kept, without
///                           the peeling (package parameter)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///     \cgalParamExtra{Kept, the solid contains the mesh and may have tunnels where parts
///                     come within a voxel of each other.}
///   \cgalParamNEnd
///   \cgalParamNBegin{memory_limit}
///     \cgalParamDescription{the most memory the function may allocate, in bytes (package
///                           parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_voxel_memory_limit`, 2 GiB}
///     \cgalParamExtra{The need is estimated before allocating: 11 bytes per voxel of the
///                     grid's box (6 with `keep_surface_voxels`).}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxelized_surface}
///     \cgalParamDescription{receives the triangles rasterised (faces, then hole-filling
///                           fans) in the grid's coordinates, for the inside tests of
///                           `to_graph()`, `cut_spurious_cycles()` and
///                           `move_skeleton_inside()`, which read it through the same
///                           name and then neither read nor transform the mesh again
///                           (package parameter)}
///     \cgalParamType{`Voxelized_surface*`}
///     \cgalParamDefault{none; a null pointer is the same}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of voxels of the solid.
/// \pre the mesh has at least one face, every coordinate is finite, it encloses some
///      volume at this resolution.
/// \throws std::invalid_argument for an empty mesh (no face), a non-finite coordinate, a
///      mesh of zero area, a resolution out of range, or a mesh that encloses no voxel at
///      all (an open sheet, or a shape thinner than a voxel: raise the resolution or close
///      the mesh; then the exception is a `No_enclosed_volume`, derived from
///      `std::invalid_argument`). A closed shape whose surface touches all its voxels (a plate under
///      about two voxels thick) is not such a mesh when it encloses the centres of some of
///      them, counted by winding numbers along grid lines in the three directions, and the
///      outside flood reached no centre that it encloses (as it does through the openings
///      of an open tube): its solid is the voxels it touches.
/// \throws std::length_error when the grid would need more memory than `memory_limit`
///      (the message names the bytes needed).
///
/// \b Complexity: O(F + A + V) time for F faces of total area A (in squared voxels) and V
///    voxels in the grid's box; O(V) extra memory.
template <typename FaceGraph, typename VoxelSet,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t voxelize(const FaceGraph& mesh, VoxelSet& voxels,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const internal::Voxelize_settings settings = internal::voxelize_settings(np, "voxelize");
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  return internal::voxelize_with(mesh, vpm, voxels, settings);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_VOXELIZE_H
