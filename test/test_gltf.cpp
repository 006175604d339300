// Specification of IO/gltf.h: a skinned glTF 2.0 file that tinygltf's own loader reads
// back, whose skin poses the mesh as linear blend skinning says (computed here from the
// file's matrices, as a glTF viewer does).
#include <CGAL/Geodesic_skeleton/IO/gltf.h>
#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>

#include <Geodesic_skeleton_test/rigs.h>
#include <Geodesic_skeleton_test/shapes.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(gltf)

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
namespace shapes = Geodesic_skeleton_test;

using Point = shapes::Rig_point;
using Mesh = shapes::Rig_mesh;
using Control = shapes::Rig_skeleton;

namespace {

using Pose = std::map<int, Eigen::Quaterniond>; // node -> rotation

// The values of an accessor, `components` per element, read through its buffer view.
template <typename T>
std::vector<T> accessor_values(const tinygltf::Model& m, int index, std::size_t components)
{
  const tinygltf::Accessor& a = m.accessors.at(std::size_t(index));
  const tinygltf::BufferView& view = m.bufferViews.at(std::size_t(a.bufferView));
  const tinygltf::Buffer& buffer = m.buffers.at(std::size_t(view.buffer));
  const std::size_t element = sizeof(T) * components;
  const std::size_t stride = view.byteStride ? view.byteStride : element;
  const std::size_t start = view.byteOffset + a.byteOffset;
  BOOST_REQUIRE(a.count == 0 || start + (a.count - 1) * stride + element <= buffer.data.size());
  BOOST_REQUIRE(a.count == 0 || (a.count - 1) * stride + element <= view.byteLength);
  std::vector<T> values(a.count * components);
  for(std::size_t i = 0; i < a.count; ++i)
    std::memcpy(&values[i * components], buffer.data.data() + start + i * stride, element);
  return values;
}

// The global transform of every node, the nodes of `pose` rotated (about their origins).
std::vector<Eigen::Matrix4d> global_transforms(const tinygltf::Model& m, const Pose& pose)
{
  std::vector<int> parent(m.nodes.size(), -1);
  for(std::size_t k = 0; k < m.nodes.size(); ++k)
    for(int c : m.nodes[k].children)
      parent.at(std::size_t(c)) = int(k);
  std::vector<Eigen::Matrix4d> global(m.nodes.size());
  std::vector<bool> done(m.nodes.size(), false);
  std::function<const Eigen::Matrix4d&(std::size_t)> transform = [&](std::size_t k) -> const Eigen::Matrix4d& {
    if(done[k])
      return global[k];
    const tinygltf::Node& node = m.nodes[k];
    BOOST_REQUIRE(node.matrix.empty() && node.scale.empty());
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    if(!node.translation.empty())
      local.block<3, 1>(0, 3) = Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]);
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    if(!node.rotation.empty())
      rotation = Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if(pose.count(int(k)))
      rotation = pose.at(int(k));
    local.block<3, 3>(0, 0) = rotation.toRotationMatrix();
    global[k] = parent[k] < 0 ? local : Eigen::Matrix4d(transform(std::size_t(parent[k])) * local);
    done[k] = true;
    return global[k];
  };
  for(std::size_t k = 0; k < m.nodes.size(); ++k)
    transform(k);
  return global;
}

// The node that holds the skinned mesh.
const tinygltf::Node& mesh_node(const tinygltf::Model& m)
{
  for(const tinygltf::Node& node : m.nodes)
    if(node.mesh >= 0)
      return node;
  throw std::runtime_error("no mesh node");
}

