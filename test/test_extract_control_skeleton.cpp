// Specification of CGAL/Geodesic_skeleton/extract_control_skeleton.h: the whole chain on
// Debian's demo meshes and on shapes with handles.
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>

#include <Geodesic_skeleton_test/shapes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Control = gs::Control_skeleton<Point>;

namespace {

struct Extracted
{
  Control control;
  gs::Control_skeleton_report report;
};

template <typename FaceGraph>
Extracted extract(const FaceGraph& mesh)
{
  Extracted e;
  e.report = gs::extract_control_skeleton(mesh, e.control);
  return e;
}

// The fraction of joints strictly inside the mesh or within `tolerance` of its surface.
double fraction_of_joints_inside(const Mesh& mesh, const Control& c)
{
  CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(mesh);
  std::size_t inside = 0;
  for(const auto& j : c.joints)
    inside += side(j.point) != CGAL::ON_UNBOUNDED_SIDE;
  return double(inside) / double(c.joints.size());
}

std::size_t joints_of_kind(const Control& c, gs::Joint_kind kind)
{
  return std::size_t(std::count_if(c.joints.begin(), c.joints.end(), [&](const auto& j) { return j.kind == kind; }));
}

} // namespace

BOOST_AUTO_TEST_SUITE(extract_control_skeleton)

// A hand-made rig for these animals has about 15 to 40 bones (spine, neck, head, tail,
// three or four per leg, ears or horns); each must give one connected tree, with its
// joints inside the mesh, and limbs reached: an end joint per leg, head and tail at least.
BOOST_AUTO_TEST_CASE(demo_animals_give_one_tree_of_a_rig_s_size_inside_the_mesh)
{
  // The elephant's mesh has three handles (V - E + F = -4): three loops, each cut once.
  struct Expected { const char* mesh; std::size_t min_bones, max_bones, min_ends, cut_bones; };
  for(const Expected& x : {Expected{"cow.off", 15, 40, 6, 0}, Expected{"dino.off", 15, 40, 6, 0},
                           Expected{"triceratops.off", 15, 40, 6, 0}, Expected{"bull.off", 15, 40, 6, 0},
                           Expected{"camel.off", 15, 40, 6, 0}, Expected{"elephant.off", 15, 40, 6, 3}})
  {
    BOOST_TEST_CONTEXT(x.mesh)
    {
      const Mesh mesh = test::demo_mesh<Mesh>(x.mesh);
      const Extracted e = extract(mesh);
      BOOST_TEST(e.control.roots.size() == 1u);
      BOOST_TEST(e.control.bones.size() >= x.min_bones);
      BOOST_TEST(e.control.bones.size() <= x.max_bones);
      BOOST_TEST(joints_of_kind(e.control, gs::Joint_kind::end) >= x.min_ends);
      BOOST_TEST(e.control.cut_bones.size() == x.cut_bones);
      BOOST_TEST(fraction_of_joints_inside(mesh, e.control) == 1.0);
    }
  }
}

// In a limb thinner than a couple of voxels, smoothing can take a curve-skeleton point out
// of the mesh (up to 1.2 % of the diagonal in the elephant's trunk and the cow's legs); the
// chain moves such points back in before the split, so that every point of the curve
// skeleton and every joint (a curve point) is inside, at coarse and fine resolutions.
BOOST_AUTO_TEST_CASE(every_curve_skeleton_point_and_joint_is_inside_a_closed_mesh)
{
  using Skeleton = gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor>;
  std::size_t moved = 0;
  for(const char* name : {"cow.off", "elephant.off"})
  {
    const Mesh mesh = test::demo_mesh<Mesh>(name);
    CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(mesh);
    for(int resolution : {gs::default_voxel_resolution, 48, 96})
    {
      BOOST_TEST_CONTEXT(name << " at resolution " << resolution)
      {
        Control c;
        Skeleton curve;
        const gs::Control_skeleton_report r = gs::extract_control_skeleton(
            mesh, c,
            gs::parameters::combine(gs::parameters::resolution(resolution), gs::parameters::curve_skeleton_output(&curve)));
        for(std::size_t v = 0; v < num_vertices(curve); ++v)
          BOOST_TEST((side(curve[v].point) != CGAL::ON_UNBOUNDED_SIDE), "curve point " << v);
        BOOST_TEST(fraction_of_joints_inside(mesh, c) == 1.0);
        BOOST_TEST(r.joints_moved_inside <= r.curve_points_moved_inside);
        moved += r.curve_points_moved_inside;
      }
    }
  }
  BOOST_TEST(moved > 0u); // the points were outside before: the step is what puts them in
}

