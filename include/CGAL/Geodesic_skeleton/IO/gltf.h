// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_IO_GLTF_H
#define CGAL_GEODESIC_SKELETON_IO_GLTF_H

/// \file IO/gltf.h
/// Writes a mesh, its control skeleton and its skinning weights as a skinned glTF 2.0 file
/// (`.glb` or `.gltf`), with tinygltf.
///
/// This header needs tinygltf (`tiny_gltf.h`) and nlohmann's `json.hpp`; the rest of the
/// package does not, and the umbrella header `CGAL/Geodesic_skeleton.h` does
/// not include it. tinygltf's functions must be compiled once in the program: link the
/// compiled library that distributions ship (Debian's `libtinygltf-dev`: CMake
/// `find_package(TinyGLTF)`, target `TinyGLTF::TinyGLTF`), or, with the header-only
/// tinygltf, define `TINYGLTF_IMPLEMENTATION` (and, unless stb_image is at hand,
/// `TINYGLTF_NO_STB_IMAGE`, `TINYGLTF_NO_STB_IMAGE_WRITE` and
/// `TINYGLTF_NO_EXTERNAL_IMAGE`; this writer stores no image) in exactly one translation
/// unit before including this header.

#include <CGAL/Geodesic_skeleton/Bone_weights.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/IO/internal/mesh_file_checks.h>
#include <CGAL/Geodesic_skeleton/internal/split_into_bones/joint_tree.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/polygon_triangles.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {
namespace IO {
namespace internal {

// `bytes` rounded up to a multiple of 4, the alignment of glTF's buffer views and chunks.
inline std::size_t aligned_to_4(std::size_t bytes) { return (bytes + 3) / 4 * 4; }

// Appends `values` to the model's one buffer (4-byte aligned) as a buffer view and an
// accessor of `count` elements, and frees them; returns the accessor's index.
template <typename T>
int add_gltf_accessor(tinygltf::Model& model, std::vector<T> values, std::size_t count, int component_type,
                      int type, int target)
{
  std::vector<unsigned char>& data = model.buffers[0].data;
  data.resize(aligned_to_4(data.size()), 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = values.size() * sizeof(T);
  view.target = target;
  data.resize(data.size() + view.byteLength);
  if(!values.empty())
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
  model.bufferViews.push_back(view);

  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size() - 1);
  accessor.byteOffset = 0;
  accessor.componentType = component_type;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return int(model.accessors.size() - 1);
}

// Writes the binary glTF container: the 12-byte header, then the JSON chunk (padded with
// spaces) and the binary chunk (padded with zeros), each to a multiple of 4 bytes, lengths
// in little-endian order.
inline void write_glb(std::ostream& os, const std::string& json, const std::vector<unsigned char>& buffer)
{
  auto put_uint32 = [&os](std::uint32_t value) {
    const char bytes[4] = {char(value & 0xff), char((value >> 8) & 0xff), char((value >> 16) & 0xff),
                           char((value >> 24) & 0xff)};
    os.write(bytes, 4);
  };
  const std::size_t json_length = aligned_to_4(json.size()), buffer_length = aligned_to_4(buffer.size());
  const std::size_t total = 12 + 8 + json_length + 8 + buffer_length;
  if(total > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("write_glTF: the model is larger than the 4 GiB a .glb file can hold");
  put_uint32(0x46546C67); // "glTF"
  put_uint32(2);
  put_uint32(std::uint32_t(total));
  put_uint32(std::uint32_t(json_length));
  put_uint32(0x4E4F534A); // "JSON"
  os.write(json.data(), std::streamsize(json.size()));
  os.write("   ", std::streamsize(json_length - json.size()));
  put_uint32(std::uint32_t(buffer_length));
  put_uint32(0x004E4942); // "BIN"
  os.write(reinterpret_cast<const char*>(buffer.data()), std::streamsize(buffer.size()));
  os.write("\0\0\0", std::streamsize(buffer_length - buffer.size()));
}

// Writes `model` to `os`, as a .glb when `binary`, else as JSON with the buffer embedded.
// A .glb's container is written here: tinygltf's writer copies the buffer (the size of the
// mesh and its weights) before writing it. tinygltf gives the JSON of the model without its
// buffer (which `model` then no longer holds), and the buffer's entry is added back.
inline void write_gltf_model(std::ostream& os, tinygltf::Model& model, bool binary)
{
  tinygltf::TinyGLTF writer;
  if(!binary)
  {
    if(!writer.WriteGltfSceneToStream(&model, os, true, false))
      throw std::runtime_error("write_glTF: cannot write the stream");
    return;
  }
  const std::vector<unsigned char> buffer = std::move(model.buffers[0].data);
  model.buffers.clear();
  std::ostringstream text;
  if(!writer.WriteGltfSceneToStream(&model, text, false, false))
    throw std::runtime_error("write_glTF: cannot write the model's JSON");
  nlohmann::json json = nlohmann::json::parse(text.str());
  json["buffers"] = nlohmann::json::array({{{"byteLength", buffer.size()}}});
  write_glb(os, json.dump(), buffer);
}

template <typename Point>
std::array<double, 3> joint_position(const Control_joint<Point>& joint)
{
  return {CGAL::to_double(joint.point.x()), CGAL::to_double(joint.point.y()), CGAL::to_double(joint.point.z())};
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// A skinned glTF 2.0 model (tinygltf) of `mesh`, `skeleton` and `weights`: what
/// `write_glTF()` writes. See `write_glTF()` for the content and the conventions.
template <typename TriangleMesh, typename Point, typename WeightMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
tinygltf::Model skinned_glTF_model(const TriangleMesh& mesh, const Control_skeleton<Point>& skeleton,
                                   WeightMap weights, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const std::string caller = "write_glTF";
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  const std::size_t n = num_vertices(mesh);
  const std::size_t joints = num_vertices(skeleton);
  const Geodesic_skeleton::internal::Joint_tree tree = Geodesic_skeleton::internal::joint_tree(skeleton, caller);
  if(joints == 0)
    throw std::invalid_argument(caller + ": the control skeleton has no joint");
  if(n == 0 || n > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument(caller + ": the mesh must have between 1 and 2^32 - 1 vertices");
  if(num_edges(skeleton) + 2 * joints > std::numeric_limits<std::uint16_t>::max())
    throw std::invalid_argument(caller + ": too many bones and joints for 16-bit joint indices");
  // The bone that leads to each joint: one per joint with a parent, from that parent.
  const std::vector<long>& incoming = tree.incoming;

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "CGAL Geodesic_skeleton";
  model.buffers.resize(1);

  // Positions (with their bounds, which glTF requires), normals, triangles.
  std::vector<float> positions(3 * n), normals(3 * n, 0.f);
  std::vector<double> normal_sums(3 * n, 0.);
  std::vector<double> low(3, HUGE_VAL), high(3, -HUGE_VAL);
  for(auto v : vertices(mesh))
  {
    const std::size_t i = get(vim, v);
    const auto& p = get(vpm, v);
    const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int a = 0; a < 3; ++a)
    {
      if(!std::isfinite(c[a]))
        throw std::invalid_argument(caller + ": a vertex has a non-finite coordinate");
      positions[3 * i + std::size_t(a)] = float(c[a]);
      low[std::size_t(a)] = std::min(low[std::size_t(a)], double(float(c[a])));
      high[std::size_t(a)] = std::max(high[std::size_t(a)], double(float(c[a])));
    }
  }
  // The triangles: a triangle face as it is, a polygon split as the voxel stages split it
  // (a quad or an n-gon, convex or not).
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * std::size_t(num_faces(mesh)));
  std::vector<std::uint32_t> corners;
  std::vector<Geodesic_skeleton::internal::Vec3> corner_points;
  std::vector<Geodesic_skeleton::internal::Corner_triple> polygon;
  for(auto f : faces(mesh))
  {
    corners.clear();
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      corners.push_back(std::uint32_t(get(vim, v)));
    if(corners.size() == 3)
    {
      indices.insert(indices.end(), corners.begin(), corners.end());
      continue;
    }
    corner_points.clear();
    for(std::uint32_t i : corners)
      corner_points.push_back({double(positions[3 * i]), double(positions[3 * i + 1]), double(positions[3 * i + 2])});
    polygon.clear();
    Geodesic_skeleton::internal::append_polygon_triangles(corner_points, polygon);
    for(const auto& triple : polygon)
      for(std::size_t k : triple)
        indices.push_back(corners[k]);
  }
  // The area-weighted normal of each triangle, added to its corners.
  for(std::size_t k = 0; k < indices.size(); k += 3)
  {
    const std::uint32_t* t = &indices[k];
    double e[2][3];
    for(int a = 0; a < 3; ++a)
    {
      e[0][a] = double(positions[3 * t[1] + std::size_t(a)]) - positions[3 * t[0] + std::size_t(a)];
      e[1][a] = double(positions[3 * t[2] + std::size_t(a)]) - positions[3 * t[0] + std::size_t(a)];
    }
    const double normal[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                              e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    for(int c = 0; c < 3; ++c)
      for(int a = 0; a < 3; ++a)
        normal_sums[3 * t[c] + std::size_t(a)] += normal[a];
  }
  if(indices.empty())
    throw std::invalid_argument(caller + ": the mesh has no faces");
  for(std::size_t i = 0; i < n; ++i)
  {
    const double* s = &normal_sums[3 * i];
    const double length = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for(std::size_t a = 0; a < 3; ++a)
      normals[3 * i + a] = length > 0 && std::isfinite(length) ? float(s[a] / length) : a == 2 ? 1.f : 0.f;
  }
  std::vector<double>().swap(normal_sums);

  // The influences of each vertex: bone b is the skin's joint b (the node at its head, see
  // below). Sets of four, as many as the vertex with the most needs (a set is added, zero
  // for the vertices before, when a vertex needs it).
  std::vector<std::vector<std::uint16_t>> joint_sets;
  std::vector<std::vector<float>> weight_sets;
  std::array<std::pair<std::uint16_t, double>, Bone_weights::capacity> influence;
  for(auto v : vertices(mesh))
  {
    const std::size_t i = get(vim, v);
    const Bone_weights w = get(weights, v);
    std::size_t count = 0;
    double total = 0;
    for(std::size_t k = 0; k < w.size(); ++k)
    {
      if(w.bone[k] >= num_edges(skeleton))
        throw std::invalid_argument(caller + ": vertex " + std::to_string(i) + " has a weight for bone " +
                                    std::to_string(w.bone[k]) + ", which does not exist");
      if(!(w.weight[k] >= 0) || !std::isfinite(w.weight[k]))
        throw std::invalid_argument(caller + ": vertex " + std::to_string(i) + " has a negative or non-finite weight");
      // glTF allows one non-zero weight per joint and vertex: repeated bones add up.
      const auto joint = std::uint16_t(w.bone[k]);
      auto same = std::find_if(influence.begin(), influence.begin() + count,
                               [&](const auto& e) { return e.first == joint; });
      if(same != influence.begin() + count)
        same->second += w.weight[k];
      else if(w.weight[k] > 0)
        influence[count++] = {joint, w.weight[k]};
      total += w.weight[k];
    }
    if(!(total > 0))
      throw std::invalid_argument(caller + ": vertex " + std::to_string(i) + " has no weight");
    while(4 * joint_sets.size() < count)
    {
      joint_sets.emplace_back(4 * n, std::uint16_t(0));
      weight_sets.emplace_back(4 * n, 0.f);
    }
    for(std::size_t k = 0; k < count; ++k)
    {
      joint_sets[k / 4][4 * i + k % 4] = influence[k].first;
      weight_sets[k / 4][4 * i + k % 4] = float(influence[k].second / total);
    }
  }

  // The buffer, reserved whole (growing it would copy it), takes each array in turn, which is
  // then freed: the memory holds about one copy of the data at a time.
  using internal::aligned_to_4;
  model.buffers[0].data.reserve(2 * aligned_to_4(12 * n) + aligned_to_4(4 * indices.size()) +
                                joint_sets.size() * (aligned_to_4(8 * n) + aligned_to_4(16 * n)) +
                                64 * (num_edges(skeleton) + joints));
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] = internal::add_gltf_accessor(
      model, std::move(positions), n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  model.accessors.back().minValues = low;
  model.accessors.back().maxValues = high;
  primitive.attributes["NORMAL"] = internal::add_gltf_accessor(
      model, std::move(normals), n, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  const std::size_t index_count = indices.size();
  primitive.indices = internal::add_gltf_accessor(model, std::move(indices), index_count,
                                                  TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                                  TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  for(std::size_t set = 0; set < joint_sets.size(); ++set)
  {
    primitive.attributes["JOINTS_" + std::to_string(set)] =
        internal::add_gltf_accessor(model, std::move(joint_sets[set]), n, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                    TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["WEIGHTS_" + std::to_string(set)] =
        internal::add_gltf_accessor(model, std::move(weight_sets[set]), n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                    TINYGLTF_TYPE_VEC4, TINYGLTF_TARGET_ARRAY_BUFFER);
  }
  tinygltf::Mesh gltf_mesh;
  gltf_mesh.name = "mesh";
  gltf_mesh.primitives.push_back(primitive);
  model.meshes.push_back(gltf_mesh);

  // The skin's joints, as an armature: node b (< B) is bone b, at its head (its parent
  // joint), so that rotating it swings the bone about that joint; then one node per root
  // joint, then one per leaf joint (the tip of the last bone of a limb, which drives no
  // vertex). Each node is translated from its parent node, without rotation; the bind pose
  // is the rest pose, so a node's inverse bind matrix is the translation by minus its origin.
  const std::size_t bones = num_edges(skeleton);
  std::vector<std::size_t> origin_joint(bones), parent_node(bones);
  std::vector<std::size_t> root_node(joints, 0);
  for(std::size_t r : tree.roots)
  {
    root_node[r] = origin_joint.size();
    origin_joint.push_back(r);
    parent_node.push_back(std::size_t(-1));
  }
  std::size_t b = 0;
  for(const auto e : boost::make_iterator_range(edges(skeleton)))
  {
    const std::size_t head = source(e, skeleton);
    origin_joint[b] = head;
    parent_node[b++] = incoming[head] >= 0 ? std::size_t(incoming[head]) : root_node[head];
  }
  for(std::size_t j = 0; j < joints; ++j)
    if(tree.children[j].empty() && incoming[j] >= 0)
    {
      origin_joint.push_back(j);
      parent_node.push_back(std::size_t(incoming[j]));
    }
  const std::size_t nodes = origin_joint.size();
  model.nodes.resize(nodes);
  tinygltf::Skin skin;
  std::vector<float> inverse_bind(16 * nodes, 0.f);
  for(std::size_t k = 0; k < nodes; ++k)
  {
    const std::size_t j = origin_joint[k];
    const auto p = internal::joint_position(skeleton[j]);
    auto offset = p;
    tinygltf::Node& node = model.nodes[k];
    if(parent_node[k] != std::size_t(-1))
    {
      const auto q = internal::joint_position(skeleton[origin_joint[parent_node[k]]]);
      for(std::size_t a = 0; a < 3; ++a)
        offset[a] -= q[a];
      model.nodes[parent_node[k]].children.push_back(int(k));
    }
    node.name = k < bones ? "bone_" + std::to_string(k)
                          : (incoming[j] < 0 ? "root_" : "end_") + std::to_string(j);
    node.translation = {offset[0], offset[1], offset[2]};
    skin.joints.push_back(int(k));
    float* m = &inverse_bind[16 * k]; // column-major
    m[0] = m[5] = m[10] = m[15] = 1.f;
    for(std::size_t a = 0; a < 3; ++a)
    {
      if(!std::isfinite(p[a]))
        throw std::invalid_argument(caller + ": joint " + std::to_string(j) + " has a non-finite coordinate");
      m[12 + a] = float(-p[a]);
    }
  }
  skin.inverseBindMatrices =
      internal::add_gltf_accessor(model, std::move(inverse_bind), nodes, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, 0);
  tinygltf::Scene scene;
  if(tree.roots.size() == 1)
    skin.skeleton = int(root_node[tree.roots.front()]);
  else
  {
    // Several trees: one node without transform holds them, the common root glTF asks for.
    tinygltf::Node armature;
    armature.name = "skeleton";
    for(std::size_t r : tree.roots)
      armature.children.push_back(int(root_node[r]));
    model.nodes.push_back(armature);
    skin.skeleton = int(model.nodes.size() - 1);
  }
  skin.name = "skeleton";
  model.skins.push_back(skin);
  tinygltf::Node mesh_node;
  mesh_node.name = "mesh";
  mesh_node.mesh = 0;
  mesh_node.skin = 0;
  model.nodes.push_back(mesh_node);
  scene.nodes = {int(model.nodes.size() - 1), skin.skeleton};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

/// \ingroup PkgGeodesicSkeletonRef
/// Writes `mesh`, `skeleton` and `weights` as a skinned glTF 2.0 scene to `os`: binary
/// (`.glb`) when `binary` is true, else JSON with the buffer embedded as a data URI
/// (`.gltf`). See `write_glTF(const std::string&, ...)`.
template <typename TriangleMesh, typename Point, typename WeightMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::ostream& write_glTF(std::ostream& os, const TriangleMesh& mesh, const Control_skeleton<Point>& skeleton,
                         WeightMap weights, bool binary,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  tinygltf::Model model = skinned_glTF_model(mesh, skeleton, weights, np);
  internal::write_gltf_model(os, model, binary);
  if(!os)
    throw std::runtime_error("write_glTF: cannot write the stream");
  return os;
}

/// \ingroup PkgGeodesicSkeletonRef
/// Writes `mesh`, `skeleton` and `weights` (from `compute_skinning_weights()`) as a skinned
/// glTF 2.0 file: binary when `path` ends with `.glb`, JSON with the buffer embedded (a
/// base64 data URI) when it ends with `.gltf`. Blender, three.js, Godot and Unity import it
/// as a mesh bound to an armature.
///
/// Content: one mesh (one primitive of triangles; polygons are split into fans) with
/// `POSITION` (with the `min` and `max` glTF requires), `NORMAL` (area-weighted, unit),
/// `indices` (unsigned int), `JOINTS_0` (unsigned short) and `WEIGHTS_0` (float), four
/// influences per vertex padded with zeros (and `JOINTS_1`/`WEIGHTS_1` when a vertex has more
/// than four); an armature of nodes, each translated from its parent node without rotation;
/// a skin whose `joints` are all those nodes, whose `inverseBindMatrices` (float `MAT4`) are
/// the inverses of the nodes' global transforms (translations by minus their origins: the
/// rest pose is the bind pose), and whose `skeleton` is the root node (with several trees, a
/// node without transform that holds their roots); a node with the mesh and the skin.
/// Vertices are in the order of the vertex index map, coordinates in the mesh's units.
///
/// <b>Bones to glTF joints.</b> glTF weights a vertex by joint nodes, and a node turns what
/// it drives about its own origin. So the armature has, as Blender's has, one node per bone
/// at the bone's head: skin joint `b` (node `b`, named `bone_<b>`) is bone `b`, placed at its
/// parent joint (the source of the edge) and child of the node of the bone that leads to
/// that joint; `JOINTS_0` values are thus the bone indices of the weights. Rotating node `b`
/// swings bone `b` and everything below it about the joint it starts from, and two bones out
/// of one junction (two legs from the hip) move independently. Then come one node per root
/// joint (`root_<j>`, parent of the nodes of the bones out of it; it drives no vertex and
/// moves its whole tree), and one per leaf joint (`end_<j>`, the tip of a limb, which drives
/// no vertex but gives importers the last bone's length). The joint that a bone leads to
/// (the target of its edge) is where the node of each bone below it stands.
/// Weights are scaled to sum 1 per vertex; a bone repeated in a vertex's weights adds up.
///
/// \tparam WeightMap a readable vertex property map of `Bone_weights`.
/// \param path the file, `.glb` or `.gltf` (any case).
/// \param mesh the mesh (a model of `FaceListGraph`).
/// \param skeleton its control skeleton; joints in any order, bones forming trees.
/// \param weights the weights of every vertex (bone numbers, see `numbered_bones()`).
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of the vertices of `mesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and a CGAL point as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, mesh)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a bijection from the vertices onto [0, `num_vertices(mesh)`):
///                           the order of the vertices in the file}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and an integer type as value type}
///     \cgalParamDefault{the mesh's internal index, or one initialised on the fly}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws std::invalid_argument for another extension, a skeleton without joint or whose
///         bones do not form trees (two bones to one joint, a bone from a joint to itself,
///         a cycle), more than 65535 nodes, a weight for a bone that does not exist, a vertex without
///         weight, a non-finite coordinate, a mesh without faces, a `.glb` over 4 GiB.
/// \throws std::runtime_error "PATH: cannot write the file" when writing fails. No file is
///         left after either.
///
/// \b Complexity: O(N + F + J) for N vertices, F faces and J joints.
template <typename TriangleMesh, typename Point, typename WeightMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void write_glTF(const std::string& path, const TriangleMesh& mesh, const Control_skeleton<Point>& skeleton,
                WeightMap weights, const NamedParameters& np = CGAL::parameters::default_values())
{
  const std::string extension = internal::file_extension(path);
  if(extension != "glb" && extension != "gltf")
    throw std::invalid_argument("write_glTF: " + path + ": the file must end with .glb or .gltf");
  // The model first, then straight into the file; a failure while writing (a model too
  // large for a .glb, a full disk) removes the part written, so that no file is left.
  tinygltf::Model model = skinned_glTF_model(mesh, skeleton, weights, np);
  std::ofstream out(path, std::ios::binary);
  if(!out)
    throw std::runtime_error(path + ": cannot write the file");
  try
  {
    internal::write_gltf_model(out, model, extension == "glb");
    if(!out.flush())
      throw std::runtime_error(path + ": cannot write the file");
  }
  catch(...)
  {
    out.close();
    std::remove(path.c_str());
    throw;
  }
}

} // namespace IO
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_IO_GLTF_H
