// Specification of CGAL/Geodesic_skeleton/reeb_graph.h and of the two mapping functions
// (geodesic_mapping_function.h, integral_geodesic_mapping_function.h).
#include <CGAL/Geodesic_skeleton/geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/integral_geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/reeb_graph.h>

#include <Geodesic_skeleton_test/shapes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>

#include <boost/graph/connected_components.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

BOOST_AUTO_TEST_SUITE(reeb_graph)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Reeb = gs::Reeb_graph<Mesh>;

namespace {

struct Graph_shape
{
  std::size_t nodes = 0, arcs = 0, components = 0, ends = 0, max_degree = 0;
  std::size_t cycles() const { return arcs + components - nodes; } // first Betti number
};

template <typename Graph>
Graph_shape shape_of(const Graph& g)
{
  Graph_shape s;
  s.nodes = num_vertices(g);
  s.arcs = num_edges(g);
  std::vector<std::size_t> component(num_vertices(g));
  s.components = s.nodes == 0 ? 0 : boost::connected_components(g, component.data());
  for(auto v : boost::make_iterator_range(vertices(g)))
  {
    s.ends += degree(v, g) == 1;
    s.max_degree = std::max<std::size_t>(s.max_degree, degree(v, g));
  }
  return s;
}

// The Reeb graph of `mesh` under the field `value(point)`.
template <typename Field>
Reeb reeb_of_coordinate_field(const Mesh& mesh, Field value, std::size_t intervals)
{
  std::vector<double> field;
  for(vertex_descriptor v : vertices(mesh))
    field.push_back(value(mesh.point(v)));
  Reeb reeb;
  gs::reeb_graph(mesh, boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, mesh)),
                 intervals, reeb);
  return reeb;
}

std::vector<double> geodesic_field(const Mesh& mesh)
{
  std::vector<double> field(num_vertices(mesh));
  gs::geodesic_mapping_function(mesh, boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, mesh)));
  return field;
}

Reeb reeb_of(const Mesh& mesh, std::vector<double>& field, std::size_t intervals)
{
  Reeb reeb;
  gs::reeb_graph(mesh, boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, mesh)),
                 intervals, reeb);
  return reeb;
}

Mesh rotated_and_moved(const Mesh& mesh)
{
  Mesh moved = mesh;
  const double a = 0.7, b = -1.1; // rotation about z by a, then about x by b
  for(vertex_descriptor v : vertices(moved))
  {
    const Point p = moved.point(v);
    const double x = std::cos(a) * p.x() - std::sin(a) * p.y(), y = std::sin(a) * p.x() + std::cos(a) * p.y();
    const double y2 = std::cos(b) * y - std::sin(b) * p.z(), z2 = std::sin(b) * y + std::cos(b) * p.z();
    moved.point(v) = Point(x + 10, y2 - 4, z2 + 2.5);
  }
  return moved;
}

} // namespace

BOOST_AUTO_TEST_CASE(a_torus_with_a_height_function_gives_one_cycle)
{
  // The torus stands on its rim: the height x cuts it into two arcs between its ends.
  const Mesh torus = test::mesh_of<Mesh>(test::torus(3, 1, 64, 24));
  const Graph_shape s = shape_of(reeb_of_coordinate_field(torus, [](const Point& p) { return p.x(); }, 16));
  BOOST_TEST(s.components == 1u);
  BOOST_TEST(s.cycles() == 1u);
}

BOOST_AUTO_TEST_CASE(a_capsule_gives_a_path)
{
  const Mesh capsule = test::mesh_of<Mesh>(test::cylinder(1, 8, 32, 60, true));
  const Reeb reeb = reeb_of_coordinate_field(capsule, [](const Point& p) { return p.z(); }, 12);
  const Graph_shape s = shape_of(reeb);
  BOOST_TEST(s.nodes == 12u);
  BOOST_TEST(s.components == 1u);
  BOOST_TEST(s.cycles() == 0u);
  BOOST_TEST(s.ends == 2u);
  BOOST_TEST(s.max_degree == 2u);
  // The nodes are centred on the axis and cover the mesh exactly once.
  std::size_t covered = 0;
  for(auto node : boost::make_iterator_range(vertices(reeb)))
  {
    BOOST_TEST(std::hypot(reeb[node].point.x(), reeb[node].point.y()) < 1e-6);
    BOOST_TEST(reeb[node].level_min <= reeb[node].level_max);
    covered += reeb[node].vertices.size();
  }
  BOOST_TEST(covered == num_vertices(capsule));
}