BOOST_AUTO_TEST_CASE(handles_are_kept_and_cut_once_each)
{
  const Mesh torus = test::mesh_of<Mesh>(test::torus(3, 1, 64, 24));
  const Extracted t = extract(torus);
  BOOST_TEST(t.report.pruned.cycles == 1u);
  BOOST_TEST(t.control.cut_bones.size() == 1u);
  BOOST_TEST(t.control.roots.size() == 1u);
  for(const char* name : {"eight.off", "double-torus-example.off"})
  {
    const Extracted e = extract(test::demo_mesh<Mesh>(name));
    BOOST_TEST(e.report.thinned.cycles == 2u, name);
    BOOST_TEST(e.report.pruned.cycles == 2u, name);
    BOOST_TEST(e.control.cut_bones.size() == 2u, name);
  }
}

BOOST_AUTO_TEST_CASE(parts_that_nearly_touch_leave_no_loop)
{
  // Legs, hands and thighs, fingers within a voxel of each other: the conservative solid
  // bridges them, thinning makes loops, and cut_spurious_cycles() opens every one of them
  // (these meshes have genus 0), so no bone has to be cut to make the tree.
  for(const char* name : {"camel.off", "man.off", "homer.off", "bear.off", "hand.off"})
  {
    const Extracted e = extract(test::demo_mesh<Mesh>(name));
    BOOST_TEST(e.report.thinned.cycles > 0u, name);
    BOOST_TEST(e.report.spurious_cycles_cut == e.report.thinned.cycles, name);
    BOOST_TEST(e.report.pruned.cycles == 0u, name);
    BOOST_TEST(e.control.cut_bones.empty(), name);
    BOOST_TEST(e.control.roots.size() == 1u, name);
  }
}

BOOST_AUTO_TEST_CASE(peeling_the_surface_voxels_removes_the_false_loops_of_parts_that_nearly_touch)
{
  // The camel's legs and the man's hands and thighs come within a voxel of each other: the
  // conservative solid bridges them; peeling the surface voxels whose centre is outside
  // the mesh (keep_surface_voxels(false)) opens the bridges, and keeps the real handles.
  struct Expected { const char* mesh; std::size_t cycles; };
  for(const Expected& x : {Expected{"camel.off", 0}, Expected{"man.off", 0}, Expected{"homer.off", 0},
                           Expected{"eight.off", 2}, Expected{"double-torus-example.off", 2}})
  {
    Control c;
    const gs::Control_skeleton_report r = gs::extract_control_skeleton(
        test::demo_mesh<Mesh>(x.mesh), c, gs::parameters::keep_surface_voxels(false));
    BOOST_TEST(r.pruned.cycles == x.cycles, x.mesh);
    BOOST_TEST(c.cut_bones.size() == x.cycles, x.mesh);
    BOOST_TEST(c.roots.size() == 1u, x.mesh);
  }
}

BOOST_AUTO_TEST_CASE(two_separate_bodies_give_two_trees)
{
  test::Soup soup = test::cylinder(1, 8, 32, 40, true);
  test::append(soup, test::cylinder(1, 8, 32, 40, true), 6, 0, 0);
  Mesh two;
  test::soup_to_mesh(soup, two);
  const Extracted e = extract(two);
  BOOST_TEST(e.control.roots.size() == 2u);
  BOOST_TEST(e.report.pruned.components == 2u);
}

BOOST_AUTO_TEST_CASE(a_moved_mesh_gives_the_moved_control_skeleton)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  Mesh moved = cow;
  const double a = 0.9, b = 0.4;
  auto move = [&](const Point& p) {
    const double x = std::cos(a) * p.x() - std::sin(a) * p.y(), y = std::sin(a) * p.x() + std::cos(a) * p.y();
    const double y2 = std::cos(b) * y - std::sin(b) * p.z(), z2 = std::sin(b) * y + std::cos(b) * p.z();
    return Point(x - 3.5, y2 + 12, z2 + 0.25);
  };
  for(auto v : vertices(moved))
    moved.point(v) = move(moved.point(v));
  const Extracted before = extract(cow), after = extract(moved);
  BOOST_TEST(after.control.bones.size() == before.control.bones.size());
  BOOST_REQUIRE(after.control.joints.size() == before.control.joints.size());
  // Each moved joint is within a voxel of a joint of the moved original.
  double worst = 0;
  for(const auto& j : before.control.joints)
  {
    const Point target = move(j.point);
    double nearest = 1e300;
    for(const auto& k : after.control.joints)
      nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(target, k.point)));
    worst = std::max(worst, nearest);
  }
  BOOST_TEST(worst <= before.report.voxel_size);
}

