// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_VOXELIZE_H
#define CGAL_GEODESIC_SKELETON_VOXELIZE_H

/// \file voxelize.h
/// The solid interior of a mesh as a set of voxels, in a grid aligned with the mesh's
/// principal axes.

#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/byte_runs.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/mesh_triangles.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/peel_surface_voxels.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/principal_frame.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/solid_voxels.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/triangle_box_overlap.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Fills `voxels` with the solid interior of `mesh`: the voxels of a grid aligned with the
/// principal axes of the mesh that are not reachable from outside the mesh (default), or,
/// with `keep_surface_voxels(false)`, only those whose centre is inside the mesh plus the
/// voxels needed to keep the parts thinner than a voxel.
///
/// <b>Method.</b> The principal axes are those of the mesh's surface (area-weighted, so
/// they do not depend on the tessellation), ordered by decreasing variance, each of the
/// first two pointing to the side of positive third moment, the third their cross product;
/// the grid has `resolution` voxels along the longest extent of the mesh in that frame, the
/// mesh centred in it. Hence a rotated or translated mesh gives the same voxel keys, and
/// `voxels.frame()` maps them to the moved mesh (up to rounding; a mesh whose principal
/// variances are equal or whose third moments vanish, such as a sphere or a cube, has no
/// preferred axes, and the grid's orientation is then arbitrary). Every voxel that a face
/// touches is marked (conservative rasterisation, a separating-axis triangle-cube test),
/// and the outside is flood-filled from the border of the grid through the unmarked voxels
/// with 6-connectivity (which no closed surface lets through). The voxels the flood does
/// not reach (the enclosed voxels and the marked surface voxels) make the solid by default;
/// it contains the whole mesh and sticks out of it by up to a voxel, so parts closer than
/// about a voxel merge (spurious tunnels, which `cut_spurious_cycles()` opens again in the
/// thinned skeleton). With `keep_surface_voxels(false)` they are peeled:
/// - <i>Inside test.</i> The winding number of the surface around each voxel centre is
///   counted along the grid lines through the centres (signed crossings of the faces and
///   hole-filling fans before the centre, a line through a shared edge counting it once).
///   A line whose crossings do not sum to zero (it passes through a gap, or meets a flipped
///   face) casts no vote; lines along x vote first, and lines along y and z as well when
///   some x line abstains. A centre is outside when the "zero" votes win; a tie, or no
///   vote, keeps the voxel. A non-zero winding number of either sign is inside, so
///   overlapping parts, self-intersections, internal parts and inverted components stay
///   solid. Voxels met only by hole-filling fans stay.
/// - <i>Only from outside.</i> Outside-centre voxels that are not 26-connected to the
///   flooded outside through outside-centre voxels stay (pockets, cavities).
/// - <i>Thin parts.</i> Outside-centre voxels three 26-steps or more from the inside-centre
///   voxels stay (parts thinner than a voxel, whose centres are all outside: a tail, an
///   ear's rim).
/// - <i>No new tunnel.</i> The other outside-centre voxels leave one at a time (outer ring
///   first), each only if the background around it stays in one piece (T6 = 1 of digital
///   topology): a voxel that fills a hole of a sheet thinner than two voxels stays. Then the
///   inside-centre surface voxels that are cut points (their removal splits the solid
///   locally and joins no background: two parts that touch diagonally) leave too.
/// - <i>No lost connection.</i> The removed voxels that the solid needs to stay connected
///   come back: a breadth-first search from every component of the kept voxels through the
///   removed ones, and Kruskal's rule on the meetings, shortest first, put back one
///   shortest link between components that the unpeeled solid connected. A bridge between
///   two parts that are otherwise connected (legs that nearly touch) is not put back, so
///   the tunnel it made disappears.
/// - <i>Dents.</i> A removed voxel with three face neighbours or more in the solid comes
///   back (two passes): it fills a notch of the digital surface, which thinning would turn
///   into a spur.
///
/// Guarantees: the solid's components are those of the unpeeled solid (one per connected
/// group of parts); every voxel whose centre is inside the mesh (non-zero winding) is in
/// the solid; an outside centre is in it only where a thin part, a link, a hole of a thin
/// sheet, a pocket or a dent needs it, always within a voxel of the surface. Limits: parts
/// closer than a voxel whose inside centres touch over a patch (not a single cut point)
/// stay joined, so a near-contact can still make a tunnel; a part thinner than a voxel and
/// shorter than about three voxels beyond the rest of the solid is lost; the inside test
/// trusts the orientation of the faces along each line (an inconsistently oriented mesh
/// abstains there and keeps its surface voxels). The peeling is not the default yet: on the
/// demo animals it removes the spurious tunnels, but the later stages (pruning, bone
/// splitting) are tuned for the conservative solid and give more bones on some of them.
///
/// <b>Open meshes.</b> Each hole of the mesh (a cycle of border halfedges) is closed, for
/// the rasterisation only, by a fan of triangles from the centroid of its vertices, so a
/// hole of any size whose border is a cycle of the mesh does not let the flood in. A gap
/// that is no border cycle (between two separate components, or in a polygon soup) is
/// closed by the voxels of its rims when it is narrower than about a voxel. A single open
/// sheet closes into a flat double sheet, which encloses nothing: an error.
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
/// \param np optional named parameters among:
///   - `vertex_point_map`: the positions of the vertices (default:
///     `get(CGAL::vertex_point, mesh)`).
///   - `resolution` (package parameter, `int`): voxels along the longest principal extent
///     of the mesh, in [4, 8192] (default: `default_voxel_resolution`, 64).
///   - `fill_holes` (package parameter, `bool`): close the border cycles of the mesh by fans
///     before rasterising, as above (default: `true`).
///   - `keep_surface_voxels` (package parameter, `bool`): keep every voxel that the
///     surface touches, without the peeling above (the solid then contains the mesh and
///     may have tunnels where parts come within a voxel of each other; default: `true`).
///   - `memory_limit` (package parameter, `double`, bytes): the most memory the function
///     may allocate (default: `default_voxel_memory_limit`, 2 GiB). The need is estimated
///     before allocating: 11 bytes per voxel of the grid's box (6 with
///     `keep_surface_voxels`).
///   - `voxelized_surface_output` (package parameter, `Voxelized_surface*`): receives the
///     triangles rasterised (faces, then hole-filling fans) in the grid's coordinates, for
///     the inside tests of `to_graph()`, `cut_spurious_cycles()` and
///     `move_skeleton_inside()` (their `voxelized_surface`), which then neither read nor
///     transform the mesh again (default: none; a null pointer is the same).
///
/// \returns the number of voxels of the solid.
/// \pre the mesh has at least one face, every coordinate is finite, it encloses some
///      volume at this resolution.
/// \throws std::invalid_argument for an empty mesh (no face), a non-finite coordinate, a
///      mesh of zero area, a resolution out of range, or a mesh that encloses no voxel at
///      all (an open sheet, or a shape thinner than a voxel: raise the resolution or close
///      the mesh). A closed shape whose surface touches all its voxels (a plate under
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
  return internal::voxelize_impl(mesh, voxels, np);
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_VOXELIZE_H
