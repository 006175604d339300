// Specification of CGAL/Geodesic_skeleton/to_graph.h, and of the voxel medial axis as a
// whole (voxelize -> distance_transform -> thin -> to_graph) on synthetic and demo meshes.
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>

#include <Geodesic_skeleton_test/shapes.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <boost/mpl/list.hpp>
#include <boost/property_map/vector_property_map.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <stdexcept>

BOOST_AUTO_TEST_SUITE(to_graph)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polyhedron = CGAL::Polyhedron_3<Kernel>;
using Voxel_set_models = boost::mpl::list<gs::Dense_voxel_grid, gs::Sparse_voxel_set>;

Mesh mesh_of(const test::Soup& soup) { return test::mesh_of<Mesh>(soup); }

Mesh demo_mesh(const char* name) { return test::demo_mesh<Mesh>(name); }

template <typename Graph>
int count_degree(const Graph& g, std::size_t d)
{
  int n = 0;
  for(auto v : boost::make_iterator_range(vertices(g)))
    n += degree(v, g) == d;
  return n;
}

template <typename Graph>
int count_triangles(const Graph& g)
{
  int n = 0;
  for(auto e : boost::make_iterator_range(edges(g)))
  {
    const auto a = source(e, g), b = target(e, g);
    for(auto c : boost::make_iterator_range(boost::adjacent_vertices(a, g)))
      if(c != b && edge(b, c, g).second)
        ++n;
  }
  return n / 3;
}

// Every mesh vertex is in exactly one skeleton vertex's list.
template <typename Graph, typename FaceGraph>
bool maps_every_vertex_once(const Graph& g, const FaceGraph& mesh)
{
  std::map<typename boost::graph_traits<FaceGraph>::vertex_descriptor, int> seen;
  for(auto v : boost::make_iterator_range(vertices(g)))
    for(auto mv : g[v].vertices)
      ++seen[mv];
  if(seen.size() != std::size_t(num_vertices(mesh)))
    return false;
  for(const auto& s : seen)
    if(s.second != 1)
      return false;
  return true;
}


} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(a_cylinder_gives_one_path_along_its_axis, VoxelSet, Voxel_set_models)
{
  const double radius = 1., height = 8.;
  const Mesh cylinder = mesh_of(test::cylinder(radius, height, 48, 160, true));
  const test::Voxel_pipeline<Mesh, VoxelSet> p(cylinder, 64);
  const auto& g = p.graph;
  const double h = p.voxel_size();
  BOOST_TEST(test::graph_components(g) == 1);
  BOOST_TEST(test::graph_cycles(g) == 0);
  BOOST_TEST(count_degree(g, 1) == 2); // a path: two ends ...
  BOOST_TEST(count_degree(g, 2) == int(num_vertices(g)) - 2); // ... and no junction
  double low = height, high = 0;
  for(auto v : boost::make_iterator_range(vertices(g)))
  {
    const Point& q = g[v].point;
    BOOST_TEST(std::hypot(q.x(), q.y()) <= h, "off the axis by " << std::hypot(q.x(), q.y()) / h << " voxels");
    low = std::min(low, q.z());
    high = std::max(high, q.z());
  }
  BOOST_TEST(low <= radius + h);
  BOOST_TEST(high >= height - radius - h);
  BOOST_TEST(maps_every_vertex_once(g, cylinder));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_torus_gives_exactly_one_cycle, VoxelSet, Voxel_set_models)
{
  const test::Voxel_pipeline<Mesh, VoxelSet> p(mesh_of(test::torus(3., 1., 64, 24)), 64);
  BOOST_TEST(test::graph_components(p.graph) == 1);
  BOOST_TEST(test::graph_cycles(p.graph) == 1);
  BOOST_TEST(count_triangles(p.graph) == 0);
}

BOOST_AUTO_TEST_CASE(eight_and_the_double_torus_give_two_cycles)
{
  for(const char* name : {"eight.off", "double-torus-example.off"})
  {
    const Mesh mesh = demo_mesh(name);
    const test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(mesh, 64);
    BOOST_TEST(test::graph_components(p.graph) == 1, name);
    BOOST_TEST(test::graph_cycles(p.graph) == 2, name);
    BOOST_TEST(count_triangles(p.graph) == 0, name);
  }
}