// The mesh's vertices posed by linear blend skinning: sum over the influences of
// weight * (global transform of the joint) * (its inverse bind matrix) * rest position.
std::vector<Eigen::Vector3d> skinned_positions(const tinygltf::Model& m, const Pose& pose)
{
  const tinygltf::Node& node = mesh_node(m);
  const tinygltf::Skin& skin = m.skins.at(std::size_t(node.skin));
  const tinygltf::Primitive& primitive = m.meshes.at(std::size_t(node.mesh)).primitives.at(0);
  const auto global = global_transforms(m, pose);
  const auto inverse_bind = accessor_values<float>(m, skin.inverseBindMatrices, 16);
  std::vector<Eigen::Matrix4d> joint_matrix;
  for(std::size_t k = 0; k < skin.joints.size(); ++k)
    joint_matrix.push_back(global.at(std::size_t(skin.joints[k])) *
                           Eigen::Map<const Eigen::Matrix4f>(&inverse_bind[16 * k]).cast<double>());
  const auto positions = accessor_values<float>(m, primitive.attributes.at("POSITION"), 3);
  std::vector<Eigen::Vector3d> posed(positions.size() / 3, Eigen::Vector3d::Zero());
  for(int set = 0; primitive.attributes.count("JOINTS_" + std::to_string(set)); ++set)
  {
    const auto joints = accessor_values<std::uint16_t>(m, primitive.attributes.at("JOINTS_" + std::to_string(set)), 4);
    const auto weights = accessor_values<float>(m, primitive.attributes.at("WEIGHTS_" + std::to_string(set)), 4);
    for(std::size_t v = 0; v < posed.size(); ++v)
      for(std::size_t i = 0; i < 4; ++i)
      {
        const Eigen::Vector4d rest(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1);
        posed[v] += weights[4 * v + i] * (joint_matrix.at(joints[4 * v + i]) * rest).head<3>();
      }
  }
  return posed;
}

// What every skinned file must hold, checked against the mesh it was written from.
void check_skinned_model(const tinygltf::Model& m, const Mesh& mesh)
{
  BOOST_REQUIRE_EQUAL(m.meshes.size(), 1u);
  BOOST_REQUIRE_EQUAL(m.skins.size(), 1u);
  const tinygltf::Node& node = mesh_node(m);
  BOOST_REQUIRE_EQUAL(node.skin, 0);
  const tinygltf::Skin& skin = m.skins[0];
  BOOST_REQUIRE(skin.skeleton >= 0 && std::size_t(skin.skeleton) < m.nodes.size());
  const tinygltf::Primitive& primitive = m.meshes[0].primitives.at(0);
  BOOST_CHECK_EQUAL(primitive.mode, TINYGLTF_MODE_TRIANGLES);

  // Counts, and the bounds of the positions that glTF requires.
  const tinygltf::Accessor& position = m.accessors.at(std::size_t(primitive.attributes.at("POSITION")));
  BOOST_CHECK_EQUAL(position.count, num_vertices(mesh));
  BOOST_CHECK_EQUAL(m.accessors.at(std::size_t(primitive.indices)).count, 3 * num_faces(mesh));
  BOOST_CHECK_EQUAL(m.accessors.at(std::size_t(primitive.attributes.at("NORMAL"))).count, num_vertices(mesh));
  BOOST_REQUIRE_EQUAL(position.minValues.size(), 3u);
  BOOST_REQUIRE_EQUAL(position.maxValues.size(), 3u);
  const auto positions = accessor_values<float>(m, primitive.attributes.at("POSITION"), 3);
  for(std::size_t a = 0; a < 3; ++a)
  {
    float low = HUGE_VALF, high = -HUGE_VALF;
    for(std::size_t v = 0; v < positions.size() / 3; ++v)
    {
      low = std::min(low, positions[3 * v + a]);
      high = std::max(high, positions[3 * v + a]);
    }
    BOOST_CHECK_EQUAL(position.minValues[a], double(low));
    BOOST_CHECK_EQUAL(position.maxValues[a], double(high));
  }

  // Weights: non-negative, summing to 1, on joints of the skin.
  std::vector<double> sum(num_vertices(mesh), 0.);
  BOOST_REQUIRE(primitive.attributes.count("JOINTS_0") && primitive.attributes.count("WEIGHTS_0"));
  for(int set = 0; primitive.attributes.count("JOINTS_" + std::to_string(set)); ++set)
  {
    const auto joints = accessor_values<std::uint16_t>(m, primitive.attributes.at("JOINTS_" + std::to_string(set)), 4);
    const auto weights = accessor_values<float>(m, primitive.attributes.at("WEIGHTS_" + std::to_string(set)), 4);
    BOOST_REQUIRE_EQUAL(weights.size(), 4 * sum.size());
    for(std::size_t i = 0; i < weights.size(); ++i)
    {
      BOOST_REQUIRE_GE(weights[i], 0.f);
      BOOST_REQUIRE_LT(joints[i], skin.joints.size());
      sum[i / 4] += weights[i];
    }
  }
  for(double s : sum)
    BOOST_REQUIRE_SMALL(s - 1, 1e-5);

  // Inverse bind matrices: invertible, the inverses of the joints' global transforms.
  const auto inverse_bind = accessor_values<float>(m, skin.inverseBindMatrices, 16);
  BOOST_REQUIRE_EQUAL(inverse_bind.size(), 16 * skin.joints.size());
  const auto global = global_transforms(m, Pose());
  for(std::size_t k = 0; k < skin.joints.size(); ++k)
  {
    const Eigen::Matrix4d ibm = Eigen::Map<const Eigen::Matrix4f>(&inverse_bind[16 * k]).cast<double>();
    BOOST_CHECK_GT(std::abs(ibm.determinant()), 1e-6);
    const Eigen::Matrix4d g = global.at(std::size_t(skin.joints[k]));
    const double scale = 1 + g.block<3, 1>(0, 3).norm();
    BOOST_CHECK_SMALL((g * ibm - Eigen::Matrix4d::Identity()).norm(), 1e-6 * scale);
    BOOST_CHECK_SMALL((ibm - g.inverse()).norm(), 1e-6 * scale);
  }

  // Unposed, the skin gives the mesh back.
  const auto rest = skinned_positions(m, Pose());
  for(std::size_t v = 0; v < rest.size(); ++v)
    BOOST_REQUIRE_SMALL((rest[v] - Eigen::Vector3d(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2])).norm(),
                        1e-4);
}

