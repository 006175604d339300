// Specification of IO/read_mesh_with_assimp.h: scene files (glTF, FBX, DAE, ...) read with
// Assimp into one mesh, every mesh placed by its node; a bad file is refused cleanly.
#include <CGAL/Geodesic_skeleton/IO/gltf.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh_with_assimp.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <Geodesic_skeleton_test/rigs.h>
#include <Geodesic_skeleton_test/shapes.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(assimp_input)

namespace gs = CGAL::Geodesic_skeleton;
namespace shapes = Geodesic_skeleton_test;

using Mesh = shapes::Rig_mesh;

namespace {

// Whether reading `path` throws std::runtime_error "PATH: ..." with `words` in it.
bool refused_with(const std::string& path, const std::string& words)
{
  Mesh mesh;
  try
  {
    gs::IO::read_mesh_with_assimp(path, mesh);
  }
  catch(const std::runtime_error& e)
  {
    const std::string message = e.what();
    BOOST_TEST_MESSAGE(message);
    return message.rfind(path + ": ", 0) == 0 && message.find(words) != std::string::npos;
  }
  return false;
}

// Writes the bar, skinned to its skeleton, as a glTF file.
void write_skinned_bar(const std::string& path)
{
  const Mesh bar = shapes::bar();
  const auto skeleton = shapes::bar_skeleton();
  const auto weights = shapes::weights_of(bar, skeleton, CGAL::parameters::default_values());
  gs::IO::write_glTF(path, bar, skeleton,
                     boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, bar)));
}

// Reads `path` (removed after) and checks it is the bar: its counts, closed, 20 long along z
// (with its bottom at z = 0 when `at_origin`: the formats that keep the file's placement).
void check_reads_back_as_the_bar(const std::string& path, bool at_origin)
{
  const Mesh bar = shapes::bar();
  Mesh back;
  gs::IO::read_mesh_with_assimp(path, back);
  std::remove(path.c_str());
  BOOST_CHECK_EQUAL(num_vertices(back), num_vertices(bar));
  BOOST_CHECK_EQUAL(num_faces(back), num_faces(bar));
  BOOST_CHECK(CGAL::is_closed(back));
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(back);
  BOOST_CHECK_CLOSE(box.zmax() - box.zmin(), 20., 1e-3);
  if(at_origin)
    BOOST_CHECK_SMALL(box.zmin(), 1e-6);
}

} // namespace

BOOST_AUTO_TEST_CASE(a_skinned_gltf_written_by_the_package_reads_back)
{
  for(const std::string path : {"assimp_bar.gltf", "assimp_bar.glb"})
  {
    write_skinned_bar(path);
    check_reads_back_as_the_bar(path, true);
  }
}

BOOST_AUTO_TEST_CASE(fbx_and_dae_files_read_into_the_same_mesh)
{
  // The package's glTF of the bar, turned into FBX and COLLADA by Assimp's own exporters,
  // reads back as the same closed bar: the formats characters come in. ASCII FBX: Assimp
  // 5.2's importer refuses the binary FBX its own exporter writes ("block offset is out of
  // range"); binary FBX from Blender reads (checked by hand, doc/manual.md).
  write_skinned_bar("assimp_bar_source.glb");
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile("assimp_bar_source.glb", 0);
  std::remove("assimp_bar_source.glb");
  BOOST_REQUIRE(scene != nullptr);
  for(const auto& [format, path] : {std::pair<std::string, std::string>{"fbxa", "assimp_bar.fbx"},
                                    std::pair<std::string, std::string>{"collada", "assimp_bar.dae"}})
  {
    Assimp::Exporter exporter;
    BOOST_REQUIRE_MESSAGE(exporter.Export(scene, format, path) == AI_SUCCESS,
                          format << ": " << exporter.GetErrorString());
    check_reads_back_as_the_bar(path, false);
  }
}