BOOST_AUTO_TEST_CASE(two_disjoint_spheres_give_two_components)
{
  test::Soup soup = test::icosphere(1., 3);
  test::append(soup, test::icosphere(1., 3), 3., 0., 0.);
  const test::Voxel_pipeline<Mesh, gs::Dense_voxel_grid> p(mesh_of(soup), 48);
  BOOST_TEST(test::graph_components(p.graph) == 2);
  BOOST_TEST(test::graph_cycles(p.graph) == 0);
}

BOOST_AUTO_TEST_CASE(the_graph_has_as_many_cycles_as_the_solid_and_no_triangle)
{
  // Demo meshes whose solids have tunnels at this resolution (near-contacts included): the
  // graph's cycle count is the solid's first Betti number, 1 - Euler characteristic.
  for(const char* name : {"cow.off", "elephant.off", "camel.off"})
  {
    const test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(demo_mesh(name), 96);
    BOOST_TEST(test::graph_cycles(p.graph) == 1 - p.solid_euler, name);
    BOOST_TEST(count_triangles(p.graph) == 0, name);
  }
}

BOOST_AUTO_TEST_CASE(an_unthinned_plate_gives_a_graph_without_triangle_or_cycle)
{
  // The voxels of a whole plate, not thinned: their triangles are one cluster of thousands
  // (a thinning that leaves a patch of sheet makes such clusters). Its graph is a tree, and a
  // plate with a hole through it has one cycle.
  const Mesh plate = mesh_of(test::box(0., 0., 0., 4., 4., 0.4));
  test::Soup frame_soup = test::box(0., 0., 0., 4., 1., 0.4);
  test::append(frame_soup, test::box(0., 3., 0., 4., 4., 0.4), 0., 0., 0.);
  test::append(frame_soup, test::box(0., 1., 0., 1., 3., 0.4), 0., 0., 0.);
  test::append(frame_soup, test::box(3., 1., 0., 4., 3., 0.4), 0., 0., 0.);
  const Mesh frame = mesh_of(frame_soup);
  for(const auto& [mesh, cycles] : {std::make_pair(&plate, 0), std::make_pair(&frame, 1)})
  {
    gs::Sparse_voxel_set voxels;
    gs::voxelize(*mesh, voxels, gs::parameters::resolution(48));
    const gs::Voxel_distance_field distances = gs::distance_transform(voxels);
    BOOST_TEST_REQUIRE(voxels.size() > 2000u);
    typename test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set>::Skeleton g;
    gs::to_graph(voxels, distances, *mesh, g);
    BOOST_TEST(num_vertices(g) == voxels.size());
    BOOST_TEST(test::graph_components(g) == 1);
    BOOST_TEST(count_triangles(g) == 0);
    BOOST_TEST(test::graph_cycles(g) == cycles);
  }
}

BOOST_AUTO_TEST_CASE(a_rigid_motion_moves_the_skeleton_with_the_mesh)
{
  const Mesh cow = demo_mesh("cow.off");
  const test::Voxel_pipeline<Mesh, gs::Dense_voxel_grid> original(cow, 64);
  const auto before = test::skeleton_points(original.graph);
  for(unsigned seed : {3u, 4u})
  {
    const auto motion = test::random_rigid_motion<Kernel>(seed, -2.5, 10., 0.7);
    Mesh moved = cow;
    for(auto v : vertices(moved))
      moved.point(v) = motion.transform(moved.point(v));
    const test::Voxel_pipeline<Mesh, gs::Dense_voxel_grid> p(moved, 64);
    std::vector<Point> back;
    const auto inverse = motion.inverse();
    for(const Point& q : test::skeleton_points(p.graph))
      back.push_back(inverse.transform(q));
    const double distance = test::hausdorff(before, back);
    BOOST_TEST_MESSAGE("seed " << seed << ": Hausdorff " << distance / original.voxel_size() << " voxels");
    BOOST_TEST(distance < original.voxel_size());
  }
}