tinygltf::Model load(const std::string& path)
{
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  const bool binary = path.substr(path.size() - 4) == ".glb";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                         : loader.LoadASCIIFromFile(&model, &error, &warning, path);
  BOOST_TEST_INFO(path << ": " << error << warning);
  BOOST_REQUIRE(ok);
  BOOST_CHECK(error.empty());
  return model;
}

struct Rigged
{
  Mesh mesh;
  Control skeleton;
  std::vector<gs::Bone_weights> weights;
  auto weight_map() const { return boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, mesh)); }
};

std::string temporary_path(const std::string& name)
{
  return (boost::unit_test::framework::current_test_case().p_name.get() + "_" + name);
}

Rigged rigged_cow()
{
  auto [mesh, skeleton] = shapes::demo_mesh_with_skeleton("cow.off");
  Rigged r{std::move(mesh), std::move(skeleton), {}};
  r.weights = shapes::weights_of(r.mesh, r.skeleton, CGAL::parameters::default_values());
  return r;
}

// The weights of `mesh` for `skeleton`, written to `name` (its extension picks the format),
// read back with tinygltf's loader, checked against the mesh; the file is removed.
tinygltf::Model skinned_round_trip(const Mesh& mesh, const Control& skeleton, const std::string& name)
{
  const auto weights = shapes::weights_of(mesh, skeleton, CGAL::parameters::default_values());
  const std::string path = temporary_path(name);
  gs::IO::write_glTF(path, mesh, skeleton,
                     boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, mesh)));
  const tinygltf::Model m = load(path);
  std::remove(path.c_str());
  check_skinned_model(m, mesh);
  return m;
}

} // namespace

BOOST_AUTO_TEST_CASE(a_glb_file_reads_back_with_its_counts_weights_and_bind_matrices)
{
  const Rigged cow = rigged_cow();
  const std::string path = temporary_path("cow.glb");
  gs::IO::write_glTF(path, cow.mesh, cow.skeleton, cow.weight_map());
  const tinygltf::Model m = load(path);
  check_skinned_model(m, cow.mesh);
  // One node per bone, per root and per leaf joint, then the mesh's.
  std::size_t leaves = 0;
  for(std::size_t j = 0; j < num_vertices(cow.skeleton); ++j)
    leaves += out_degree(j, cow.skeleton) == 0;
  BOOST_CHECK_EQUAL(m.skins[0].joints.size(), num_edges(cow.skeleton) + cow.skeleton[boost::graph_bundle].roots.size() + leaves);
  BOOST_CHECK_EQUAL(m.nodes.at(std::size_t(m.skins[0].skeleton)).name, "root_" + std::to_string(cow.skeleton[boost::graph_bundle].roots[0]));
  std::remove(path.c_str());
}

BOOST_AUTO_TEST_CASE(a_gltf_file_embeds_its_buffer_and_reads_back)
{
  const Rigged cow = rigged_cow();
  const std::string path = temporary_path("cow.gltf");
  gs::IO::write_glTF(path, cow.mesh, cow.skeleton, cow.weight_map());
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  BOOST_CHECK(text.str().find("data:application/octet-stream;base64,") != std::string::npos);
  check_skinned_model(load(path), cow.mesh);
  std::remove(path.c_str());
}

