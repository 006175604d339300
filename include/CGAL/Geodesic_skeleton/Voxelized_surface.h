// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_VOXELIZED_SURFACE_H
#define CGAL_GEODESIC_SKELETON_VOXELIZED_SURFACE_H

/// \file Voxelized_surface.h
/// The surface of a mesh in the grid of its voxelization, with the inside test that the
/// voxel stages share.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/internal/grid_line_crossings.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {
// Tells Voxelized_surface that its triangles are a mesh's faces then hole-filling fans.
struct Triangles_of_a_mesh
{};
} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Where a point lies with respect to a `Voxelized_surface`.
enum class Surface_side
{
  outside,  ///< the winding number of the surface around the point is zero
  inside,   ///< the winding number is not zero (of either sign: overlapping parts and
            ///< inverted components are inside)
  undecided ///< no grid line through the point has crossings that sum to zero (it passes
            ///< through gaps of an open surface along all three axes)
};

/// \ingroup PkgGeodesicSkeletonRef
/// The faces of a mesh (and, when its holes are filled, the fans that close them) in the
/// grid coordinates of a `Voxel_frame`, with the inside test of the voxel stages: the
/// winding number of the surface, counted along lines parallel to the grid's axes.
///
/// `voxelize()` fills one with the triangles it rasterised (named parameter
/// `voxelized_surface`), and `to_graph()`, `cut_spurious_cycles()` and
/// `move_skeleton_inside()` take it (named parameter `voxelized_surface`), so that a chain
/// of stages reads and transforms the mesh once; without it each of them builds its own
/// from the mesh. It holds a copy of the triangles: about as large as the mesh.
class Voxelized_surface
{
public:
  /// An empty surface (no triangle; every point outside).
  Voxelized_surface() = default;

  /// The faces of `mesh` (polygons split into fans), and with `fill_holes` the fans that
  /// close its border cycles as `voxelize()` closes them, in the grid coordinates of
  /// `frame`, in an order from which `cut_spurious_cycles()` names the connected component
  /// of the mesh that each belongs to (to tell where the surface overlaps itself).
  /// \tparam FaceGraph a model of `FaceListGraph`.
  /// \tparam VertexPointMap a readable vertex property map to a CGAL point type.
  /// \throws std::invalid_argument when a vertex has a non-finite coordinate or the mesh
  ///      has no face.
  /// \b Complexity: O(F + H log H) for F faces and H halfedges (the holes' walk).
  template <typename FaceGraph, typename VertexPointMap>
  Voxelized_surface(const FaceGraph& mesh, VertexPointMap vpm, const Voxel_frame& frame, bool fill_holes = true)
    : m_frame(frame), m_lines(internal::mesh_grid_lines(mesh, vpm, frame, fill_holes, "Voxelized_surface"))
  {}

  /// Takes triangles already in the grid coordinates of `frame` (a triangle with a
  /// non-finite corner meets no grid line: it is never crossed). Their components are not
  /// known: where they overlap, `cut_spurious_cycles()` cannot tell a surface that overlaps
  /// itself from separate parts, and takes them for separate parts. O(F) for F triangles.
  Voxelized_surface(const Voxel_frame& frame, std::vector<std::array<Voxel_frame::Vector, 3>> grid_triangles)
    : m_frame(frame), m_lines(std::in_place, std::move(grid_triangles))
  {}

  /// \cond SKIP_IN_MANUAL
  // A mesh's triangles in grid coordinates, as voxelize() made them (faces, then
  // hole-filling fans): the stages can name their components (internal::triangle_parts()).
  Voxelized_surface(const Voxel_frame& frame, std::vector<std::array<Voxel_frame::Vector, 3>> grid_triangles,
                    internal::Triangles_of_a_mesh)
    : m_frame(frame), m_lines(std::in_place, std::move(grid_triangles), true)
  {}
  /// \endcond

  /// The frame whose grid coordinates the triangles are in.
  const Voxel_frame& frame() const { return m_frame; }
  /// The number of triangles (faces split into triangles, then hole-filling fans).
  std::size_t number_of_triangles() const { return m_lines ? m_lines->triangles().size() : 0; }
  /// Whether there is no triangle.
  bool empty() const { return number_of_triangles() == 0; }

