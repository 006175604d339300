// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// voxel_medial_axis_example: the voxel stages one by one, as a user who wants the
// intermediate products calls them: solid voxelization, distance transform (the MAT
// radius), grassfire thinning, the paths into the lobes of thick plates, the paper's
// pruning (Algorithm 1), and the curve-skeleton
// graph with the mesh vertices mapped to it. Pruning judges each piece's twigs against its
// widest sheet, and on a grid finer than the default one, the end points of the skeleton on
// the default grid guide it, as in extract_control_skeleton().
//
// Usage: voxel_medial_axis_example [MESH] [RESOLUTION]
// Prints the size of each stage. Exits with 1 and a message on stderr on bad input.

#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/route_skeleton_on_finer_grid.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/reach_sheet_lobes.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#ifndef GEODESIC_SKELETON_EXAMPLE_MESH
#define GEODESIC_SKELETON_EXAMPLE_MESH "data/meshes/cow.off"
#endif

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

namespace GS = CGAL::Geodesic_skeleton;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : GEODESIC_SKELETON_EXAMPLE_MESH;
  const int resolution = argc > 2 ? std::atoi(argv[2]) : GS::default_voxel_resolution;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || num_vertices(mesh) == 0)
  {
    std::cerr << "error: cannot read a polygon mesh from '" << filename << "'\n";
    return EXIT_FAILURE;
  }
  try
  {
    //! [voxel_medial_axis]
    // 1. The solid interior, on a grid aligned with the mesh's principal axes. Which
    //    branches the rig has is decided on the default grid (the level of detail); a finer
    //    grid only places them more precisely (step 7).
    const int pruning_resolution = (std::min)(resolution, GS::default_voxel_resolution);
    GS::Dense_voxel_grid solid;
    GS::voxelize(mesh, solid, GS::parameters::resolution(pruning_resolution));

    // 2. The squared distance of every voxel to the outside: the MAT radius function.
    GS::Voxel_distance_field distances = GS::distance_transform(solid);

    // 3. The grassfire: a one-voxel-thick curve skeleton with the solid's topology, and
    //    the sheet radius of its voxels (the half width of a thin sheet, measured in it),
    //    read at one level of distance and across close levels (a thick slanted plate).
    GS::Voxel_skeleton skeleton;
    GS::thin(solid, distances, skeleton);
    const GS::Skeleton_point_counts thinned = GS::count_skeleton_points(skeleton.voxels);

    // 4. A thick plate that thinning burnt to a point or stubs (a starfish, a cushion) gets a
    //    path into each lobe of its medial sheet that the skeleton's balls leave out.
    const GS::Sheet_lobes_report lobes = GS::reach_sheet_lobes(skeleton.voxels, distances);

    // 5. The loops that parts closer than a voxel made, which the mesh has no handle for.
    const std::size_t cut = GS::cut_spurious_cycles(skeleton.voxels, mesh);

    // 6. The paper's pruning; twigs are snipped by the MAT radius (in voxels), or in a
    //    thin sheet by its half width, and so are the branches inside the MAT balls of
    //    the rest of the skeleton; each piece is judged against its widest sheet.
    const GS::Pruning_report pruning = GS::prune_skeleton(skeleton, distances);

    // 7. On a finer grid, the same branches routed through the middle of its solid, which
    //    keeps the links of the pruned skeleton where the finer grid separates parts.
    std::size_t along_coarser = 0;
    if(resolution > pruning_resolution)
    {
      GS::Dense_voxel_grid fine_solid;
      GS::voxelize(mesh, fine_solid, GS::parameters::resolution(resolution));
      GS::add_skeleton_to_solid(skeleton.voxels, fine_solid);
      GS::Voxel_distance_field fine_distances = GS::distance_transform(fine_solid);
      along_coarser = GS::route_skeleton_on_finer_grid(skeleton, distances, fine_distances);
      distances = std::move(fine_distances);
    }

    // 8. The curve skeleton graph: points in the mesh's coordinates, radii, mesh vertices.
    GS::Curve_skeleton<Point, vertex_descriptor> curve;
    GS::to_graph(skeleton, distances, mesh, curve);
    const GS::Skeleton_statistics shape = GS::skeleton_statistics(curve);
    //! [voxel_medial_axis]

    std::cout << "solid voxels:        " << distances.box().volume() << " in the box, voxel size "
              << distances.frame().voxel_size() << "\n"
              << "thinned skeleton:    " << thinned.total() << " voxels, " << thinned.end << " end points, "
              << thinned.branched_connection << " branched connection points\n"
              << "sheet lobes reached: " << lobes.lobes_reached << " (" << lobes.sheet_voxels << " thick sheet voxels)\n"
              << "spurious cycles cut: " << cut << "\n"
              << "pruning:             " << pruning.branched_regions << " branched regions, "
              << pruning.removed_branched_points << " branched points and " << pruning.snipped_points
              << " twig points removed\n"
              << "curve skeleton:      " << shape.points << " points, " << shape.end_points << " ends, "
              << shape.junctions << " junctions, " << shape.cycles << " cycles\n";
    if(resolution > pruning_resolution)
      std::cout << "level of detail:     branches of resolution " << pruning_resolution << " routed at "
                << resolution << ", " << along_coarser << " along the coarser grid's voxels\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
