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

#include <boost/graph/depth_first_search.hpp>

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

//! [bone_printer]
// Prints each bone as a depth-first walk of the forest meets it, parent before child.
struct Bone_printer : boost::default_dfs_visitor
{
  template <typename Bone, typename Skeleton>
  void tree_edge(Bone bone, const Skeleton& control) const
  {
    const auto parent = source(bone, control), child = target(bone, control);
    std::cout << GS::to_string(control[parent].kind) << ' ' << parent << " -> " << GS::to_string(control[child].kind)
              << ' ' << child << ", " << control[bone].length << " long\n";
  }
};
//! [bone_printer]

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

    // Walk the forest, a boost::adjacency_list whose edges are the bones (parent joint to
    // child joint), depth first from each root.
    std::vector<boost::default_color_type> colour(num_vertices(control), boost::white_color);
    for(std::size_t root : control[boost::graph_bundle].roots)
      boost::depth_first_visit(control, root, Bone_printer(), colour.data());

    // Write it for an animation tool.
    if(argc > 2)
    {
      std::ofstream bvh(argv[2]);
      GS::IO::write_BVH(bvh, control);
    }
    //! [control_skeleton]
    std::cout << num_vertices(control) << " joints, " << num_edges(control) << " bones, in "
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
    const auto bones = edges(control);
    const GS::Control_bone<Point>& longest = control[*std::max_element(
        bones.first, bones.second, [&](const auto& a, const auto& b) { return control[a].length < control[b].length; })];
    std::vector<double> bend;
    GS::chord_to_point_distance_accumulation(longest.points, longest.length / 3, std::back_inserter(bend));
    //! [split_into_bones]
    std::cout << "coarser rig: " << num_edges(coarse) << " bones; longest bone: " << longest.points.size()
              << " points, largest accumulation " << *std::max_element(bend.begin(), bend.end()) << "\n";
  }
  catch(const std::exception& e)
  {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