BOOST_AUTO_TEST_CASE(a_two_component_mesh_gives_two_components)
{
  test::Soup two = test::icosphere(1, 3);
  test::append(two, test::icosphere(0.5, 3), 4, 0, 0);
  const Mesh spheres = test::mesh_of<Mesh>(two);
  std::vector<double> field = geodesic_field(spheres);
  for(double value : field)
    BOOST_TEST(std::isfinite(value));
  const Graph_shape s = shape_of(reeb_of(spheres, field, 10));
  BOOST_TEST(s.components == 2u);
  BOOST_TEST(s.cycles() == 0u);
}

BOOST_AUTO_TEST_CASE(the_geodesic_reeb_graph_of_a_moved_mesh_is_the_same_graph)
{
  Mesh cow;
  test::read_demo_mesh("cow.off", cow);
  const Mesh moved = rotated_and_moved(cow);
  std::vector<double> field = geodesic_field(cow), moved_field = geodesic_field(moved);
  const Reeb reeb = reeb_of(cow, field, 30), moved_reeb = reeb_of(moved, moved_field, 30);

  BOOST_REQUIRE_EQUAL(num_vertices(reeb), num_vertices(moved_reeb));
  BOOST_REQUIRE_EQUAL(num_edges(reeb), num_edges(moved_reeb));
  // Same vertex sets per node, same arcs.
  for(std::size_t node = 0; node < num_vertices(reeb); ++node)
    BOOST_TEST(reeb[node].vertices == moved_reeb[node].vertices);
  std::set<std::pair<std::size_t, std::size_t>> arcs, moved_arcs;
  for(auto e : boost::make_iterator_range(edges(reeb)))
    arcs.insert(std::minmax<std::size_t>(source(e, reeb), target(e, reeb)));
  for(auto e : boost::make_iterator_range(edges(moved_reeb)))
    moved_arcs.insert(std::minmax<std::size_t>(source(e, moved_reeb), target(e, moved_reeb)));
  BOOST_TEST((arcs == moved_arcs));
}

BOOST_AUTO_TEST_CASE(a_reeb_graph_has_as_many_cycles_as_the_surface_has_handles)
{
  // Level sets are followed through the faces, so thin bands of values make no false
  // loops: a genus-0 animal gives a tree, the genus-2 demo shapes two cycles, and the
  // elephant of the demo data, whose Euler characteristic V - E + F is -4, three.
  struct Expected { const char* mesh; std::size_t cycles; };
  for(const Expected& x : {Expected{"cow.off", 0}, Expected{"camel.off", 0}, Expected{"dino.off", 0},
                           Expected{"man.off", 0}, Expected{"eight.off", 2},
                           Expected{"double-torus-example.off", 2}})
  {
    Mesh mesh;
    test::read_demo_mesh(x.mesh, mesh);
    std::vector<double> field = geodesic_field(mesh);
    for(std::size_t intervals : {10, 30, 100})
      BOOST_TEST(shape_of(reeb_of(mesh, field, intervals)).cycles() == x.cycles,
                 x.mesh << " with " << intervals << " intervals");
  }
  Mesh elephant;
  test::read_demo_mesh("elephant.off", elephant);
  BOOST_TEST(long(num_vertices(elephant)) - long(num_edges(elephant)) + long(num_faces(elephant)) == -4);
  std::vector<double> integral(num_vertices(elephant));
  gs::integral_geodesic_mapping_function(
      elephant, boost::make_iterator_property_map(integral.begin(), get(CGAL::vertex_index, elephant)));
  BOOST_TEST(shape_of(reeb_of(elephant, integral, 30)).cycles() <= 3u);
}

BOOST_AUTO_TEST_CASE(the_geodesic_field_starts_at_an_extremity)
{
  // On a capsule the farthest-point search finds a cap: the field runs along the axis.
  const Mesh capsule = test::mesh_of<Mesh>(test::cylinder(1, 8, 32, 60, true));
  const std::vector<double> field = geodesic_field(capsule);
  const auto lowest = std::min_element(field.begin(), field.end()) - field.begin();
  BOOST_TEST(*std::min_element(field.begin(), field.end()) == 0.0);
  const double z = capsule.point(vertex_descriptor(static_cast<std::uint32_t>(lowest))).z();
  BOOST_TEST((z < 0.01 || z > 7.99));
  BOOST_TEST(*std::max_element(field.begin(), field.end()) > 8.0);
}

