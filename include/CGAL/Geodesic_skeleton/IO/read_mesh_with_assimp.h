// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_READ_MESH_WITH_ASSIMP_H
#define CGAL_GEODESIC_SKELETON_IO_READ_MESH_WITH_ASSIMP_H

/// \file IO/read_mesh_with_assimp.h
/// Reads the meshes of an FBX, glTF/GLB, COLLADA (DAE) or any other file that the Open Asset
/// Import Library (Assimp) reads, merged into one mesh.
///
/// This header needs Assimp (Debian: `libassimp-dev`; CMake `find_package(assimp)`, target
/// `assimp::assimp`), a compiled library: link it. The rest of the package does not need it,
/// and the umbrella header `CGAL/Geodesic_skeleton.h` does not include this one.

#include <CGAL/Geodesic_skeleton/IO/internal/soup_to_mesh.h>

#include <CGAL/boost/graph/properties.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

// Appends the triangles of the meshes of `node` and its descendants to the soup, each mesh's
// vertices moved by the node's global transform (`parent` times the node's own).
template <typename Point>
void append_assimp_node(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                        std::vector<Point>& points, std::vector<std::vector<std::size_t>>& polygons)
{
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for(unsigned int m = 0; m < node.mNumMeshes; ++m)
  {
    if(node.mMeshes[m] >= scene.mNumMeshes)
      throw std::runtime_error("a node refers to a mesh that does not exist");
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const std::size_t first = points.size();
    for(unsigned int v = 0; v < mesh.mNumVertices; ++v)
    {
      const aiVector3D p = transform * mesh.mVertices[v];
      points.emplace_back(double(p.x), double(p.y), double(p.z));
    }
    for(unsigned int f = 0; f < mesh.mNumFaces; ++f)
    {
      const aiFace& face = mesh.mFaces[f];
      if(face.mNumIndices < 3) // points and lines: not a surface
        continue;
      std::vector<std::size_t> polygon;
      for(unsigned int i = 0; i < face.mNumIndices; ++i)
      {
        if(face.mIndices[i] >= mesh.mNumVertices)
          throw std::runtime_error("a face refers to vertex " + std::to_string(face.mIndices[i]) +
                                   ", but its mesh has only " + std::to_string(mesh.mNumVertices) + " vertices");
        polygon.push_back(first + std::size_t(face.mIndices[i]));
      }
      polygons.push_back(std::move(polygon));
    }
  }
  for(unsigned int c = 0; c < node.mNumChildren; ++c)
    append_assimp_node(scene, *node.mChildren[c], transform, points, polygons);
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Reads every mesh of the scene file `path` with Assimp (FBX, glTF 2.0 `.gltf`/`.glb`,
/// COLLADA `.dae`, Blender, 3DS, OBJ, ...: what the installed Assimp reads) into `mesh`
/// (cleared first), merged into one: each mesh placed by the global transform of every node
/// that shows it (a mesh shown by two nodes comes twice), in the file's units. Polygons are
/// triangulated and identical vertices joined (`aiProcess_Triangulate |
/// aiProcess_JoinIdenticalVertices`); points and lines are left out. The soup is then checked
/// and repaired as `read_mesh()` does (finite coordinates, valid indices, at least one face;
/// not a clean manifold: repaired and oriented). A skinned mesh is read in its bind pose;
/// its skeleton and weights are not read.
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` with a vertex point map whose points are
///         constructible from three `double`s (`Surface_mesh`, `Polyhedron_3`, ...).
/// \throws std::runtime_error with a message "PATH: problem" when the file cannot be opened,
///         Assimp cannot read it (the message gives Assimp's reason), it holds no mesh, a
///         coordinate is not finite, an index names no vertex, or there is no face.
///
/// \b Complexity: Assimp's reading, then O(N + F) for N vertices and F faces (plus the
/// repair's O((N + F) log(N + F)) when needed).
template <typename PolygonMesh>
void read_mesh_with_assimp(const std::string& path, PolygonMesh& mesh)
{
  using Point = typename boost::property_traits<
      typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type;
  auto fail = [&](const std::string& problem) { throw std::runtime_error(path + ": " + problem); };
  if(!std::ifstream(path))
    fail("cannot open the file");
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if(scene == nullptr)
    fail(std::string("the file cannot be read as a scene: ") + importer.GetErrorString());
  if((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || scene->mRootNode == nullptr || scene->mNumMeshes == 0)
    fail("the file holds no mesh");
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  try
  {
    internal::append_assimp_node(*scene, *scene->mRootNode, aiMatrix4x4(), points, polygons);
  }
  catch(const std::runtime_error& e)
  {
    fail(e.what());
  }
  importer.FreeScene();
  internal::polygon_soup_to_checked_mesh(path, points, polygons, mesh);
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_READ_MESH_WITH_ASSIMP_H
