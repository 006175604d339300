// The file formats that skeletonize loads on demand from a plug-in, skeletonize_formats.so,
// built beside it (examples/skeletonize_formats.cpp): FBX, glTF and DAE input through Assimp,
// and skinned glTF output through tinygltf. Linked into skeletonize itself, those two
// libraries cost every run about 9 ms of start-up (the dynamic loader relocates Assimp's
// 10 MB), more than skeletonizing a small mesh takes; as a plug-in they cost only the runs
// that read or write those files (benchmark/README.md, skeletonize_benchmark).

#ifndef GEODESIC_SKELETON_EXAMPLES_SKELETONIZE_FORMATS_H
#define GEODESIC_SKELETON_EXAMPLES_SKELETONIZE_FORMATS_H

#include <CGAL/Geodesic_skeleton/Bone_weights.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <ostream>
#include <string>
#include <vector>

namespace skeletonize_formats {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;

// What the plug-in offers. Each function returns an empty string on success, else the error
// (no exception crosses the plug-in's boundary).
struct Functions
{
  // IO::read_mesh_with_assimp(path, mesh).
  std::string (*read_scene)(const std::string& path, Mesh& mesh);
  // IO::write_glTF(out, mesh, skeleton, weights (one per vertex, by vertex index), binary).
  std::string (*write_glTF)(std::ostream& out, const Mesh& mesh, const CGAL::Geodesic_skeleton::Control_skeleton<Point>& skeleton,
                            const std::vector<CGAL::Geodesic_skeleton::Bone_weights>& weights, bool binary);
};

// The plug-in's one exported symbol, found with dlsym().
constexpr const char* entry_point = "geodesic_skeleton_skeletonize_formats";
constexpr const char* file_name = "skeletonize_formats.so";

} // namespace skeletonize_formats

#endif // GEODESIC_SKELETON_EXAMPLES_SKELETONIZE_FORMATS_H