BOOST_AUTO_TEST_CASE(demo_animals_give_one_connected_skeleton_inside_the_mesh)
{
  for(const char* name : {"cow.off", "camel.off", "elephant.off", "dino.off"})
  {
    const Mesh mesh = demo_mesh(name);
    const test::Voxel_pipeline<Mesh, gs::Dense_voxel_grid> p(mesh, 64);
    BOOST_TEST(test::graph_components(p.graph) == 1, name);
    BOOST_TEST(maps_every_vertex_once(p.graph, mesh), name);
    // Where a part is thinner than about two voxels, the skeleton runs through voxels that
    // the surface crosses; to_graph() puts their points inside the mesh: every point is.
    const CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(mesh);
    int outside = 0;
    for(auto v : boost::make_iterator_range(vertices(p.graph)))
      if(side(p.graph[v].point) == CGAL::ON_UNBOUNDED_SIDE)
      {
        ++outside;
        BOOST_TEST_MESSAGE(name << ": point " << p.graph[v].point << " (voxel radius^2 "
                                << p.distances.squared_distance(p.graph[v].voxel) << ") is outside");
      }
    BOOST_TEST(outside == 0, name << ": " << outside << " of " << num_vertices(p.graph) << " points outside");
  }
}

// A point moved inside stays within its voxel, or where the lines through the voxel find no
// inside, within its voxel's 26-neighbourhood: the skeleton moves by at most 1.5 voxels
// along each axis.
BOOST_AUTO_TEST_CASE(points_stay_near_their_voxels)
{
  const Mesh mesh = demo_mesh("camel.off");
  const test::Voxel_pipeline<Mesh, gs::Dense_voxel_grid> p(mesh, 64);
  const gs::Voxel_frame& frame = p.distances.frame();
  std::size_t moved = 0, left_voxel = 0;
  for(auto v : boost::make_iterator_range(vertices(p.graph)))
  {
    const auto& node = p.graph[v];
    const auto g = frame.to_grid({node.point.x(), node.point.y(), node.point.z()});
    const double offset[3] = {g[0] - node.voxel.x - 0.5, g[1] - node.voxel.y - 0.5, g[2] - node.voxel.z - 0.5};
    const double chebyshev = std::max({std::abs(offset[0]), std::abs(offset[1]), std::abs(offset[2])});
    BOOST_TEST(chebyshev <= 1.5 + 1e-9);
    moved += chebyshev > 1e-9;
    left_voxel += chebyshev > 0.5 + 1e-9;
  }
  BOOST_TEST_MESSAGE("camel: " << moved << " of " << num_vertices(p.graph) << " points moved off their voxel centre, "
                               << left_voxel << " out of their voxel");
  BOOST_TEST(moved > 0u); // the camel's tail and ears are thinner than two voxels at 64
}

BOOST_AUTO_TEST_CASE(the_elephant_with_holes_has_nearly_the_elephant_skeleton)
{
  const test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> closed(demo_mesh("elephant.off"), 64);
  const test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> holed(demo_mesh("elephant-with-holes.off"), 64);
  const double distance = test::hausdorff(test::skeleton_points(closed.graph), test::skeleton_points(holed.graph));
  BOOST_TEST_MESSAGE("Hausdorff " << distance / closed.voxel_size() << " voxels");
  BOOST_TEST(distance < 4 * closed.voxel_size());
  BOOST_TEST(test::graph_components(holed.graph) == 1);
}

BOOST_AUTO_TEST_CASE(radii_are_the_distance_to_the_surface)
{
  // A sphere of radius 1 thins to its centre, of radius about 1.
  const test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(mesh_of(test::icosphere(1., 4)), 48);
  BOOST_TEST(num_vertices(p.graph) == 1u);
  const auto& centre = p.graph[0];
  BOOST_TEST(std::sqrt(test::squared_distance_3(centre.point, Point(0, 0, 0))) <= p.voxel_size());
  BOOST_TEST(std::abs(centre.radius - 1.) <= p.voxel_size());
  BOOST_TEST(centre.vertices.size() == std::size_t(num_vertices(mesh_of(test::icosphere(1., 4)))));
}

