// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// reeb_graph_example: the Reeb graph of a mesh over a mapping function: the geodesic
// distance from an extremity, or the integral geodesic of the Multiresolution Reeb Graph.
//
// Usage: reeb_graph_example [MESH] [INTERVALS]
// Prints the nodes, arcs, ends and cycles of both graphs. Exits with 1 on bad input.

#include <CGAL/Geodesic_skeleton/geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/integral_geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/reeb_graph.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

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
  const std::size_t intervals = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 30;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || num_vertices(mesh) == 0)
  {
    std::cerr << "error: cannot read a polygon mesh from '" << filename << "'\n";
    return EXIT_FAILURE;
  }
  try
  {
    //! [reeb_graph]
    // A mapping function: the geodesic distance from an extremity of each component.
    auto field = mesh.add_property_map<vertex_descriptor, double>("v:geodesic").first;
    GS::geodesic_mapping_function(mesh, field);

    // Its Reeb graph: one node per connected part of the mesh in each interval.
    GS::Reeb_graph<Mesh> reeb;
    GS::reeb_graph(mesh, field, intervals, reeb);

    // The same with the integral geodesic of the Multiresolution Reeb Graph.
    auto integral = mesh.add_property_map<vertex_descriptor, double>("v:integral").first;
    GS::integral_geodesic_mapping_function(mesh, integral);
    GS::Reeb_graph<Mesh> integral_reeb;
    GS::reeb_graph(mesh, integral, intervals, integral_reeb);
    //! [reeb_graph]

    for(const auto* graph : {&reeb, &integral_reeb})
    {
      const GS::Skeleton_statistics s = GS::skeleton_statistics(*graph);
      std::cout << (graph == &reeb ? "geodesic:          " : "integral geodesic: ") << s.points << " nodes, "
                << s.edges << " arcs, " << s.end_points << " ends, " << s.cycles << " cycles\n";
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
