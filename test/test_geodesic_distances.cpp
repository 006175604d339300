// Specification of CGAL/Geodesic_skeleton/geodesic_distances.h.
#include <CGAL/Geodesic_skeleton/geodesic_distances.h>

#include <Geodesic_skeleton_test/shapes.h>

#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Random.h>
#include <CGAL/property_map.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/aff_transformation_tags.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

BOOST_AUTO_TEST_SUITE(geodesic_distances)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;

namespace {

template <typename Graph, typename Sources>
std::vector<double> distances_from(const Graph& g, const Sources& sources)
{
  const auto vim = CGAL::get_initialized_vertex_index_map(g);
  std::vector<double> d(num_vertices(g));
  gs::geodesic_distances(g, sources, boost::make_iterator_property_map(d.begin(), vim));
  return d;
}

struct Relative_errors
{
  double mean = 0, max = 0, min = std::numeric_limits<double>::infinity();
};

// Relative error of `computed` against `exact`, over the vertices whose exact distance is
// at least `min_exact` (near the source both are tiny and the ratio says nothing).
Relative_errors relative_errors(const std::vector<double>& computed, const std::vector<double>& exact,
                                double min_exact)
{
  Relative_errors e;
  std::size_t n = 0;
  for(std::size_t i = 0; i < computed.size(); ++i)
  {
    if(exact[i] < min_exact)
      continue;
    const double r = (computed[i] - exact[i]) / exact[i];
    e.mean += std::abs(r);
    e.max = std::max(e.max, r);
    e.min = std::min(e.min, r);
    ++n;
  }
  e.mean /= static_cast<double>(n);
  return e;
}

} // namespace

// Shortest edge paths over-estimate the geodesic by a factor that depends on the direction
// relative to the triangulation. On an equilateral lattice the factor at angle phi from an
// edge direction (0 <= phi <= 30 degrees) is cos(phi) + sin(phi)/sqrt(3): at most
// 2/sqrt(3) = 1.155, 1.103 on average over directions. The icosphere is not a uniform lattice
// (its 12 five-valent vertices and the projection distort it), which raises the worst case.
// Chords inscribed in a curved surface under-estimate by less than 0.1% at these sizes.
// These are the tolerances of the Dijkstra baseline; a better field plugs into the same map.
BOOST_AUTO_TEST_CASE(sphere_distances_are_close_to_great_circle_arcs)
{
  const double radius = 2.0;
  const Mesh sphere = test::mesh_of<Mesh>(test::icosphere(radius, 5)); // 10242 vertices
  const vertex_descriptor source = *vertices(sphere).begin();
  const std::vector<double> d = distances_from(sphere, source);

  std::vector<double> exact;
  const Point s = sphere.point(source);
  for(vertex_descriptor v : vertices(sphere))
  {
    const Point p = sphere.point(v);
    const double cosine = std::clamp(CGAL::to_double((s - CGAL::ORIGIN) * (p - CGAL::ORIGIN)) /
                                         (radius * radius), -1.0, 1.0);
    exact.push_back(radius * std::acos(cosine));
  }
  const Relative_errors e = relative_errors(d, exact, 0.1 * radius);
  BOOST_TEST_MESSAGE("sphere: mean " << e.mean << " min " << e.min << " max " << e.max);
  BOOST_TEST(e.min > -0.001);
  BOOST_TEST(e.max < 0.25);
  BOOST_TEST(e.mean < 0.10);
}

BOOST_AUTO_TEST_CASE(open_cylinder_distances_are_close_to_unrolled_distances)
{
  const double radius = 1.0, height = 6.0;
  const int around = 96, along = 106; // ring spacing sqrt(3)/2 of 2 pi r / around: equilateral
  const Mesh tube = test::mesh_of<Mesh>(test::cylinder(radius, height, around, along, false));
  const vertex_descriptor source = *vertices(tube).begin(); // angle 0, z 0
  const std::vector<double> d = distances_from(tube, source);

  std::vector<double> exact;
  for(vertex_descriptor v : vertices(tube))
  {
    const Point p = tube.point(v);
    const double angle = std::abs(std::atan2(CGAL::to_double(p.y()), CGAL::to_double(p.x())));
    exact.push_back(std::hypot(radius * angle, CGAL::to_double(p.z())));
  }
  const Relative_errors e = relative_errors(d, exact, 0.5);
  BOOST_TEST_MESSAGE("cylinder: mean " << e.mean << " min " << e.min << " max " << e.max);
  BOOST_TEST(e.min > -0.001);
  BOOST_TEST(e.max < 0.157); // 2/sqrt(3) - 1, plus the chord effect
  BOOST_TEST(e.mean < 0.11); // 0.103 for directions spread evenly
}

