// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The context of the ```cpp blocks of README.md and doc/manual.md: the includes and the
// names that those fragments assume, so that the test `documentation_code_blocks` can
// compile and run them (extract_code_blocks.cmake puts each block in a function of its own,
// after CODE_BLOCK_NAMES). A block may use:
//   Kernel, Mesh, vertex_descriptor   the kernel, CGAL::Surface_mesh of its points, and
//                                      the mesh's vertex descriptor;
//   params                            CGAL::Geodesic_skeleton::parameters;
//   mesh                              a demo mesh (const), read from the command line;
//   source, source_vertex             a vertex of the mesh (its first);
//   distance                          a writable vertex property map of double;
//   my_lengths                        an edge property map of double: the edge lengths.
// Only the umbrella header of the package is included, as a user who follows the README
// would: it must compile without the file-format libraries (nlohmann_json, tinygltf,
// Assimp), which the test's target does not link.

#ifndef GEODESIC_SKELETON_TEST_CODE_BLOCK_CONTEXT_H
#define GEODESIC_SKELETON_TEST_CODE_BLOCK_CONTEXT_H

#include <CGAL/Geodesic_skeleton.h>

#if defined(INCLUDE_NLOHMANN_JSON_HPP_) || defined(TINY_GLTF_H_) || defined(AI_SCENE_H_INC)
#error "<CGAL/Geodesic_skeleton.h> includes a file-format library"
#endif

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <exception>
#include <initializer_list>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
namespace params = CGAL::Geodesic_skeleton::parameters;

struct Code_block_context
{
  const Mesh& mesh;
  vertex_descriptor source;
  Mesh::Property_map<Mesh::Vertex_index, double> distance;
  Mesh::Property_map<Mesh::Edge_index, double> my_lengths;
};

// The names a block may use, declared at the top of its function.
#define CODE_BLOCK_NAMES(context)                                       \
  [[maybe_unused]] const Mesh& mesh = (context).mesh;                   \
  [[maybe_unused]] const vertex_descriptor source = (context).source;   \
  [[maybe_unused]] const vertex_descriptor source_vertex = (context).source; \
  [[maybe_unused]] const auto distance = (context).distance;            \
  [[maybe_unused]] const auto my_lengths = (context).my_lengths;

using Code_block = void (*)(const Code_block_context&);
struct Named_code_block
{
  Code_block run;
  const char* where; // "FILE:LINE" of the block's first line
};

// Reads the mesh argv[1], runs every block on it, and checks that the distance map that
// the blocks fill is a distance field from the source (0 there, positive elsewhere).
// Returns 0 when every block ran, 1 otherwise.
inline int run_code_blocks(int argc, char** argv, std::initializer_list<Named_code_block> blocks)
{
  if(argc != 2)
  {
    std::cerr << "usage: documentation_code_blocks MESH\n";
    return 1;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || num_vertices(mesh) < 2)
  {
    std::cerr << argv[1] << ": cannot read a mesh\n";
    return 1;
  }
  auto distance = mesh.add_property_map<Mesh::Vertex_index, double>("v:distance", -1.0).first;
  auto lengths = mesh.add_property_map<Mesh::Edge_index, double>("e:length", 0.0).first;
  for(Mesh::Edge_index e : edges(mesh))
    lengths[e] = std::sqrt(CGAL::squared_distance(mesh.point(source(e, mesh)), mesh.point(target(e, mesh))));
  const Code_block_context context{mesh, *vertices(mesh).begin(), distance, lengths};

  int status = 0;
  for(const Named_code_block& block : blocks)
  {
    try
    {
      block.run(context);
      std::cout << block.where << ": ran\n";
    }
    catch(const std::exception& e)
    {
      std::cerr << block.where << ": " << e.what() << '\n';
      status = 1;
    }
  }
  std::size_t positive = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
    positive += distance[v] > 0;
  if(distance[context.source] != 0 || positive + 1 != num_vertices(mesh))
  {
    std::cerr << "the blocks did not fill the distance map from the source\n";
    status = 1;
  }
  return status;
}

#endif // GEODESIC_SKELETON_TEST_CODE_BLOCK_CONTEXT_H
