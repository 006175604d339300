// Specification of the writers in CGAL/Geodesic_skeleton/IO/: BVH, OBJ, polylines, JSON.
// The BVH is read back by a small parser written here, from the format's definition.
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/IO/bvh.h>
#include <CGAL/Geodesic_skeleton/IO/json.h>
#include <CGAL/Geodesic_skeleton/IO/obj.h>
#include <CGAL/Geodesic_skeleton/IO/polylines.h>
#include <CGAL/Geodesic_skeleton/split_into_bones.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <Geodesic_skeleton_test/joints.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(io)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Skeleton = gs::Curve_skeleton<Point, int>;
using Control = gs::Control_skeleton<Point>;

namespace {

// A body with two arms, one bent, and a loop (a handle): a tree with a cut bone.
Control sample_control_skeleton()
{
  Skeleton s;
  auto chain = [&](Point from, Point to, int steps, long attach) {
    std::size_t previous = attach >= 0 ? std::size_t(attach) : std::size_t(-1);
    std::size_t last = 0;
    for(int i = 0; i <= steps; ++i)
    {
      const std::size_t v = add_vertex(s);
      s[v].point = from + (to - from) * (double(i) / steps);
      s[v].radius = 1.0;
      if(previous != std::size_t(-1))
        add_edge(previous, v, s);
      previous = last = v;
    }
    return last;
  };
  const std::size_t hip = chain(Point(0, 0, 0), Point(0, 0, 20), 40, -1);
  const std::size_t elbow = chain(Point(0.5, 0, 20), Point(15, 0, 20), 30, long(hip));
  chain(Point(15, 0.5, 20), Point(15, 15, 20), 30, long(elbow));
  chain(Point(-0.5, 0, 20), Point(-15, 0, 20), 30, long(hip));
  // A loop hanging from the spine's base.
  const std::size_t base = 0;
  std::size_t previous = base;
  for(int i = 1; i < 40; ++i)
  {
    const double a = 2 * 3.14159265358979 * i / 40;
    const std::size_t v = add_vertex(s);
    s[v].point = Point(6 * std::sin(a), 0, -6 + 6 * std::cos(a));
    s[v].radius = 1.0;
    add_edge(previous, v, s);
    previous = v;
  }
  add_edge(previous, base, s);
  Control c;
  gs::split_into_bones(s, c);
  return c;
}

struct Bvh_joint
{
  std::string name;
  int parent = -1;
  double offset[3] = {0, 0, 0};
  int channels = 0;
  bool has_end_site = false;
};

// Parses the HIERARCHY of a BVH file and the number of values of its first frame.
struct Bvh_file
{
  std::vector<Bvh_joint> joints;
  std::size_t frame_values = 0;
  int frames = 0;

  explicit Bvh_file(std::istream& is)
  {
    std::string word;
    is >> word;
    BOOST_REQUIRE_EQUAL(word, "HIERARCHY");
    std::vector<int> stack; // open joints; -2 marks an End Site block
    while(is >> word && word != "MOTION")
    {
      if(word == "ROOT" || word == "JOINT")
      {
        Bvh_joint j;
        is >> j.name;
        j.parent = stack.empty() ? -1 : stack.back();
        joints.push_back(j);
      }
      else if(word == "End")
      {
        is >> word; // Site
        joints.at(std::size_t(stack.back())).has_end_site = true;
        stack.push_back(-2);
        is >> word; // {
        BOOST_REQUIRE_EQUAL(word, "{");
      }
      else if(word == "{")
        stack.push_back(int(joints.size()) - 1);
      else if(word == "}")
        stack.pop_back();
      else if(word == "OFFSET")
      {
        double o[3];
        is >> o[0] >> o[1] >> o[2];
        if(stack.back() >= 0)
          for(int c = 0; c < 3; ++c)
            joints[std::size_t(stack.back())].offset[c] = o[c];
      }
      else if(word == "CHANNELS")
      {
        is >> joints[std::size_t(stack.back())].channels;
        for(int c = 0; c < joints[std::size_t(stack.back())].channels; ++c)
          is >> word;
      }
    }
    BOOST_REQUIRE(stack.empty());
    is >> word >> frames; // Frames: N
    is >> word >> word >> word; // Frame Time: t
    std::string line;
    std::getline(is, line);
    std::getline(is, line);
    std::istringstream values(line);
    double v;
    while(values >> v)
      ++frame_values;
  }
};

} // namespace

