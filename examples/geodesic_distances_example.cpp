// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// geodesic_distances_example: geodesic distances on a triangle mesh (Dijkstra over its
// edges), the first stage of the package's data flow.
//
// Usage: geodesic_distances_example [MESH] [SOURCE_VERTEX]
//   MESH           a mesh file that CGAL reads (OFF, OBJ, PLY, ...); default: the demo
//                  cow.off of the build tree.
//   SOURCE_VERTEX  the index of the source vertex. Without it, the example takes the
//                  farthest-point pair: the vertex farthest from vertex 0 becomes the source.
// Prints the number of vertices, the largest distance (world units), the farthest vertex and
// the number of vertices on a shortest path to it. Exits with 1 and a message on stderr when
// the input cannot be used.

#include <CGAL/Geodesic_skeleton/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#ifndef GEODESIC_SKELETON_EXAMPLE_MESH
#define GEODESIC_SKELETON_EXAMPLE_MESH "data/meshes/cow.off"
#endif

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

namespace GS = CGAL::Geodesic_skeleton;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : GEODESIC_SKELETON_EXAMPLE_MESH;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from '" << filename
              << "' (missing file, or not a valid OFF/OBJ/PLY/STL mesh)\n";
    return EXIT_FAILURE;
  }
  if(num_vertices(mesh) == 0)
  {
    std::cerr << "error: the mesh in '" << filename << "' has no vertices\n";
    return EXIT_FAILURE;
  }

  long source_index = -1; // -1: the end of a farthest-point pair
  if(argc > 2)
  {
    char* end = nullptr;
    source_index = std::strtol(argv[2], &end, 10);
    if(*end != '\0' || source_index < 0 || source_index >= long(num_vertices(mesh)))
    {
      std::cerr << "error: source vertex '" << argv[2] << "' is not an index in [0, "
                << num_vertices(mesh) << ")\n";
      return EXIT_FAILURE;
    }
  }

  try
  {
    //! [geodesic_distances]
    // The source: the given vertex, or the end of a farthest-point pair (the vertex
    // farthest from vertex 0), which lies at a tip of the shape.
    const vertex_descriptor source =
        source_index >= 0 ? vertex_descriptor(Mesh::size_type(source_index))
                          : GS::farthest_vertex(mesh, *vertices(mesh).begin()).first;

    // Distances from the source to every vertex, in a property map owned by the caller.
    auto distance = mesh.add_property_map<vertex_descriptor, double>("v:distance").first;
    GS::geodesic_distances(mesh, source, distance);

    // The vertex farthest from the source (unreached vertices are skipped), and a
    // shortest edge path to it, as a vertex sequence.
    const auto [farthest, max_distance] = GS::farthest_vertex(mesh, source);
    std::vector<vertex_descriptor> path;
    GS::shortest_path(mesh, source, farthest, std::back_inserter(path));
    //! [geodesic_distances]

    std::cout << "mesh:              " << filename << "\n"
              << "vertices:          " << num_vertices(mesh) << "\n"
              << "source vertex:     " << std::size_t(source) << "\n"
              << "max distance:      " << max_distance << " (world units)\n"
              << "farthest vertex:   " << std::size_t(farthest) << " (distance " << distance[farthest]
              << ")\n"
              << "shortest path:     " << path.size() << " vertices\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
