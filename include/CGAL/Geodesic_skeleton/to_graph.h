// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_TO_GRAPH_H
#define CGAL_GEODESIC_SKELETON_TO_GRAPH_H

/// \file to_graph.h
/// A one-voxel-thick voxel skeleton as a curve-skeleton graph, with the mesh vertices
/// mapped to its vertices.

#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/curve_skeleton_graph.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Converts a one-voxel-thick voxel skeleton (the output of `thin()`) into a curve-skeleton
/// graph: one graph vertex per skeleton voxel, with the medial radius there; an edge
/// between 26-adjacent voxels, except the shortcuts that would make little triangles; and
/// every vertex of `mesh` mapped to exactly one graph vertex.
///
/// <b>Points.</b> A graph vertex is at its voxel's centre, in the mesh's own coordinates,
/// unless that centre is outside the mesh. Where the shape is thinner than about two voxels
/// (a horn, an ear, a tail tip), the skeleton must run through voxels that the surface
/// crosses to stay connected, and such a centre may lie outside the mesh; the vertex then
/// moves to a point inside the mesh: among the lines along the three grid axes through the
/// 3 x 3 points at -1/3, 0 and 1/3 of the voxel's cross-section, the midpoint of the
/// longest piece that is in the voxel and inside the mesh; where these lines find none (the
/// part only clips the voxel), the inside point nearest to the centre on such lines through
/// the voxel and its 26 neighbours (so a point moves by at most 1.5 voxels along each
/// axis). Inside and outside are decided by the winding number of the surface (hole-filling
/// fans included, as in `voxelize()`), counted along grid lines; a line whose crossings do
/// not sum to zero (through a gap of an open surface) cannot decide, and a vertex that no
/// line decides, or near which no line finds inside (a part much thinner than a third of a
/// voxel), stays at the centre.
///
/// <b>Edges.</b> Three pairwise 26-adjacent voxels make a triangle of the adjacency graph
/// that is no cycle of the shape. Edges are removed, longest first (a corner diagonal before
/// an edge diagonal before a face link), each only when it fills exactly one independent
/// triangle, until no triangle is left: the graph has then no triangle, the same connected
/// components as the voxels, and exactly as many independent cycles as the voxel skeleton
/// has tunnels (its first Betti number, with the voxels as closed unit cubes).
///
/// <b>Mesh vertices.</b> A mesh vertex maps to the skeleton voxel that a breadth-first
/// wave from all skeleton voxels, through the solid of `distances` (26-connected), reaches
/// first at the vertex's voxel: a nearest skeleton voxel along a path inside the shape, so a
/// vertex of a leg maps to the leg's skeleton, not to the nearest point of the other leg.
/// A vertex whose voxel the wave does not reach (outside the solid) takes a reached
/// 26-neighbour voxel's label, else the Euclidean nearest skeleton voxel.
///
/// \tparam VoxelSet a model of `VoxelSet`. Whatever the model, its voxels are indexed in a
///         dense array over its bounding box.
/// \tparam VoxelDistanceField a model of `VoxelDistanceField` (`Voxel_distance_field`);
///         its solid is copied into a dense array of labels over its box.
/// \tparam FaceGraph a model of `FaceListGraph`: its vertices are mapped, its faces decide
///         which voxel centres are inside.
/// \tparam Graph a `boost::adjacency_list` with `vecS` vertices, such as
///         `Curve_skeleton<Point, vertex_descriptor>`, whose vertex bundle has members
///         `point` (constructible from three `double`s), `radius` (`double`), `vertices`
///         (a container of `FaceGraph` vertex descriptors with `push_back`) and `voxel`.
/// \param skeleton the voxel skeleton (its frame maps voxels to the mesh's coordinates).
/// \param distances the distance field of the solid the skeleton was thinned from
///        (`distance_transform()`); it gives the radii and the solid for the mapping.
/// \param mesh the mesh whose vertices are mapped.
/// \param graph receives the skeleton (cleared first). Vertices are in increasing
///        `(z, y, x)` voxel order.
/// \param np optional named parameters among:
///   - `vertex_point_map`: the positions of the mesh vertices (default:
///     `get(CGAL::vertex_point, mesh)`).
///   - `fill_holes` (package parameter, `bool`): count the fans that close the mesh's holes
///     as surface in the inside test, as `voxelize()` does (default: `true`).
///   - `voxelized_surface` (package parameter, `const Voxelized_surface*`): the mesh as
///     `voxelize()` rasterised it (its `voxelized_surface_output`), for the inside test
///     (default: built from `mesh`, `vertex_point_map` and `fill_holes` when a centre is
///     in doubt). It must be in the skeleton's frame.
///   - `memory_limit` (package parameter, `double`, bytes): the most memory the function
///     may allocate (default: `default_voxel_memory_limit`, 2 GiB); the need, 4 bytes per
///     voxel of the field's box and of the skeleton's box, is checked before allocating.
///
/// \pre `skeleton` is not empty, and has the frame of `distances`.
/// \throws std::invalid_argument when `skeleton` is empty, a mesh vertex has a
///      non-finite coordinate, or `voxelized_surface` is in another frame.
/// \throws std::length_error when the work arrays would need more than `memory_limit`.
///
/// \b Complexity: O(S + B + M + F) time for S skeleton voxels, B voxels in the field's box,
///    M mesh vertices and F faces (plus the grid cells that the faces cover, seen along
///    each axis, and the rare triangle clusters, each of a few voxels).
template <typename VoxelSet, typename VoxelDistanceField, typename FaceGraph, typename Graph,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void to_graph(const VoxelSet& skeleton, const VoxelDistanceField& distances,
              const FaceGraph& mesh, Graph& graph,
              const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  internal::Stage_surface<FaceGraph, decltype(vpm)> mesh_lines(
      choose_parameter(get_parameter(np, internal_np::voxelized_surface_tag), static_cast<const Voxelized_surface*>(nullptr)),
      mesh, vpm, skeleton.frame(), choose_parameter(get_parameter(np, internal_np::fill_holes_tag), true), "to_graph");
  internal::to_graph_impl(skeleton, distances, mesh, graph, vpm, internal::memory_limit(np), mesh_lines);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_TO_GRAPH_H