BOOST_AUTO_TEST_CASE(a_bvh_read_back_has_the_same_hierarchy_and_offsets)
{
  const Control c = sample_control_skeleton();
  BOOST_REQUIRE(num_vertices(c) >= 5u);
  BOOST_REQUIRE_EQUAL(c[boost::graph_bundle].cut_bones.size(), 1u);
  std::stringstream file;
  gs::IO::write_BVH(file, c);
  const Bvh_file bvh(file);

  // Written depth first from the root: map BVH joints back by name (<kind>_<index>).
  BOOST_REQUIRE_EQUAL(bvh.joints.size(), num_vertices(c));
  std::vector<int> index_of(bvh.joints.size());
  for(std::size_t b = 0; b < bvh.joints.size(); ++b)
  {
    const std::string& name = bvh.joints[b].name;
    index_of[b] = std::stoi(name.substr(name.rfind('_') + 1));
    BOOST_TEST(name.substr(0, name.rfind('_')) == gs::to_string(c[std::size_t(index_of[b])].kind));
  }
  for(std::size_t b = 0; b < bvh.joints.size(); ++b)
  {
    const auto& joint = c[std::size_t(index_of[b])];
    const long parent = test::parent_index(c, std::size_t(index_of[b]));
    const Bvh_joint& read = bvh.joints[b];
    BOOST_TEST((read.parent < 0 ? parent == -1 : parent == index_of[std::size_t(read.parent)]));
    const Point origin = parent < 0 ? Point(0, 0, 0) : c[std::size_t(parent)].point;
    BOOST_TEST(read.offset[0] == joint.point.x() - origin.x(), boost::test_tools::tolerance(1e-6));
    BOOST_TEST(read.offset[1] == joint.point.y() - origin.y(), boost::test_tools::tolerance(1e-6));
    BOOST_TEST(read.offset[2] == joint.point.z() - origin.z(), boost::test_tools::tolerance(1e-6));
    BOOST_TEST(read.channels == (parent < 0 ? 6 : 3));
    // Leaves end with an End Site: the limb tips, and a joint where a cycle was cut.
    const bool leaf = out_degree(std::size_t(index_of[b]), c) == 0;
    BOOST_TEST(read.has_end_site == leaf);
    if(joint.kind == gs::Joint_kind::end)
      BOOST_TEST(leaf);
  }
  BOOST_TEST(bvh.frames == 1);
  BOOST_TEST(bvh.frame_values == 6 + 3 * (num_vertices(c) - 1));
}

BOOST_AUTO_TEST_CASE(obj_has_a_vertex_per_joint_and_a_line_per_bone)
{
  const Control c = sample_control_skeleton();
  std::stringstream file;
  gs::IO::write_OBJ(file, c);
  std::size_t v = 0, l = 0;
  std::string line;
  while(std::getline(file, line))
  {
    v += line.rfind("v ", 0) == 0;
    l += line.rfind("l ", 0) == 0;
  }
  BOOST_TEST(v == num_vertices(c));
  BOOST_TEST(l == num_edges(c) + c[boost::graph_bundle].cut_bones.size());
}

