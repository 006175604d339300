// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CUT_SPURIOUS_CYCLES_H
#define CGAL_GEODESIC_SKELETON_CUT_SPURIOUS_CYCLES_H

/// \file cut_spurious_cycles.h
/// Opens the cycles of a voxel skeleton that the mesh has no handle for: the tunnels that
/// voxelization makes where two parts come within a voxel of each other.

#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/internal/cut_spurious_cycles/touching_curves.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Opens the cycles of a voxel skeleton that the mesh has no handle for. A solid voxelized
/// conservatively (`voxelize()`'s default) joins parts that come within about a voxel of
/// each other (a hand resting on a thigh, legs that nearly touch), and `thin()`, which keeps
/// the solid's topology, turns each such bridge into a cycle of the skeleton. Such a cycle
/// crosses the gap between the parts, outside the mesh, or through a place where one
/// connected component of the mesh overlaps itself (limbs that interpenetrate; separate
/// components that overlap are one solid). While the skeleton has more cycles
/// than the mesh has handles: first, where the curves of two parts touch across the gap, a
/// voxel of one curve is moved to a free neighbour inside the mesh that still links its
/// own curve and no longer touches the other, so that neither curve is cut; then skeleton
/// voxels with a step that leaves the mesh are removed, those farthest along the mesh's
/// surface from the middle of the model first (the tip of a tail that rests on a leg, not
/// its root). Either is kept where it opens a
/// cycle without splitting a connected component, the cycles counted on the graph of the
/// skeleton as changed (as `to_graph()` would make it). The method, what it keeps and its
/// limits are described in the manual, section \ref manual_cut_spurious_cycles.
///
/// \tparam VoxelSet a model of `VoxelSet`. Whatever the model, its voxels are indexed in a
///         dense array over its bounding box.
/// \tparam FaceGraph a model of `FaceListGraph`, the mesh the skeleton was computed from.
/// \param skeleton a one-voxel-thick voxel skeleton (`thin()`), in the frame of the mesh's
///        voxelization; the removed voxels leave it, and a moved voxel leaves it for a
///        26-neighbour inside its bounding box (`bounding_box()`).
/// \param mesh the mesh. Its connected components (by shared vertices) tell a surface that
///        overlaps itself from separate parts that overlap; its edges measure how far along
///        the surface the voxels that a removal chooses among lie. They are named for the
///        triangles of a `voxelized_surface` that `voxelize()` or the mesh constructor of
///        `Voxelized_surface` made from this mesh, with the same `fill_holes`; the overlaps
///        of one built from triangles alone are taken for separate parts'.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices of `mesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fill_holes}
///     \cgalParamDescription{whether the fans that close the mesh's holes count as surface,
///                           as `voxelize()` does (package parameter)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxelized_surface}
///     \cgalParamDescription{the mesh as `voxelize()` rasterised it (its
///                           `voxelized_surface`), for the inside tests (package
///                           parameter)}
///     \cgalParamType{`const Voxelized_surface*`}
///     \cgalParamDefault{built from `mesh`, `vertex_point_map` and `fill_holes` when
///                       needed}
///     \cgalParamExtra{It must be in the skeleton's frame.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of cycles opened.
/// \throws std::invalid_argument when a mesh vertex has a non-finite coordinate, or
///      `voxelized_surface` is in another frame.
///
/// \b Complexity: O(S log S + M + F) for S skeleton voxels, M mesh vertices and halfedges and
///    F faces (plus the grid cells the faces cover along each axis), and O(S) per move or
///    run of voxels tried (the graph of the skeleton as changed is built anew); the moves
///    tried are at most 26 per voxel of a cycle with three neighbours or more, and only those
///    that pass the local tests (O(1) each) are counted on the graph; the removals are tried
///    per pass, a pass repeated only while it opens cycles; nothing beyond counting the
///    cycles when there are no more than handles. When a pass removes voxels, once per call:
///    O(E + M Q) for E edges and Q single voxels tried (their nearest vertices), and shortest
///    paths along the edges in buckets as wide as the mean edge, about O(M + E) on a mesh
///    whose edges are of like lengths.
template <typename VoxelSet, typename FaceGraph,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t cut_spurious_cycles(VoxelSet& skeleton, const FaceGraph& mesh,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  if(skeleton.size() == 0 || num_faces(mesh) == 0)
    return 0;
  internal::Stage_surface<FaceGraph, decltype(vpm)> mesh_lines(
      choose_parameter(get_parameter(np, internal_np::voxelized_surface_tag), static_cast<const Voxelized_surface*>(nullptr)),
      mesh, vpm, skeleton.frame(), choose_parameter(get_parameter(np, internal_np::fill_holes_tag), true),
      "cut_spurious_cycles");
  return internal::cut_spurious_cycles_impl(skeleton, mesh, mesh_lines);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_CUT_SPURIOUS_CYCLES_H