  /// Where each of `points` (world coordinates) lies: along the first grid axis whose line
  /// through the point has crossings that sum to zero, inside where the winding number is
  /// not zero.
  /// \b Complexity: O(F + N + C) for F triangles, N points and C pairs of a point and a
  /// triangle whose grid cells its lines meet.
  std::vector<Surface_side> sides(const std::vector<Voxel_frame::Vector>& points) const
  {
    std::vector<Surface_side> result(points.size(), Surface_side::outside);
    if(empty())
      return result;
    std::vector<internal::Vec3> in_grid(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      in_grid[i] = m_frame.to_grid(points[i]);
    const std::vector<internal::Point_side> sides = internal::sides_of_points(*m_lines, in_grid);
    for(std::size_t i = 0; i < points.size(); ++i)
      result[i] = sides[i] == internal::Point_side::inside    ? Surface_side::inside
                  : sides[i] == internal::Point_side::outside ? Surface_side::outside
                                                               : Surface_side::undecided;
    return result;
  }

  /// \cond SKIP_IN_MANUAL
  // The triangles and their grid cells, for the package's stages.
  const internal::Grid_line_crossings& grid_lines() const
  {
    if(!m_lines)
      throw std::logic_error("Voxelized_surface: empty");
    return *m_lines;
  }
  /// \endcond

private:
  Voxel_frame m_frame;
  std::optional<internal::Grid_line_crossings> m_lines;
};

namespace internal {

// The voxelized surface a stage reads: the one given as named parameter `voxelized_surface`
// (a pointer; checked to be in `frame`), else one built from `mesh` on first use.
template <typename FaceGraph, typename VertexPointMap>
class Stage_surface
{
public:
  Stage_surface(const Voxelized_surface* given, const FaceGraph& mesh, VertexPointMap vpm, const Voxel_frame& frame,
                bool fill_holes, const char* caller)
    : m_given(given), m_mesh(mesh), m_vpm(vpm), m_frame(frame), m_fill_holes(fill_holes), m_caller(caller)
  {
    if(m_given != nullptr && !(m_given->frame() == frame))
      throw std::invalid_argument(std::string(caller) +
                                  ": the voxelized surface is in another frame than the voxels");
  }
  const Grid_line_crossings& operator()()
  {
    if(m_given != nullptr)
      return m_given->grid_lines();
    if(!m_built)
      m_built.emplace(mesh_grid_lines(m_mesh, m_vpm, m_frame, m_fill_holes, m_caller));
    return *m_built;
  }

  VertexPointMap vertex_point_map() const { return m_vpm; }

  // The connected components of the mesh's vertices (vertex_components()), computed on
  // first use.
  const Vertex_components& vertex_components()
  {
    if(!m_components)
      m_components = internal::vertex_components(m_mesh, CGAL::get_initialized_vertex_index_map(m_mesh));
    return *m_components;
  }

  // The connected component of the mesh that each triangle of the surface belongs to
  // (triangle_parts()), computed on first use; null when the surface's triangles are not
  // the mesh's faces and fans as triangle_parts() orders them (a surface given as triangles
  // alone, or whose holes were closed otherwise).
  const std::vector<std::uint32_t>* triangle_parts()
  {
    if(!m_parts_tried)
    {
      m_parts_tried = true;
      const Grid_line_crossings& lines = (*this)();
      if(lines.of_a_mesh())
      {
        std::vector<std::uint32_t> parts = internal::triangle_parts(m_mesh, m_vpm, m_fill_holes, vertex_components());
        if(parts.size() == lines.triangles().size())
          m_parts = std::move(parts);
      }
    }
    return m_parts ? &*m_parts : nullptr;
  }

private:
  const Voxelized_surface* m_given;
  const FaceGraph& m_mesh;
  VertexPointMap m_vpm;
  Voxel_frame m_frame;
  bool m_fill_holes;
  const char* m_caller;
  std::optional<Grid_line_crossings> m_built;
  std::optional<Vertex_components> m_components;
  bool m_parts_tried = false;
  std::optional<std::vector<std::uint32_t>> m_parts;
};

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_VOXELIZED_SURFACE_H