BOOST_AUTO_TEST_CASE(a_polyhedron_gives_the_same_skeleton_as_a_surface_mesh)
{
  CGAL::Polyhedron_3<Kernel> cow_polyhedron;
  test::read_demo_mesh("cow.off", cow_polyhedron);
  const Extracted p = extract(cow_polyhedron), s = extract(test::demo_mesh<Mesh>("cow.off"));
  BOOST_TEST(p.control.joints.size() == s.control.joints.size());
  BOOST_TEST(p.control.bones.size() == s.control.bones.size());
}

BOOST_AUTO_TEST_CASE(the_report_and_the_visitor_see_every_stage)
{
  struct Counting_visitor
  {
    std::vector<std::string>* stages;
    void stage_finished(const std::string& stage, double ms)
    {
      BOOST_TEST(ms >= 0);
      stages->push_back(stage);
    }
  };
  std::vector<std::string> stages;
  gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor> curve;
  gs::Reeb_graph<Mesh> reeb;
  Control c;
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  const gs::Control_skeleton_report r = gs::extract_control_skeleton(
      cow, c,
      gs::parameters::combine(CGAL::parameters::visitor(Counting_visitor{&stages}),
                              gs::parameters::curve_skeleton_output(&curve),
                              gs::parameters::reeb_graph_output(&reeb)));
  BOOST_TEST(stages.size() == r.timings_ms.size());
  BOOST_TEST(stages.back() == "reeb_graph");
  BOOST_TEST(num_vertices(curve) == r.pruned.points);
  BOOST_TEST(num_vertices(reeb) == r.reeb_nodes);
  BOOST_TEST(r.pruned.points <= r.thinned.points);
  // Every mesh vertex is mapped to exactly one curve-skeleton vertex.
  std::size_t mapped = 0;
  for(std::size_t v = 0; v < num_vertices(curve); ++v)
    mapped += curve[v].vertices.size();
  BOOST_TEST(mapped == num_vertices(cow));
}

BOOST_AUTO_TEST_CASE(a_null_output_pointer_asks_for_nothing)
{
  // The same call with null output pointers makes no Reeb graph and no thinned graph, and
  // the same control skeleton; with real pointers it makes both.
  using Skeleton = gs::Curve_skeleton<Point, boost::graph_traits<Mesh>::vertex_descriptor>;
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  Control with_outputs, without_outputs;
  Skeleton thinned;
  gs::Reeb_graph<Mesh> reeb;
  const gs::Control_skeleton_report asked = gs::extract_control_skeleton(
      cow, with_outputs,
      gs::parameters::combine(gs::parameters::thinned_skeleton_output(&thinned),
                              gs::parameters::reeb_graph_output(&reeb)));
  const gs::Control_skeleton_report not_asked = gs::extract_control_skeleton(
      cow, without_outputs,
      gs::parameters::combine(gs::parameters::thinned_skeleton_output(static_cast<Skeleton*>(nullptr)),
                              gs::parameters::reeb_graph_output(static_cast<gs::Reeb_graph<Mesh>*>(nullptr)),
                              gs::parameters::curve_skeleton_output(static_cast<Skeleton*>(nullptr))));
  auto timed_reeb_graph = [](const gs::Control_skeleton_report& r) {
    return std::any_of(r.timings_ms.begin(), r.timings_ms.end(), [](const auto& t) { return t.first == "reeb_graph"; });
  };
  BOOST_TEST(timed_reeb_graph(asked));
  BOOST_TEST(asked.reeb_nodes > 0u);
  BOOST_TEST(num_vertices(thinned) == asked.thinned.points);
  BOOST_TEST(!timed_reeb_graph(not_asked));
  BOOST_TEST(not_asked.reeb_nodes == 0u);
  BOOST_TEST(not_asked.thinned.points == asked.thinned.points);
  BOOST_TEST(without_outputs.joints.size() == with_outputs.joints.size());
  for(std::size_t j = 0; j < with_outputs.joints.size(); ++j)
    BOOST_TEST(without_outputs.joints[j].point == with_outputs.joints[j].point);
}

BOOST_AUTO_TEST_SUITE_END()
