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
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/skeleton_vertex_maps.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/curve_skeleton_graph.h>
#include <CGAL/Geodesic_skeleton/internal/to_graph/skeleton_adjacency.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <cstddef>
#include <stdexcept>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Converts a one-voxel-thick voxel skeleton (the output of `thin()`) into a curve-skeleton
/// graph: one graph vertex per skeleton voxel, with the medial radius there; an edge
/// between 26-adjacent voxels, except the shortcuts that would make little triangles; and
/// every vertex of `mesh` mapped to exactly one graph vertex.
///
/// A graph vertex is at its voxel's centre, in the mesh's own coordinates, unless that
/// centre is outside the mesh, where it moves inside (by at most 1.5 voxels along each
/// axis). The graph has no triangle, the same connected components as the voxels, and as
/// many independent cycles as the voxel skeleton has tunnels. A mesh vertex maps to the
/// skeleton voxel nearest along a path inside the solid. The method (the points, the
/// edges, the mapping of the mesh vertices) is described in the manual, section
/// \ref manual_to_graph.
///
/// \tparam VoxelSet a model of `VoxelSet`. Whatever the model, its voxels are indexed in a
///         dense array over its bounding box.
/// \tparam VoxelDistanceField a model of `VoxelDistanceField` (`Voxel_distance_field`);
///         its solid is copied into a dense array of labels over its box.
/// \tparam FaceGraph a model of `FaceListGraph`: its vertices are mapped, its faces decide
///         which voxel centres are inside.
/// \tparam Graph a `boost::adjacency_list` with `vecS` vertices, such as
///         `Curve_skeleton<Point, vertex_descriptor>` or
///         `CGAL::Mean_curvature_flow_skeletonization<FaceGraph>::Skeleton`, whose vertex
///         bundle has a `point` member (a point type constructible from three `double`s).
///         Each vertex's point, mesh vertices (a container of the vertex descriptors of
///         `FaceGraph` constructible from an iterator range) and voxel go to the bundle's
///         members `point`, `vertices` and `voxel`, its radius to the member `radius` or to
///         the `mat_radius_map` below; a bundle without such a member (and no map for the
///         radius) does not receive that quantity.
/// \param skeleton the voxel skeleton (its frame maps voxels to the mesh's coordinates).
/// \param distances the distance field of the solid the skeleton was thinned from
///        (`distance_transform()`); it gives the radii and the solid for the mapping.
/// \param mesh the mesh whose vertices are mapped.
/// \param graph receives the skeleton (cleared first). Vertices are in increasing
///        `(z, y, x)` voxel order.
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
///     \cgalParamDescription{whether the fans that close the mesh's holes count as surface
///                           in the inside test, as `voxelize()` does (package parameter)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxelized_surface}
///     \cgalParamDescription{the mesh as `voxelize()` rasterised it (its
///                           `voxelized_surface`), for the inside test (package
///                           parameter)}
///     \cgalParamType{`const Voxelized_surface*`}
///     \cgalParamDefault{built from `mesh`, `vertex_point_map` and `fill_holes` when a
///                       centre is in doubt}
///     \cgalParamExtra{It must be in the skeleton's frame.}
///   \cgalParamNEnd
///   \cgalParamNBegin{mat_radius_map}
///     \cgalParamDescription{receives the medial radius at each vertex of `graph`, in world
///                           units (package parameter)}
///     \cgalParamType{a model of `WritablePropertyMap` with the vertex descriptor of `graph`
///                    as key type and `double` as value type}
///     \cgalParamDefault{the vertex bundle's `radius` member; without one, not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{memory_limit}
///     \cgalParamDescription{the most memory the function may allocate, in bytes (package
///                           parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`default_voxel_memory_limit`, 2 GiB}
///     \cgalParamExtra{The need, 4 bytes per voxel of the field's box and of the
///                     skeleton's box, is checked before allocating.}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre `skeleton` is not empty, and has the frame of `distances`.
/// \throws std::invalid_argument when `skeleton` is empty, a mesh vertex has a
///      non-finite coordinate, or `voxelized_surface` is in another frame.
/// \throws std::length_error when the work arrays would need more than `memory_limit`.
///
/// \b Complexity: O(S + B + M + F) time for S skeleton voxels, B voxels in the field's box,
///    M mesh vertices and F faces (plus the grid cells that the faces cover, seen along
///    each axis), plus O(T log T) for the T triangles of the 26-adjacency graph (a few at
///    each junction of a thinned skeleton; a patch of sheet or an unthinned set has many).
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
  internal::to_graph_impl(skeleton, distances, mesh, graph, vpm, internal::curve_skeleton_output_maps(graph, np),
                          internal::memory_limit(np), mesh_lines);
}

namespace internal {

// The rounds in which a level that is not a sheet can burn: a shell around a limb or a body
// burns in one or two (a sheet radius is 0, 1 or 2 there), so only the rounds beyond these
// measure a sheet's width.
constexpr double shell_rounds = 2;

// The half width (world units) of a sheet of sheet radius `rounds` on a grid of voxels
// `voxel_size` long: (rounds - shell_rounds) voxels, at least 0.
inline double sheet_half_width(const Sheet_radii& radii, const Voxel_key& k, double voxel_size)
{
  return (std::max)(0.0, radius_in(radii, k) - shell_rounds) * voxel_size;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// The curve skeleton of a `Voxel_skeleton`, as `to_graph(skeleton.voxels, ...)` makes it,
/// whose vertices also carry the skeleton's radii in world units: a vertex's
/// `Curve_skeleton_vertex::sheet_half_width` is the half width of the thin sheet it runs
/// through (its voxel's sheet radius r gives r - 2 voxels, at least 0: any level, a limb's
/// shell too, burns in up to two rounds, which say nothing of a sheet), and its
/// `Curve_skeleton_vertex::piece_radius` that of the widest sheet of its piece before
/// pruning (`Voxel_skeleton::piece_sheet_radii`). Each vertex reads the radii of
/// `skeleton.radius_voxel()` of its voxel, in voxels `skeleton.radius_voxel_size` long.
/// `split_into_bones()` reads both.
///
/// \param skeleton the voxel skeleton, e.g. pruned and routed.
/// \param distances,mesh,np as for the other overload.
/// \param curve receives the curve skeleton (cleared first).
///
/// \b Complexity: that of the other overload, plus O(N) expected hash lookups for its N
///    vertices.
template <typename VoxelDistanceField, typename FaceGraph, typename Point, typename MeshVertex,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void to_graph(const Voxel_skeleton& skeleton, const VoxelDistanceField& distances, const FaceGraph& mesh,
              Curve_skeleton<Point, MeshVertex>& curve, const NamedParameters& np = CGAL::parameters::default_values())
{
  to_graph(skeleton.voxels, distances, mesh, curve, np);
  for(std::size_t v = 0; v < num_vertices(curve); ++v)
  {
    const Voxel_key k = skeleton.radius_voxel(curve[v].voxel);
    curve[v].sheet_half_width = internal::sheet_half_width(skeleton.sheet_radii, k, skeleton.radius_voxel_size);
    curve[v].piece_radius = internal::sheet_half_width(skeleton.piece_sheet_radii, k, skeleton.radius_voxel_size);
  }
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_TO_GRAPH_H
