// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CUT_SPURIOUS_CYCLES_H
#define CGAL_GEODESIC_SKELETON_CUT_SPURIOUS_CYCLES_H

/// \file cut_spurious_cycles.h
/// Opens the cycles of a voxel skeleton that the mesh has no handle for: the tunnels that
/// voxelization makes where two parts come within a voxel of each other.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/internal/cut_spurious_cycles/spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Opens the cycles of a voxel skeleton that the mesh has no handle for. A solid voxelized
/// conservatively (`voxelize()`'s default) joins parts that come within about a voxel of
/// each other (a hand resting on a thigh, legs that nearly touch), and `thin()`, which keeps
/// the solid's topology, turns each such bridge into a cycle of the skeleton. Such a cycle
/// crosses the gap between the parts, outside the mesh: removing the skeleton voxels on
/// either side of the gap opens it.
///
/// <b>Method.</b> The skeleton's cycles are counted on its 26-adjacency graph without
/// junction triangles (as in `to_graph()`), and compared with the number of handles of the
/// mesh: the sum over its connected components of their genus, holes capped by discs. When
/// there are more cycles than handles, each step between two adjacent voxels on cycles is
/// tested: it leaves the mesh when every walk along the grid axes between the two centres
/// (through the voxel centres between them, in each order of the axes) meets a point of
/// winding number zero, counted along grid lines (hole-filling fans count as surface, as in
/// `voxelize()`; a line whose crossings do not sum to zero cannot decide and counts as
/// inside). While there are more cycles than handles, voxels with such a step are removed
/// where that lowers the number of cycles without splitting a connected component: single
/// voxels first (those whose centre is outside the mesh, then those with the most steps
/// out), then runs of them (connected groups, shortest first). The stubs left are twigs
/// for `prune_skeleton()`.
///
/// The mesh's handles are kept as long as the skeleton has no more cycles than the mesh has
/// handles. Overlapping components that close a ring (a handle made of separate parts)
/// keep their cycle too, since the skeleton stays inside the parts there. Limits: a ring of
/// parts thinner than a voxel, which the skeleton leaves, can be opened when the
/// components' genus does not account for it; and where the skeletons of two touching
/// parts cross (legs crossed at the contact), removing the crossing would split the
/// skeleton, and the cycle stays.
///
/// \tparam VoxelSet a model of `VoxelSet`. Whatever the model, its voxels are indexed in a
///         dense array over its bounding box.
/// \tparam FaceGraph a model of `FaceListGraph`, the mesh the skeleton was computed from.
/// \param skeleton a one-voxel-thick voxel skeleton (`thin()`), in the frame of the mesh's
///        voxelization; the removed voxels leave it.
/// \param mesh the mesh.
/// \param np optional named parameters among:
///   - `vertex_point_map`: the positions of the mesh's vertices (default:
///     `get(CGAL::vertex_point, mesh)`).
///   - `fill_holes` (package parameter, `bool`): count the fans that close the mesh's holes
///     as surface, as `voxelize()` does (default: `true`).
///   - `voxelized_surface` (package parameter, `const Voxelized_surface*`): the mesh as
///     `voxelize()` rasterised it (its `voxelized_surface_output`), for the inside tests
///     (default: built from `mesh`, `vertex_point_map` and `fill_holes` when needed). It
///     must be in the skeleton's frame.
///
/// \returns the number of cycles opened.
/// \throws std::invalid_argument when a mesh vertex has a non-finite coordinate, or
///      `voxelized_surface` is in another frame.
///
/// \b Complexity: O(S log S + M + F) for S skeleton voxels, M mesh vertices and edges and
///    F faces (plus the grid cells the faces cover along each axis), and O(S) per run of
///    voxels tried; nothing beyond counting the cycles when there are no more than handles.
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
