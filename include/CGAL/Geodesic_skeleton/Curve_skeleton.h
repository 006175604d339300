// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CURVE_SKELETON_H
#define CGAL_GEODESIC_SKELETON_CURVE_SKELETON_H

/// \file Curve_skeleton.h
/// The curve skeleton graph: a Boost.Graph adjacency list whose vertices hold a point, the
/// medial-axis radius there, the mesh vertices mapped to it and the widths of the sheet and
/// the piece it runs through.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <boost/graph/adjacency_list.hpp>

#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// A vertex of a curve skeleton. `point` and `vertices` have the names of
/// `CGAL::Mean_curvature_flow_skeletonization::Skeleton`'s vertex, so code written for one
/// reads the other.
///
/// \tparam Point the point type of the mesh (e.g. `Kernel::Point_3`).
/// \tparam MeshVertex the vertex descriptor of the mesh.
template <typename Point, typename MeshVertex>
struct Curve_skeleton_vertex
{
  /// The point type.
  using Point_type = Point;
  /// The vertex descriptor of the mesh.
  using Mesh_vertex = MeshVertex;

  /// The position, in the mesh's own coordinates.
  Point point;
  /// The radius of the medial ball there (world units): the distance to the surface.
  double radius = 0;
  /// The mesh vertices mapped to this skeleton vertex (every mesh vertex is in exactly one
  /// skeleton vertex's list).
  std::vector<MeshVertex> vertices;
  /// The voxel it comes from (in the frame of the voxel set), when it comes from one.
  Voxel_key voxel;
  /// The half width of the thin sheet (a wing, a fin, a cape) it runs through, in world
  /// units, 0 where it runs through none: `split_into_bones()` measures its lengths in the
  /// larger of `radius` and this (`to_graph()` of a `Voxel_skeleton` sets it).
  double sheet_half_width = 0;
  /// A radius of its connected piece measured otherwise, in world units: `split_into_bones()`
  /// takes the largest radius of the piece (its level of detail) as at least the largest of
  /// these over the piece (`to_graph()` of a `Voxel_skeleton` sets the half width of the
  /// piece's widest sheet before pruning, `Voxel_skeleton::piece_sheet_radii`).
  double piece_radius = 0;
};

/// \ingroup PkgGeodesicSkeletonRef
/// The curve skeleton of a mesh: an undirected `boost::adjacency_list` (vertices and edges
/// in vectors) of `Curve_skeleton_vertex`. Walk it with Boost.Graph, or split it into
/// polylines with `CGAL::split_graph_into_polylines()`.
template <typename Point, typename MeshVertex>
using Curve_skeleton = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                             Curve_skeleton_vertex<Point, MeshVertex>>;

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_CURVE_SKELETON_H
