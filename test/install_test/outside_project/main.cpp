// A user's program, built against the installed package: geodesic distances on both
// CGAL mesh types, which must agree.
#include <CGAL/Geodesic_skeleton.h>

// The umbrella header needs none of the file-format libraries (nlohmann_json, tinygltf,
// Assimp): the installed package does not find them, and this project does not link them.
#if defined(INCLUDE_NLOHMANN_JSON_HPP_) || defined(TINY_GLTF_H_) || defined(AI_SCENE_H_INC)
#error "<CGAL/Geodesic_skeleton.h> includes a file-format library"
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

template <typename Mesh>
double farthest_distance(const char* path)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || num_vertices(mesh) == 0)
    throw std::runtime_error(std::string("cannot read ") + path);
  return CGAL::Geodesic_skeleton::farthest_vertex(mesh, *vertices(mesh).begin()).second;
}

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: outside_user MESH\n";
    return 2;
  }
  const double on_surface_mesh = farthest_distance<CGAL::Surface_mesh<Kernel::Point_3>>(argv[1]);
  const double on_polyhedron = farthest_distance<CGAL::Polyhedron_3<Kernel>>(argv[1]);
  std::cout << "farthest geodesic distance: Surface_mesh " << on_surface_mesh
            << ", Polyhedron_3 " << on_polyhedron << "\n";
  return (on_surface_mesh > 0 && std::abs(on_surface_mesh - on_polyhedron) < 1e-9) ? 0 : 1;
}