BOOST_AUTO_TEST_CASE(a_polyhedron_gives_the_same_skeleton_as_a_surface_mesh)
{
  Polyhedron polyhedron;
  test::read_demo_mesh("dino.off", polyhedron);
  const test::Voxel_pipeline<Polyhedron, gs::Dense_voxel_grid> a(polyhedron, 64);
  const test::Voxel_pipeline<Mesh, gs::Dense_voxel_grid> b(demo_mesh("dino.off"), 64);
  BOOST_TEST(num_vertices(a.graph) == num_vertices(b.graph));
  BOOST_TEST(num_edges(a.graph) == num_edges(b.graph));
  BOOST_TEST(maps_every_vertex_once(a.graph, polyhedron));
}

BOOST_AUTO_TEST_CASE(an_mcf_skeleton_receives_the_points_and_mesh_vertices_and_a_radius_map_the_radii)
{
  // CGAL's MCF skeleton has `point` and `vertices` members, no radius and no voxel: the
  // first two are written through the bundle, the radius through the map the user gives.
  const Mesh cow = demo_mesh("cow.off");
  const test::Voxel_pipeline<Mesh, gs::Sparse_voxel_set> p(cow, 64);
  CGAL::Mean_curvature_flow_skeletonization<Mesh>::Skeleton mcf;
  std::vector<double> radii;
  gs::to_graph(p.voxels, p.distances, cow, mcf,
               gs::parameters::mat_radius_map(boost::make_function_property_map<std::size_t, double&>(
                   [&radii](std::size_t v) -> double& {
                     if(v >= radii.size())
                       radii.resize(v + 1, -1.);
                     return radii[v];
                   })));
  BOOST_TEST(num_vertices(mcf) == num_vertices(p.graph));
  BOOST_TEST(num_edges(mcf) == num_edges(p.graph));
  BOOST_TEST(radii.size() == num_vertices(p.graph));
  for(std::size_t v = 0; v < num_vertices(mcf); ++v)
  {
    BOOST_TEST(mcf[v].point == p.graph[v].point);
    BOOST_TEST((mcf[v].vertices == p.graph[v].vertices));
    BOOST_TEST(radii[std::min(v, radii.size() - 1)] == p.graph[v].radius);
  }
  BOOST_TEST(maps_every_vertex_once(mcf, cow));
}

BOOST_AUTO_TEST_CASE(a_bundle_with_only_a_point_receives_the_points_and_a_radius_map_the_radii)
{
  // A graph whose bundle has a `point` and none of the other member names: the points go
  // to the bundle, the radii to the map the user owns, equal to what Curve_skeleton's
  // members receive; the mesh vertices and voxels are not written anywhere.
  struct Node
  {
    Point point;
    int tag = 7;
  };
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, Node>;
  const Mesh dino = demo_mesh("dino.off");
  const test::Voxel_pipeline<Mesh, gs::Dense_voxel_grid> p(dino, 48);
  Graph g;
  boost::vector_property_map<double> radii;
  gs::to_graph(p.voxels, p.distances, dino, g, gs::parameters::mat_radius_map(radii));
  BOOST_TEST(num_vertices(g) == num_vertices(p.graph));
  BOOST_TEST(num_edges(g) == num_edges(p.graph));
  for(std::size_t v = 0; v < num_vertices(g); ++v)
  {
    BOOST_TEST(g[v].tag == 7);
    BOOST_TEST(g[v].point == p.graph[v].point);
    BOOST_TEST(radii[v] == p.graph[v].radius);
  }
}

BOOST_AUTO_TEST_CASE(an_empty_skeleton_is_an_error)
{
  gs::Sparse_voxel_set empty;
  gs::Curve_skeleton<Point, Mesh::Vertex_index> g;
  BOOST_CHECK_THROW(gs::to_graph(empty, gs::Voxel_distance_field(), mesh_of(test::box(0, 0, 0, 1, 1, 1)), g),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