BOOST_AUTO_TEST_CASE(distance_is_symmetric)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  CGAL::Random rng(7);
  for(int k = 0; k < 10; ++k)
  {
    const vertex_descriptor a(rng.get_int(0, int(num_vertices(cow))));
    const vertex_descriptor b(rng.get_int(0, int(num_vertices(cow))));
    const double ab = distances_from(cow, a)[b];
    const double ba = distances_from(cow, b)[a];
    BOOST_TEST(ab == ba, boost::test_tools::tolerance(1e-12));
  }
}

BOOST_AUTO_TEST_CASE(distance_satisfies_the_triangle_inequality)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  CGAL::Random rng(11);
  for(int k = 0; k < 10; ++k)
  {
    const vertex_descriptor a(rng.get_int(0, int(num_vertices(cow))));
    const std::vector<double> from_a = distances_from(cow, a);
    for(int j = 0; j < 20; ++j)
    {
      const vertex_descriptor b(rng.get_int(0, int(num_vertices(cow))));
      const std::vector<double> from_b = distances_from(cow, b);
      const vertex_descriptor c(rng.get_int(0, int(num_vertices(cow))));
      BOOST_TEST(from_a[c] <= from_a[b] + from_b[c] + 1e-12);
    }
  }
}

BOOST_AUTO_TEST_CASE(distances_are_invariant_under_a_rigid_motion)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  Mesh moved = cow;
  CGAL::Random rng(3);
  // A random rotation (from a random unit quaternion) followed by a translation.
  double q[4], n = 0;
  for(double& c : q)
  {
    c = rng.get_double(-1, 1);
    n += c * c;
  }
  for(double& c : q)
    c /= std::sqrt(n);
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const CGAL::Aff_transformation_3<Kernel> motion(
      1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y), 12.5,
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x), -3.25,
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y), 100.0);
  for(vertex_descriptor v : vertices(moved))
    moved.point(v) = motion.transform(moved.point(v));

  const vertex_descriptor source(17);
  const std::vector<double> before = distances_from(cow, source);
  const std::vector<double> after = distances_from(moved, source);
  for(std::size_t i = 0; i < before.size(); ++i)
    BOOST_TEST(after[i] == before[i], boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(multi_source_distance_is_the_minimum_of_single_source_distances)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  const std::vector<vertex_descriptor> sources = {vertex_descriptor(5), vertex_descriptor(900),
                                                  vertex_descriptor(2500)};
  const std::vector<double> multi = distances_from(cow, sources);
  std::vector<double> minimum(num_vertices(cow), std::numeric_limits<double>::infinity());
  for(vertex_descriptor s : sources)
  {
    const std::vector<double> single = distances_from(cow, s);
    for(std::size_t i = 0; i < single.size(); ++i)
      minimum[i] = std::min(minimum[i], single[i]);
  }
  for(std::size_t i = 0; i < multi.size(); ++i)
    BOOST_TEST(multi[i] == minimum[i], boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_vertex_in_another_component_is_at_infinity)
{
  test::Soup two = test::icosphere(1, 2);
  const std::size_t first_size = two.points.size();
  test::append(two, test::icosphere(1, 2), 5, 0, 0);
  const Mesh spheres = test::mesh_of<Mesh>(two);
  const std::vector<double> d = distances_from(spheres, vertex_descriptor(0));
  for(std::size_t i = 0; i < d.size(); ++i)
  {
    if(i < first_size)
      BOOST_TEST(std::isfinite(d[i]));
    else
      BOOST_TEST(std::isinf(d[i]));
  }
  // The farthest vertex is looked for among reachable vertices only.
  const auto farthest = gs::farthest_vertex(spheres, vertex_descriptor(0));
  BOOST_TEST(std::size_t(farthest.first) < first_size);
  BOOST_TEST(std::isfinite(farthest.second));
}

BOOST_AUTO_TEST_CASE(surface_mesh_and_polyhedron_give_the_same_distances)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  Polyhedron cow_polyhedron;
  test::read_demo_mesh("cow.off", cow_polyhedron);
  BOOST_REQUIRE_EQUAL(num_vertices(cow_polyhedron), num_vertices(cow));

  // Both read the file in order, so the i-th vertex is the same point in both.
  std::vector<boost::graph_traits<Polyhedron>::vertex_descriptor> polyhedron_vertices(
      vertices(cow_polyhedron).begin(), vertices(cow_polyhedron).end());
  const std::vector<double> from_mesh = distances_from(cow, vertex_descriptor(42));
  const std::vector<double> from_polyhedron = distances_from(cow_polyhedron, polyhedron_vertices[42]);
  for(std::size_t i = 0; i < from_mesh.size(); ++i)
    BOOST_TEST(from_polyhedron[i] == from_mesh[i], boost::test_tools::tolerance(1e-12));

  const auto farthest = gs::farthest_vertex(cow_polyhedron, polyhedron_vertices[42]);
  BOOST_TEST(farthest.second == *std::max_element(from_mesh.begin(), from_mesh.end()),
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(predecessors_trace_paths_as_long_as_the_distances)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  std::vector<double> d(num_vertices(cow));
  std::vector<vertex_descriptor> predecessor(num_vertices(cow));
  const vertex_descriptor source(100);
  gs::geodesic_distances(cow, source, boost::make_iterator_property_map(d.begin(), get(CGAL::vertex_index, cow)),
                         gs::parameters::vertex_predecessor_map(boost::make_iterator_property_map(
                             predecessor.begin(), get(CGAL::vertex_index, cow))));
  BOOST_TEST(predecessor[source] == source);
  for(vertex_descriptor v : vertices(cow))
  {
    if(v == source)
      continue;
    const vertex_descriptor p = predecessor[v];
    BOOST_TEST(d[v] == d[p] + std::sqrt(CGAL::squared_distance(cow.point(v), cow.point(p))),
               boost::test_tools::tolerance(1e-9));
  }
}

BOOST_AUTO_TEST_CASE(shortest_path_is_an_edge_path_of_the_geodesic_length)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  const vertex_descriptor source(10), target(2000);
  std::vector<vertex_descriptor> path;
  const double length = gs::shortest_path(cow, source, target, std::back_inserter(path));
  BOOST_REQUIRE(path.size() >= 2);
  BOOST_TEST(path.front() == source);
  BOOST_TEST(path.back() == target);
  double sum = 0;
  for(std::size_t i = 1; i < path.size(); ++i)
  {
    BOOST_TEST(halfedge(path[i - 1], path[i], cow).second); // consecutive vertices share an edge
    sum += std::sqrt(CGAL::squared_distance(cow.point(path[i - 1]), cow.point(path[i])));
  }
  BOOST_TEST(sum == length, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(length == distances_from(cow, source)[target], boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(shortest_path_to_another_component_is_empty_and_infinite)
{
  test::Soup two = test::icosphere(1, 1);
  const std::size_t first_size = two.points.size();
  test::append(two, test::icosphere(1, 1), 5, 0, 0);
  const Mesh spheres = test::mesh_of<Mesh>(two);
  std::vector<vertex_descriptor> path;
  const double length = gs::shortest_path(spheres, vertex_descriptor(0),
                                          vertex_descriptor(first_size + 3), std::back_inserter(path));
  BOOST_TEST(std::isinf(length));
  BOOST_TEST(path.empty());
}

BOOST_AUTO_TEST_CASE(farthest_vertex_has_the_largest_distance)
{
  const Mesh cow = test::demo_mesh<Mesh>("cow.off");
  const std::vector<vertex_descriptor> sources = {vertex_descriptor(1), vertex_descriptor(1500)};
  const std::vector<double> d = distances_from(cow, sources);
  const auto farthest = gs::farthest_vertex(cow, sources);
  BOOST_TEST(farthest.second == *std::max_element(d.begin(), d.end()));
  BOOST_TEST(d[farthest.first] == farthest.second);
}

BOOST_AUTO_TEST_CASE(a_custom_edge_weight_map_is_used)
{
  const Mesh box = test::mesh_of<Mesh>(test::box(0, 0, 0, 1, 1, 1));
  // Every edge weighs 1: distances become hop counts.
  const auto unit = CGAL::Constant_property_map<boost::graph_traits<Mesh>::edge_descriptor, double>(1.0);
  std::vector<double> d(num_vertices(box));
  gs::geodesic_distances(box, vertex_descriptor(0),
                         boost::make_iterator_property_map(d.begin(), get(CGAL::vertex_index, box)),
                         gs::parameters::edge_weight_map(unit));
  for(vertex_descriptor v : vertices(box))
  {
    const double hops = d[v];
    BOOST_TEST(hops == std::round(hops));
    BOOST_TEST(hops <= 2.0);
  }
}

BOOST_AUTO_TEST_CASE(bad_input_gives_clear_exceptions)
{
  auto distances_throw = [](const Mesh& m, auto sources, auto np) {
    std::vector<double> d(num_vertices(m) + 1);
    gs::geodesic_distances(m, sources, boost::make_iterator_property_map(d.begin(), get(CGAL::vertex_index, m)), np);
  };
  const auto no_parameters = CGAL::parameters::default_values();

  // An empty mesh.
  const Mesh empty;
  BOOST_CHECK_THROW(distances_throw(empty, vertex_descriptor(0), no_parameters), std::invalid_argument);

  // A source that is not in the mesh, or no source at all.
  const Mesh box = test::mesh_of<Mesh>(test::box(0, 0, 0, 1, 1, 1));
  BOOST_CHECK_THROW(distances_throw(box, vertex_descriptor(8), no_parameters), std::invalid_argument);
  BOOST_CHECK_THROW(distances_throw(box, Mesh::null_vertex(), no_parameters), std::invalid_argument);
  BOOST_CHECK_THROW(distances_throw(box, std::vector<vertex_descriptor>(), no_parameters), std::invalid_argument);
  std::vector<vertex_descriptor> path;
  BOOST_CHECK_THROW(gs::shortest_path(box, vertex_descriptor(0), vertex_descriptor(99), std::back_inserter(path)),
                    std::invalid_argument);

  // A negative edge weight.
  Mesh weighted = box;
  auto weights = weighted.add_property_map<Mesh::Edge_index, double>("e:weight", 1.0).first;
  weights[*edges(weighted).begin()] = -1.0;
  BOOST_CHECK_THROW(distances_throw(weighted, vertex_descriptor(0), gs::parameters::edge_weight_map(weights)),
                    std::invalid_argument);

  // NaN coordinates.
  Mesh with_nan = box;
  with_nan.point(vertex_descriptor(3)) = Point(std::nan(""), 0, 0);
  BOOST_CHECK_THROW(distances_throw(with_nan, vertex_descriptor(0), no_parameters), std::invalid_argument);

}

BOOST_AUTO_TEST_CASE(a_surface_mesh_with_removed_vertices_still_works)
{
  // Surface_mesh keeps removed elements until collect_garbage(); BGL's num_vertices counts
  // them, so indices stay in range and every live vertex gets its distance.
  Mesh with_garbage = test::mesh_of<Mesh>(test::icosphere(1, 2));
  CGAL::Euler::remove_center_vertex(halfedge(vertex_descriptor(0), with_garbage), with_garbage);
  BOOST_REQUIRE(with_garbage.has_garbage());
  const std::vector<double> d = distances_from(with_garbage, vertex_descriptor(1));
  for(vertex_descriptor v : vertices(with_garbage))
    BOOST_TEST(std::isfinite(d[v]));
}

BOOST_AUTO_TEST_SUITE_END()