BOOST_AUTO_TEST_CASE(polylines_hold_every_bone_point)
{
  const Control c = sample_control_skeleton();
  std::stringstream file;
  gs::IO::write_polylines(file, c);
  std::string line;
  std::size_t polylines = 0;
  while(std::getline(file, line))
  {
    std::istringstream in(line);
    std::size_t n;
    in >> n;
    const gs::Control_bone<Point>& bone = polylines < num_edges(c)
                                              ? c[gs::numbered_bones(c)[polylines]]
                                              : c[boost::graph_bundle].cut_bones[polylines - num_edges(c)];
    BOOST_TEST(n == bone.points.size());
    double x, y, z;
    std::size_t read = 0;
    while(in >> x >> y >> z)
      ++read;
    BOOST_TEST(read == n);
    ++polylines;
  }
  BOOST_TEST(polylines == num_edges(c) + c[boost::graph_bundle].cut_bones.size());
}

// A curve skeleton's polylines: one per branch between end points and junctions, the
// junction in each of its branches, a closed loop ending on its first point.
BOOST_AUTO_TEST_CASE(curve_skeleton_polylines_are_its_branches)
{
  Skeleton s;
  auto add = [&](double x, double y, double z) {
    const auto v = add_vertex(s);
    s[v].point = Point(x, y, z);
    return v;
  };
  // A Y: the junction at the origin, arms of 2, 2 and 3 points beyond it.
  const auto junction = add(0, 0, 0);
  const std::vector<std::vector<std::array<double, 3>>> arms{
      {{1, 0, 0}, {2, 0, 0}}, {{0, 1, 0}, {0, 2, 0}}, {{0, 0, -1}, {0, 0, -2}, {0, 0, -3}}};
  for(const auto& arm : arms)
  {
    auto previous = junction;
    for(const auto& p : arm)
    {
      const auto v = add(p[0], p[1], p[2]);
      add_edge(previous, v, s);
      previous = v;
    }
  }
  // A separate loop of 4 points.
  const auto a = add(10, 0, 0), b = add(11, 0, 0), c = add(11, 1, 0), d = add(10, 1, 0);
  add_edge(a, b, s);
  add_edge(b, c, s);
  add_edge(c, d, s);
  add_edge(d, a, s);
  std::stringstream file;
  gs::IO::write_curve_skeleton_polylines(file, s);
  std::vector<std::size_t> sizes;
  std::size_t closed = 0;
  for(std::string line; std::getline(file, line);)
  {
    std::istringstream in(line);
    std::size_t n = 0;
    in >> n;
    std::vector<std::array<double, 3>> points;
    for(std::array<double, 3> p; in >> p[0] >> p[1] >> p[2];)
      points.push_back(p);
    BOOST_TEST(points.size() == n);
    if(points.size() >= 2 && points.front() == points.back())
      ++closed;
    sizes.push_back(n);
  }
  std::sort(sizes.begin(), sizes.end());
  BOOST_TEST(sizes == (std::vector<std::size_t>{3, 3, 4, 5}), boost::test_tools::per_element());
  BOOST_TEST(closed == 1u);
}

BOOST_AUTO_TEST_CASE(json_lists_joints_with_parents_and_kinds)
{
  const Control c = sample_control_skeleton();
  const nlohmann::json j = nlohmann::json::parse(gs::IO::control_skeleton_to_json(c).dump());
  BOOST_REQUIRE_EQUAL(j.at("joints").size(), num_vertices(c));
  for(std::size_t i = 0; i < num_vertices(c); ++i)
  {
    BOOST_TEST(j["joints"][i]["parent"].get<long>() == test::parent_index(c, i));
    BOOST_TEST(j["joints"][i]["kind"].get<std::string>() == gs::to_string(c[i].kind));
    BOOST_TEST(j["joints"][i]["position"][2].get<double>() == c[i].point.z());
  }
  BOOST_TEST(j.at("bones").size() == num_edges(c));
  BOOST_TEST(j.at("cut_bones").size() == 1u);
  for(const auto& bone : j["bones"])
    BOOST_TEST(test::parent_index(c, bone[1].get<std::size_t>()) == bone[0].get<long>());
}

BOOST_AUTO_TEST_CASE(an_empty_skeleton_cannot_be_written_as_bvh)
{
  std::stringstream file;
  BOOST_CHECK_THROW(gs::IO::write_BVH(file, Control()), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