BOOST_AUTO_TEST_CASE(a_box_of_quads_with_five_bones_per_vertex_reads_back)
{
  // A 2 x 2 x 2 box of six quads; every vertex weighted by five bones of a chain (the fifth
  // goes to a second set of four), vertex 0 with bone 0 twice (the two add up).
  Mesh box;
  std::vector<Mesh::Vertex_index> v;
  for(int k = 0; k < 8; ++k)
    v.push_back(box.add_vertex(Point(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1)));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads)
    BOOST_REQUIRE(box.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]) != Mesh::null_face());
  const Control skeleton = shapes::chain_skeleton(
      {Point(0, 0, -1), Point(0, 0, -0.6), Point(0, 0, -0.2), Point(0, 0, 0.2), Point(0, 0, 0.6), Point(0, 0, 1)});
  std::vector<gs::Bone_weights> weights(8);
  for(std::size_t i = 0; i < 8; ++i)
    for(std::uint32_t b = 0; b < 5; ++b)
      weights[i].push_back((b + i) % 5, float(b + 1));
  weights[0].push_back(0, 3.f);
  const std::string path = temporary_path("box.glb");
  gs::IO::write_glTF(path, box, skeleton, boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, box)));
  const tinygltf::Model m = load(path);
  std::remove(path.c_str());
  const tinygltf::Primitive& primitive = m.meshes.at(0).primitives.at(0);

  // Two triangles per quad, facing out of the box, covering its area.
  const auto positions = accessor_values<float>(m, primitive.attributes.at("POSITION"), 3);
  const auto indices = accessor_values<std::uint32_t>(m, primitive.indices, 1);
  BOOST_REQUIRE_EQUAL(indices.size(), 36u);
  double area = 0;
  for(std::size_t t = 0; t < indices.size(); t += 3)
  {
    Eigen::Vector3d p[3];
    for(int c = 0; c < 3; ++c)
    {
      BOOST_REQUIRE_LT(indices[t + c], 8u);
      p[c] = Eigen::Vector3d(positions[3 * indices[t + c]], positions[3 * indices[t + c] + 1], positions[3 * indices[t + c] + 2]);
    }
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    area += normal.norm() / 2;
    BOOST_CHECK_GT(normal.dot(p[0] + p[1] + p[2]), 0); // outwards: the centre is the origin
  }
  BOOST_CHECK_SMALL(area - 24, 1e-9);

  // The weights read back over both sets, scaled to sum 1.
  BOOST_REQUIRE(primitive.attributes.count("JOINTS_1") && !primitive.attributes.count("JOINTS_2"));
  std::vector<std::map<int, double>> read(8);
  for(int set = 0; set < 2; ++set)
  {
    const auto joints = accessor_values<std::uint16_t>(m, primitive.attributes.at("JOINTS_" + std::to_string(set)), 4);
    const auto values = accessor_values<float>(m, primitive.attributes.at("WEIGHTS_" + std::to_string(set)), 4);
    for(std::size_t k = 0; k < values.size(); ++k)
      if(values[k] > 0)
        read[k / 4][joints[k]] += values[k];
  }
  for(std::size_t i = 0; i < 8; ++i)
  {
    const double total = i == 0 ? 18 : 15;
    BOOST_REQUIRE_EQUAL(read[i].size(), 5u);
    for(std::uint32_t b = 0; b < 5; ++b)
      BOOST_CHECK_SMALL(read[i][int((b + i) % 5)] - ((b + 1) + (i == 0 && (b + i) % 5 == 0 ? 3 : 0)) / total, 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(bending_a_bar_at_its_middle_joint_moves_its_end_rigidly_and_tears_nothing)
{
  const Mesh bar = shapes::bar();
  const tinygltf::Model m = skinned_round_trip(bar, shapes::bar_skeleton(), "bar.glb");

  // Node 1 is bone 1, at its head, joint 1 (z = 10): turn it by 60 degrees about x.
  BOOST_REQUIRE_EQUAL(m.nodes.at(1).name, "bone_1");
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(60 * shapes::pi / 180, Eigen::Vector3d::UnitX()));
  const auto posed = skinned_positions(m, Pose{{1, turn}});
  const Eigen::Vector3d joint(0, 0, 10);
  std::size_t rigid = 0, still = 0;
  for(auto v : vertices(bar))
  {
    const Eigen::Vector3d p(bar.point(v).x(), bar.point(v).y(), bar.point(v).z());
    if(p.z() > 14) // beyond the blend around the joint: bone 1's alone
    {
      BOOST_CHECK_SMALL((posed[v] - (joint + turn * (p - joint))).norm(), 1e-4);
      ++rigid;
    }
    if(p.z() < 6)
    {
      BOOST_CHECK_SMALL((posed[v] - p).norm(), 1e-4);
      ++still;
    }
  }
  BOOST_CHECK_GT(rigid, 100u);
  BOOST_CHECK_GT(still, 100u);
  // No vertex jumps away from its neighbours: no edge is stretched past twice its length.
  double shortest = HUGE_VAL, longest = 0;
  for(auto e : edges(bar))
  {
    const auto a = source(e, bar), b = target(e, bar);
    const double rest = std::sqrt(CGAL::squared_distance(bar.point(a), bar.point(b)));
    const double ratio = (posed[a] - posed[b]).norm() / rest;
    shortest = std::min(shortest, ratio);
    longest = std::max(longest, ratio);
  }
  BOOST_TEST_MESSAGE("edge length ratios after a 60 degree bend: " << shortest << " to " << longest);
  // The inside of the bend folds (linear blend skinning does, with any weights as narrow as
  // artists paint them: bone heat's own blend compresses it to 0.47) but no edge collapses.
  BOOST_CHECK_GT(shortest, 0.2);
  BOOST_CHECK_LT(longest, 2.0);
}

BOOST_AUTO_TEST_CASE(several_trees_hang_from_one_skeleton_node)
{
  shapes::Soup soup = shapes::cylinder(1, 20, 24, 46, true);
  shapes::append(soup, shapes::cylinder(1, 20, 24, 46, true), 4, 0, 0);
  const Mesh mesh = shapes::mesh_of<Mesh>(soup);
  Control skeleton = shapes::chain_skeleton({Point(0, 0, 1), Point(0, 0, 10), Point(0, 0, 19)});
  skeleton = shapes::chain_skeleton({Point(4, 0, 1), Point(4, 0, 19)}, skeleton);
  const tinygltf::Model m = skinned_round_trip(mesh, skeleton, "two_bars.gltf");
  const tinygltf::Node& top = m.nodes.at(std::size_t(m.skins[0].skeleton));
  BOOST_CHECK_EQUAL(top.name, "skeleton");
  BOOST_CHECK_EQUAL(top.children.size(), 2u);
}

BOOST_AUTO_TEST_CASE(bad_skeletons_and_paths_are_refused)
{
  const Mesh bar = shapes::bar();
  const Control skeleton = shapes::bar_skeleton();
  const auto weights = shapes::weights_of(bar, skeleton, CGAL::parameters::default_values());
  const auto map = boost::make_iterator_property_map(weights.begin(), get(CGAL::vertex_index, bar));
  std::ostringstream out;
  BOOST_CHECK_THROW(gs::IO::write_glTF("bar.txt", bar, skeleton, map), std::invalid_argument);
  // The bar's skeleton is the chain 0 -> 1 -> 2; each bone added below breaks the forest.
  Control cycle = skeleton;
  add_edge(2, 0, cycle);
  BOOST_CHECK_THROW(gs::IO::write_glTF(out, bar, cycle, map, true), std::invalid_argument);
  BOOST_CHECK_THROW(gs::IO::write_glTF("cycle.glb", bar, cycle, map), std::invalid_argument);
  BOOST_CHECK(!std::ifstream("cycle.glb")); // refused before the file is made
  Control two_parents = skeleton;
  add_edge(0, 2, two_parents);
  BOOST_CHECK_THROW(gs::IO::write_glTF(out, bar, two_parents, map, true), std::invalid_argument);
  Control loop = skeleton;
  add_edge(0, 0, loop);
  BOOST_CHECK_THROW(gs::IO::write_glTF(out, bar, loop, map, true), std::invalid_argument);
  BOOST_CHECK_THROW(gs::IO::write_glTF("/no/such/folder/bar.glb", bar, skeleton, map), std::runtime_error);
}

BOOST_AUTO_TEST_SUITE_END()
