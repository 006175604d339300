// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// skinning_example: a mesh, its control skeleton, its skinning weights (geodesic voxel
// binding), and the three written as a skinned glTF 2.0 file that Blender imports as a mesh
// bound to an armature.
//
// Usage: skinning_example [MESH] [OUT.glb]
// Prints how many vertices each bone drives; writes OUT.glb (or .gltf) when given. Exits with
// 1 on bad input.

#include <CGAL/Geodesic_skeleton/IO/gltf.h>
#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#ifndef GEODESIC_SKELETON_EXAMPLE_MESH
#define GEODESIC_SKELETON_EXAMPLE_MESH "data/meshes/cow.off"
#endif

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

namespace GS = CGAL::Geodesic_skeleton;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : GEODESIC_SKELETON_EXAMPLE_MESH;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || num_vertices(mesh) == 0)
  {
    std::cerr << "error: cannot read a polygon mesh from '" << filename << "'\n";
    return EXIT_FAILURE;
  }
  try
  {
    //! [skinning]
    GS::Control_skeleton<Point> control;
    GS::extract_control_skeleton(mesh, control);

    // Up to 4 bones per vertex, in a property map of the mesh; and the bone of largest
    // weight of each vertex (the mesh cut into one piece per bone).
    auto weights = mesh.add_property_map<Mesh::Vertex_index, GS::Bone_weights>("v:bone_weights").first;
    auto segment = mesh.add_property_map<Mesh::Vertex_index, int>("v:bone", -1).first;
    const GS::Skinning_report report = GS::compute_skinning_weights(
        mesh, control, weights,
        GS::parameters::combine(GS::parameters::max_bones_per_vertex(4), GS::parameters::sharpness(2.5),
                                GS::parameters::bone_segmentation_map(segment)));

    // Mesh, armature and weights, for an animation tool.
    if(argc > 2)
      GS::IO::write_glTF(argv[2], mesh, control, weights);
    //! [skinning]

    const auto bones = GS::numbered_bones(control);
    std::vector<std::size_t> driven(bones.size(), 0);
    std::size_t influences = 0;
    for(Mesh::Vertex_index v : vertices(mesh))
    {
      ++driven[std::size_t(segment[v])];
      influences += weights[v].size();
    }
    for(std::size_t b = 0; b < bones.size(); ++b)
      std::cout << "bone " << b << " (" << source(bones[b], control) << " -> " << target(bones[b], control) << "): "
                << driven[b] << " vertices\n";
    std::cout << num_vertices(mesh) << " vertices, " << bones.size() << " bones, "
              << double(influences) / double(num_vertices(mesh)) << " bones per vertex on average, weights in "
              << report.milliseconds << " ms\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << '\n';
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