BOOST_AUTO_TEST_CASE(given_sources_must_reach_every_component)
{
  test::Soup two = test::icosphere(1, 1);
  test::append(two, test::icosphere(1, 1), 4, 0, 0);
  const Mesh spheres = test::mesh_of<Mesh>(two);
  std::vector<double> field(num_vertices(spheres));
  const std::vector<vertex_descriptor> one_source = {vertex_descriptor(0)};
  BOOST_CHECK_THROW(gs::geodesic_mapping_function(
                        spheres, boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, spheres)),
                        gs::parameters::source_vertices(one_source)),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(the_integral_field_is_low_in_the_middle_and_high_at_the_tips)
{
  const Mesh capsule = test::mesh_of<Mesh>(test::cylinder(1, 8, 32, 60, true));
  std::vector<double> field(num_vertices(capsule));
  gs::integral_geodesic_mapping_function(
      capsule, boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, capsule)),
      gs::parameters::number_of_base_vertices(std::size_t(30)));
  vertex_descriptor highest = *vertices(capsule).begin();
  for(vertex_descriptor v : vertices(capsule))
  {
    const double value = field[v];
    BOOST_TEST((value >= 0.0 && value <= 1.0));
    const double from_middle = std::abs(capsule.point(v).z() - 4.0);
    if(from_middle < 0.5)
      BOOST_TEST(value < 0.2);
    if(from_middle > 3.9) // the caps, rims included
      BOOST_TEST(value > 0.7);
    if(value > field[highest])
      highest = v;
  }
  BOOST_TEST(std::abs(capsule.point(highest).z() - 4.0) > 3.99); // the maximum is on a cap
}

BOOST_AUTO_TEST_CASE(the_integral_field_does_not_change_under_a_rigid_motion)
{
  Mesh cow;
  test::read_demo_mesh("cow.off", cow);
  const Mesh moved = rotated_and_moved(cow);
  std::vector<double> field(num_vertices(cow)), moved_field(num_vertices(cow));
  gs::integral_geodesic_mapping_function(cow, boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, cow)));
  gs::integral_geodesic_mapping_function(moved, boost::make_iterator_property_map(moved_field.begin(), get(CGAL::vertex_index, moved)));
  for(std::size_t i = 0; i < field.size(); ++i)
    BOOST_TEST(moved_field[i] == field[i], boost::test_tools::tolerance(1e-6));
}

BOOST_AUTO_TEST_CASE(surface_mesh_and_polyhedron_give_the_same_graph)
{
  Mesh cow;
  Polyhedron cow_polyhedron;
  test::read_demo_mesh("cow.off", cow);
  test::read_demo_mesh("cow.off", cow_polyhedron);
  std::vector<double> field = geodesic_field(cow);
  std::vector<double> polyhedron_field(num_vertices(cow_polyhedron));
  const auto vim = CGAL::get_initialized_vertex_index_map(cow_polyhedron);
  gs::geodesic_mapping_function(cow_polyhedron, boost::make_iterator_property_map(polyhedron_field.begin(), vim));
  gs::Reeb_graph<Polyhedron> polyhedron_reeb;
  gs::reeb_graph(cow_polyhedron, boost::make_iterator_property_map(polyhedron_field.begin(), vim), 30,
                 polyhedron_reeb);
  const Graph_shape a = shape_of(reeb_of(cow, field, 30)), b = shape_of(polyhedron_reeb);
  BOOST_TEST(a.nodes == b.nodes);
  BOOST_TEST(a.arcs == b.arcs);
  BOOST_TEST(a.ends == b.ends);
}

BOOST_AUTO_TEST_CASE(bad_input_gives_clear_exceptions)
{
  Reeb reeb;
  const Mesh empty;
  std::vector<double> none;
  BOOST_CHECK_THROW(gs::reeb_graph(empty, boost::make_iterator_property_map(none.begin(), get(CGAL::vertex_index, empty)),
                                   10, reeb),
                    std::invalid_argument);

  const Mesh box = test::mesh_of<Mesh>(test::box(0, 0, 0, 1, 1, 1));
  std::vector<double> field(num_vertices(box), 1.0);
  auto field_map = boost::make_iterator_property_map(field.begin(), get(CGAL::vertex_index, box));
  BOOST_CHECK_THROW(gs::reeb_graph(box, field_map, 0, reeb), std::invalid_argument);
  BOOST_CHECK_NO_THROW(gs::reeb_graph(box, field_map, 5, reeb)); // a constant field: one node
  BOOST_TEST(num_vertices(reeb) == 1u);
  field[3] = std::numeric_limits<double>::infinity();
  BOOST_CHECK_THROW(gs::reeb_graph(box, field_map, 5, reeb), std::invalid_argument);
  field[3] = std::nan("");
  BOOST_CHECK_THROW(gs::reeb_graph(box, field_map, 5, reeb), std::invalid_argument);
  BOOST_CHECK_THROW(gs::integral_geodesic_mapping_function(box, field_map, gs::parameters::number_of_base_vertices(std::size_t(0))),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
