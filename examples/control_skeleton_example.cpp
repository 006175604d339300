// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// control_skeleton_example: the whole chain in one call, then the control skeleton written
// as BVH (importable by Blender as an armature).
//
// Usage: control_skeleton_example [MESH] [OUT.bvh]
// Prints the joints and bones; writes OUT.bvh when given. Exits with 1 on bad input.

#include <CGAL/Geodesic_skeleton/IO/bvh.h>
#include <CGAL/Geodesic_skeleton/chord_to_point_distance_accumulation.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>
#include <CGAL/Geodesic_skeleton/split_into_bones.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <vector>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>

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
    //! [control_skeleton]
    // Mesh to control skeleton, every stage with its default; a finer grid and a
    // smoother skeleton are one named parameter away.
    GS::Control_skeleton<Point> control;
    const GS::Control_skeleton_report report = GS::extract_control_skeleton(
        mesh, control,
        GS::parameters::combine(GS::parameters::resolution(64), GS::parameters::smoothing_window(5)));

    // Walk the tree: every joint but the root has a parent; bones lead to their child.
    for(const GS::Control_bone<Point>& bone : control.bones)
      std::cout << GS::to_string(control.joints[bone.parent].kind) << ' ' << bone.parent << " -> "
                << GS::to_string(control.joints[bone.child].kind) << ' ' << bone.child << ", "
                << bone.length << " long\n";

    // Write it for an animation tool.
    if(argc > 2)
    {
      std::ofstream bvh(argv[2]);
      GS::IO::write_BVH(bvh, control);
    }
    //! [control_skeleton]
    std::cout << control.joints.size() << " joints, " << control.bones.size() << " bones, in "
              << report.total_ms << " ms\n";

    //! [split_into_bones]
    // The later stages alone, on the curve skeleton the chain hands back: a coarser rig
    // (joints at bends of about 48 degrees or more only, bones allowed to stray by 1.5
    // radii from straight) from the same smoothed skeleton...
    GS::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor> curve;
    GS::extract_control_skeleton(mesh, control, GS::parameters::curve_skeleton_output(&curve));
    GS::Control_skeleton<Point> coarse;
    GS::split_into_bones(curve, coarse,
                         GS::parameters::combine(GS::parameters::bend_threshold(0.126),
                                                 GS::parameters::straightness_tolerance(1.5)));

    // ... and the chord-to-point distance accumulation along the longest bone, with chords
    // of a third of its length: where it peaks, the bone bends most.
    const auto& longest = *std::max_element(control.bones.begin(), control.bones.end(),
                                            [](const auto& a, const auto& b) { return a.length < b.length; });
    std::vector<double> bend;
    GS::chord_to_point_distance_accumulation(longest.points, longest.length / 3, std::back_inserter(bend));
    //! [split_into_bones]
    std::cout << "coarser rig: " << coarse.bones.size() << " bones; longest bone: " << longest.points.size()
              << " points, largest accumulation " << *std::max_element(bend.begin(), bend.end()) << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