BOOST_AUTO_TEST_CASE(the_meshes_of_several_nodes_are_merged_where_their_nodes_put_them)
{
  // A glTF scene: one tetrahedron shown by two nodes, the second moved by 10 along x.
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.buffers.resize(1);
  const std::vector<float> corners{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::vector<std::uint32_t> triangles{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = gs::IO::internal::add_gltf_accessor(
      model, corners, 4, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  model.accessors.back().minValues = {0, 0, 0};
  model.accessors.back().maxValues = {1, 1, 1};
  primitive.indices = gs::IO::internal::add_gltf_accessor(model, triangles, 12, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                                          TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  model.meshes.resize(1);
  model.meshes[0].primitives.push_back(primitive);
  model.nodes.resize(3);
  model.nodes[0].children = {1, 2};
  model.nodes[1].mesh = 0;
  model.nodes[2].mesh = 0;
  model.nodes[2].translation = {10, 0, 0};
  model.scenes.resize(1);
  model.scenes[0].nodes = {0};
  model.defaultScene = 0;
  const std::string path = "assimp_two_nodes.gltf";
  {
    std::ofstream out(path);
    tinygltf::TinyGLTF writer;
    BOOST_REQUIRE(writer.WriteGltfSceneToStream(&model, out, true, false));
  }
  Mesh mesh;
  gs::IO::read_mesh_with_assimp(path, mesh);
  std::remove(path.c_str());
  BOOST_CHECK_EQUAL(num_vertices(mesh), 8u);
  BOOST_CHECK_EQUAL(num_faces(mesh), 8u);
  std::vector<std::size_t> component(num_faces(mesh));
  BOOST_CHECK_EQUAL(CGAL::Polygon_mesh_processing::connected_components(
                        mesh, boost::make_iterator_property_map(component.begin(), get(CGAL::face_index, mesh))),
                    2u);
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  BOOST_CHECK_SMALL(box.xmin(), 1e-6);
  BOOST_CHECK_CLOSE(box.xmax(), 11., 1e-5);
}

BOOST_AUTO_TEST_CASE(polygons_are_triangulated)
{
  const std::string path = "assimp_quads.obj";
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                         "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n";
  Mesh mesh;
  gs::IO::read_mesh_with_assimp(path, mesh);
  std::remove(path.c_str());
  BOOST_CHECK_EQUAL(num_vertices(mesh), 5u);
  BOOST_CHECK_EQUAL(num_faces(mesh), 6u);
  BOOST_CHECK(CGAL::is_triangle_mesh(mesh));
  BOOST_CHECK(CGAL::is_closed(mesh));
}

BOOST_AUTO_TEST_CASE(bad_files_are_refused_with_the_path_and_the_reason)
{
  BOOST_CHECK(refused_with("no_such_file.fbx", "cannot open the file"));
  std::mt19937 random(13);
  for(const std::string name : {"garbage.fbx", "garbage.glb", "garbage.dae", "garbage.gltf"})
  {
    std::ofstream out(name, std::ios::binary);
    for(int i = 0; i < 4096; ++i)
      out.put(char(random() & 0xff));
    out.close();
    BOOST_CHECK(refused_with(name, "cannot be read") || refused_with(name, "no mesh"));
    std::remove(name.c_str());
  }
  // A binary FBX header followed by garbage.
  {
    std::ofstream out("truncated.fbx", std::ios::binary);
    out << std::string("Kaydara FBX Binary  \0\x1a\0", 23);
    for(int i = 0; i < 512; ++i)
      out.put(char(random() & 0xff));
  }
  BOOST_CHECK(refused_with("truncated.fbx", "cannot be read") || refused_with("truncated.fbx", "no mesh"));
  std::remove("truncated.fbx");
  // Points only: no face.
  std::ofstream("points.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  BOOST_CHECK(refused_with("points.obj", "no"));
  std::remove("points.obj");
}

BOOST_AUTO_TEST_SUITE_END()
