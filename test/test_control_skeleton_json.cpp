// Specification of IO/read_control_skeleton_json.h: the control skeleton that
// control_skeleton_to_json() and skeletonize write reads back, and a hand-written one too;
// a bad file is refused with the reason.
#include <CGAL/Geodesic_skeleton/IO/json.h>
#include <CGAL/Geodesic_skeleton/IO/read_control_skeleton_json.h>

#include <Geodesic_skeleton_test/rigs.h>

#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

BOOST_AUTO_TEST_SUITE(control_skeleton_json)

namespace gs = CGAL::Geodesic_skeleton;
namespace shapes = Geodesic_skeleton_test;

using Control = shapes::Rig_skeleton;
using json = nlohmann::json;

namespace {

Control read(const json& j)
{
  Control skeleton;
  gs::IO::read_control_skeleton_json(j, skeleton);
  return skeleton;
}

// Whether reading `j` throws std::invalid_argument with `words` in its message.
bool refused_with(const json& j, const std::string& words)
{
  try
  {
    read(j);
  }
  catch(const std::invalid_argument& e)
  {
    BOOST_TEST_MESSAGE(e.what());
    return std::string(e.what()).find(words) != std::string::npos;
  }
  return false;
}

// Three joints in a chain: 0 the root, 1 its child, 2 the child of 1.
json chain()
{
  return json::parse(R"({"joints": [{"position": [0, 0, 0], "parent": -1},
                                    {"position": [0, 0, 1], "parent": 0},
                                    {"position": [0, 0, 3], "parent": 1}]})");
}

} // namespace

BOOST_AUTO_TEST_CASE(the_json_that_skeletonize_writes_reads_back)
{
  const Control control = shapes::demo_mesh_with_skeleton("cow.off").skeleton;
  const json written = gs::IO::control_skeleton_to_json(control);
  // Bare, and inside a report as skeletonize writes it.
  for(const json& j : {written, json{{"input", "cow.off"}, {"control", written}}})
  {
    const Control back = read(j);
    BOOST_REQUIRE_EQUAL(num_vertices(back), num_vertices(control));
    BOOST_REQUIRE_EQUAL(num_edges(back), num_edges(control));
    BOOST_CHECK_EQUAL(back[boost::graph_bundle].cut_bones.size(), control[boost::graph_bundle].cut_bones.size());
    BOOST_CHECK(back[boost::graph_bundle].roots == control[boost::graph_bundle].roots);
    for(std::size_t i = 0; i < num_vertices(control); ++i)
    {
      BOOST_CHECK_EQUAL(back[i].point, control[i].point);
      BOOST_CHECK_EQUAL(gs::parent_joint(i, back), gs::parent_joint(i, control));
      BOOST_CHECK(back[i].kind == control[i].kind);
      BOOST_CHECK_EQUAL(back[i].radius, control[i].radius);
    }
    const auto back_bones = gs::numbered_bones(back), bones = gs::numbered_bones(control);
    for(std::size_t b = 0; b < bones.size(); ++b)
    {
      BOOST_CHECK_EQUAL(source(back_bones[b], back), source(bones[b], control));
      BOOST_CHECK_EQUAL(target(back_bones[b], back), target(bones[b], control));
      BOOST_CHECK(back[back_bones[b]].points.empty());
    }
  }
}

BOOST_AUTO_TEST_CASE(a_hand_written_skeleton_gets_its_bones_kinds_and_roots)
{
  json j = chain();
  // Joints in any order: the root last.
  j = json::parse(R"({"joints": [{"position": [0, 0, 1], "parent": 2},
                                 {"position": [0, 0, 3], "parent": 0},
                                 {"position": [0, 0, 0], "parent": -1, "radius": 0.5}]})");
  const Control s = read(j);
  BOOST_REQUIRE_EQUAL(num_edges(s), 2u);
  const auto bones = gs::numbered_bones(s);
  BOOST_CHECK_EQUAL(source(bones[0], s), 2u);
  BOOST_CHECK_EQUAL(target(bones[0], s), 0u);
  BOOST_CHECK_CLOSE(s[bones[1]].length, 2.0, 1e-9);
  BOOST_REQUIRE_EQUAL(s[boost::graph_bundle].roots.size(), 1u);
  BOOST_CHECK_EQUAL(s[boost::graph_bundle].roots[0], 2u);
  BOOST_CHECK(s[2].kind == gs::Joint_kind::root);
  BOOST_CHECK(s[0].kind == gs::Joint_kind::bend);
  BOOST_CHECK(s[1].kind == gs::Joint_kind::end);
  BOOST_CHECK_EQUAL(s[2].radius, 0.5);
}

BOOST_AUTO_TEST_CASE(bad_skeletons_are_refused_with_the_reason)
{
  BOOST_CHECK(refused_with(json::object(), "missing key \"joints\""));
  BOOST_CHECK(refused_with(json{{"control", json::object()}}, "missing key \"joints\""));
  json j = chain();
  j["joints"][1].erase("position");
  BOOST_CHECK(refused_with(j, "joints[1]: missing key \"position\""));
  j = chain();
  j["joints"][2]["position"] = {0, 1};
  BOOST_CHECK(refused_with(j, "three numbers"));
  j = chain();
  j["joints"][2]["parent"] = 7;
  BOOST_CHECK(refused_with(j, "parent 7 does not exist"));
  j = chain();
  j["joints"][0]["parent"] = 2; // 0 -> 2 -> 1 -> 0
  BOOST_CHECK(refused_with(j, "cycle"));
  j = chain();
  j["joints"][1]["parent"] = 1;
  BOOST_CHECK(refused_with(j, "joint 1 has parent 1, itself"));
  j = chain();
  j["joints"][1]["kind"] = "elbow";
  BOOST_CHECK(refused_with(j, "unknown kind 'elbow'"));
  j = chain();
  j["bones"] = {{0, 1}, {0, 2}};
  BOOST_CHECK(refused_with(j, "does not match the parent of joint 2"));
  j = chain();
  j["bones"] = {{0, 1}};
  BOOST_CHECK(refused_with(j, "no bone leads to joint 2"));
  j = chain();
  j["bones"] = {{0, 1}, {1, 5}};
  BOOST_CHECK(refused_with(j, "bones[1] refers to a joint that does not exist"));
  j = chain();
  j["roots"] = json::array({1});
  BOOST_CHECK(refused_with(j, "\"roots\" must list exactly"));
}

BOOST_AUTO_TEST_CASE(a_file_that_is_not_json_names_the_file)
{
  const std::string path = "not_json_skeleton.json";
  std::ofstream(path) << "{\"joints\": [";
  Control s;
  try
  {
    gs::IO::read_control_skeleton_json(path, s);
    BOOST_ERROR("no exception");
  }
  catch(const std::runtime_error& e)
  {
    BOOST_CHECK(std::string(e.what()).rfind(path + ": not valid JSON", 0) == 0);
  }
  std::remove(path.c_str());
  BOOST_CHECK_THROW(gs::IO::read_control_skeleton_json("no_such_skeleton.json", s), std::runtime_error);
}

BOOST_AUTO_TEST_SUITE_END()
