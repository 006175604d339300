// skeletonize_formats.so: the plug-in that skeletonize loads (dlopen) when it reads an FBX,
// glTF or DAE file or writes a skinned glTF file; see skeletonize_formats.h for why.

#include "skeletonize_formats.h"

#include <CGAL/Geodesic_skeleton/IO/gltf.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh_with_assimp.h>

#include <boost/property_map/property_map.hpp>

#include <exception>

namespace {

using namespace skeletonize_formats;

std::string read_scene(const std::string& path, Mesh& mesh)
{
  try
  {
    CGAL::Geodesic_skeleton::IO::read_mesh_with_assimp(path, mesh);
    return std::string();
  }
  catch(const std::exception& e)
  {
    return e.what();
  }
}

std::string write_glTF(std::ostream& out, const Mesh& mesh, const CGAL::Geodesic_skeleton::Control_skeleton<Point>& skeleton,
                       const std::vector<CGAL::Geodesic_skeleton::Bone_weights>& weights, bool binary)
{
  try
  {
    CGAL::Geodesic_skeleton::IO::write_glTF(
        out, mesh, skeleton, boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, mesh)), binary);
    return std::string();
  }
  catch(const std::exception& e)
  {
    return e.what();
  }
}

const Functions functions{&read_scene, &write_glTF};

} // namespace

extern "C" __attribute__((visibility("default"))) const Functions* geodesic_skeleton_skeletonize_formats()
{
  return &functions;
}
