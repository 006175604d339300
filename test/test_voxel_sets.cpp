// Specification of the VoxelSet concept's models (Dense_voxel_grid.h, Sparse_voxel_set.h),
// of Voxel_key.h and of Voxel_frame.h; every voxel stage on the archetypes of the VoxelSet
// and VoxelDistanceField concepts.
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/reach_sheet_lobes.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>
#include <CGAL/Geodesic_skeleton/internal/medial_path_search.h>

#include <Geodesic_skeleton_test/shapes.h>
#include <Geodesic_skeleton_test/voxel_archetypes.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(voxel_sets)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

namespace {

using Voxel_set_models = boost::mpl::list<gs::Dense_voxel_grid, gs::Sparse_voxel_set>;

const gs::Voxel_box test_box{gs::Voxel_key{-3, -2, -1}, gs::Voxel_key{5, 6, 7}};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeleton = gs::Curve_skeleton<Kernel::Point_3, Mesh::Vertex_index>;

// What every voxel stage gives, run in the order of extract_control_skeleton().
struct Stage_outputs
{
  std::size_t solid_size = 0, thinned_away = 0, cut_away = 0;
  std::set<gs::Voxel_key> solid, thinned, reached, pruned;
  std::array<std::size_t, 3> lobes{};
  std::vector<std::uint32_t> squared_distances;
  std::array<std::size_t, 3> small_pieces{};
  std::array<std::size_t, 5> pruning{}, classes{};
  std::vector<std::tuple<gs::Voxel_key, double, double, double, double, std::size_t>> nodes;
  std::set<std::pair<std::size_t, std::size_t>> edges;
};

// `as_field` turns distance_transform()'s result into the field type the stages get.
template <typename VoxelSet, typename AsField>
Stage_outputs run_voxel_stages(const Mesh& mesh, AsField as_field)
{
  Stage_outputs out;
  VoxelSet voxels;
  out.solid_size = gs::voxelize(mesh, voxels, gs::parameters::resolution(40));
  out.solid = test::keys_of(voxels);
  const auto field = as_field(gs::distance_transform(voxels));
  out.squared_distances = field.values();
  out.thinned_away = gs::thin(voxels, field);
  out.thinned = test::keys_of(voxels);
  const gs::Sheet_lobes_report lobes = gs::reach_sheet_lobes(voxels, field);
  out.lobes = {lobes.sheet_voxels, lobes.lobes_reached, lobes.voxels_added};
  out.reached = test::keys_of(voxels);
  const gs::Small_pieces_report pieces = gs::remove_small_pieces(voxels, field);
  out.small_pieces = {pieces.pieces, pieces.removed_pieces, pieces.removed_voxels};
  out.cut_away = gs::cut_spurious_cycles(voxels, mesh);
  const gs::Pruning_report pruning = gs::prune_skeleton(voxels);
  out.pruning = {pruning.branched_regions, pruning.removed_branched_points, pruning.snipped_branches,
                 pruning.snipped_points, pruning.rounds};
  out.pruned = test::keys_of(voxels);
  const gs::Skeleton_point_counts counts = gs::count_skeleton_points(voxels);
  out.classes = {counts.isolated, counts.end, counts.middle, counts.connection, counts.branched_connection};
  Skeleton graph;
  gs::to_graph(voxels, field, mesh, graph);
  for(auto v : boost::make_iterator_range(vertices(graph)))
    out.nodes.emplace_back(graph[v].voxel, graph[v].point.x(), graph[v].point.y(), graph[v].point.z(),
                           graph[v].radius, graph[v].vertices.size());
  for(auto e : boost::make_iterator_range(edges(graph)))
    out.edges.emplace(std::minmax(std::size_t(source(e, graph)), std::size_t(target(e, graph))));
  return out;
}

} // namespace

// The archetypes have the concepts' members and nothing more: this compiles only if no
// stage asks more of a voxel set or of a distance field than its concept says.
BOOST_AUTO_TEST_CASE(every_voxel_stage_runs_on_the_concept_archetypes_as_on_a_sparse_set)
{
  // A torus with a bar through its hole: a cycle, junctions, end branches.
  Geodesic_skeleton_test::Soup soup = Geodesic_skeleton_test::torus(2, 0.6, 48, 16);
  Geodesic_skeleton_test::append(soup, Geodesic_skeleton_test::box(-3, -0.3, -0.3, 3, 0.3, 0.3));
  const Mesh mesh = Geodesic_skeleton_test::mesh_of<Mesh>(soup);
  const Stage_outputs sparse =
      run_voxel_stages<gs::Sparse_voxel_set>(mesh, [](gs::Voxel_distance_field f) { return f; });
  const Stage_outputs archetype = run_voxel_stages<Geodesic_skeleton_test::Voxel_set_archetype>(
      mesh, [](gs::Voxel_distance_field f) { return Geodesic_skeleton_test::Voxel_distance_field_archetype(std::move(f)); });
  BOOST_TEST(sparse.thinned_away > 0u);
  BOOST_TEST(sparse.edges.size() > 0u);
  BOOST_TEST(archetype.solid_size == sparse.solid_size);
  BOOST_TEST((archetype.solid == sparse.solid));
  BOOST_TEST((archetype.squared_distances == sparse.squared_distances));
  BOOST_TEST(archetype.thinned_away == sparse.thinned_away);
  BOOST_TEST((archetype.thinned == sparse.thinned));
  BOOST_TEST((archetype.lobes == sparse.lobes));
  BOOST_TEST((archetype.reached == sparse.reached));
  BOOST_TEST((archetype.small_pieces == sparse.small_pieces));
  BOOST_TEST(archetype.cut_away == sparse.cut_away);
  BOOST_TEST((archetype.pruning == sparse.pruning));
  BOOST_TEST((archetype.pruned == sparse.pruned));
  BOOST_TEST((archetype.classes == sparse.classes));
  BOOST_TEST((archetype.nodes == sparse.nodes));
  BOOST_TEST((archetype.edges == sparse.edges));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_model_behaves_like_a_set_of_keys, VoxelSet, Voxel_set_models)
{
  VoxelSet s;
  s.reset(gs::Voxel_frame(), test_box);
  BOOST_TEST(s.size() == 0u);
  std::mt19937 random(7);
  std::set<gs::Voxel_key> reference;
  for(int step = 0; step < 2000; ++step)
  {
    const gs::Voxel_key k{test_box.min.x + int(random() % 8), test_box.min.y + int(random() % 8),
                          test_box.min.z + int(random() % 8)};
    if(random() % 3 == 0)
      BOOST_TEST(s.erase(k) == (reference.erase(k) == 1));
    else
      BOOST_TEST(s.insert(k) == reference.insert(k).second);
    BOOST_TEST(s.contains(k) == (reference.count(k) == 1));
  }
  BOOST_TEST(s.size() == reference.size());
  BOOST_TEST((test::keys_of(s) == reference));
  for(const gs::Voxel_key& k : reference)
    BOOST_TEST(s.bounding_box().contains(k));
  BOOST_TEST(!s.contains(gs::Voxel_key{100, 100, 100}));
  s.clear();
  BOOST_TEST(s.size() == 0u);
  BOOST_TEST(test::keys_of(s).empty());
}

BOOST_AUTO_TEST_CASE_TEMPLATE(reset_empties_the_set_and_sets_the_frame, VoxelSet, Voxel_set_models)
{
  VoxelSet s;
  s.reset(gs::Voxel_frame(), test_box);
  s.insert(gs::Voxel_key{0, 0, 0});
  const gs::Voxel_frame frame({1., 2., 3.}, {{{0., 1., 0.}, {-1., 0., 0.}, {0., 0., 1.}}}, 0.25);
  s.reset(frame, test_box);
  BOOST_TEST(s.size() == 0u);
  BOOST_TEST(s.frame().voxel_size() == 0.25);
  BOOST_TEST(s.frame().origin()[2] == 3.);
}

BOOST_AUTO_TEST_CASE(the_dense_grid_refuses_keys_outside_its_box)
{
  gs::Dense_voxel_grid g;
  g.reset(gs::Voxel_frame(), test_box);
  BOOST_CHECK_THROW(g.insert(gs::Voxel_key{5, 0, 0}), std::out_of_range);
  BOOST_TEST(!g.erase(gs::Voxel_key{5, 0, 0}));
  BOOST_TEST(g.insert(gs::Voxel_key{4, 5, 6}));
}

BOOST_AUTO_TEST_CASE(the_dense_grid_iterates_in_key_order)
{
  gs::Dense_voxel_grid g;
  g.reset(gs::Voxel_frame(), test_box);
  for(const gs::Voxel_key k : {gs::Voxel_key{4, 0, 0}, gs::Voxel_key{-3, 1, 0}, gs::Voxel_key{0, 0, -1}})
    g.insert(k);
  std::vector<gs::Voxel_key> visited;
  g.for_each([&](const gs::Voxel_key& k) { visited.push_back(k); });
  BOOST_TEST(std::is_sorted(visited.begin(), visited.end()));
  BOOST_TEST(visited.size() == 3u);
}

BOOST_AUTO_TEST_CASE(the_26_neighbourhood_has_6_faces_12_edges_8_corners)
{
  int count[4] = {0, 0, 0, 0};
  std::set<gs::Voxel_key> distinct;
  for(const gs::Voxel_key& o : gs::neighbourhood_26())
  {
    ++count[gs::offset_order(o)];
    distinct.insert(o);
    BOOST_TEST(gs::are_26_adjacent(gs::Voxel_key{}, o));
  }
  BOOST_TEST(count[0] == 0);
  BOOST_TEST(count[1] == 6);
  BOOST_TEST(count[2] == 12);
  BOOST_TEST(count[3] == 8);
  BOOST_TEST(distinct.size() == 26u);
  // The second half is the first half mirrored, so offsets 13..25 visit each pair once.
  for(int i = 0; i < 13; ++i)
  {
    const gs::Voxel_key a = gs::neighbourhood_26()[i], b = gs::neighbourhood_26()[25 - i];
    BOOST_TEST((a + b == gs::Voxel_key{}));
  }
  BOOST_TEST(!gs::are_26_adjacent(gs::Voxel_key{}, gs::Voxel_key{2, 0, 0}));
}

BOOST_AUTO_TEST_CASE(the_frame_maps_voxel_centres_to_world_and_back)
{
  const double c = std::cos(0.3), s = std::sin(0.3);
  const gs::Voxel_frame frame({1., -2., 0.5}, {{{c, s, 0.}, {-s, c, 0.}, {0., 0., 1.}}}, 0.1);
  for(const gs::Voxel_key k : {gs::Voxel_key{0, 0, 0}, gs::Voxel_key{-7, 3, 12}, gs::Voxel_key{40, -1, 2}})
  {
    const auto p = frame.centre(k);
    BOOST_TEST((frame.voxel_of(p) == k));
    const auto g = frame.to_grid(p);
    BOOST_TEST(g[0] == k.x + 0.5, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(g[2] == k.z + 0.5, boost::test_tools::tolerance(1e-9));
  }
  // Neighbouring centres are one voxel size apart in world units.
  const auto a = frame.centre(gs::Voxel_key{0, 0, 0}), b = frame.centre(gs::Voxel_key{0, 1, 0});
  BOOST_TEST(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) == 0.1, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_frame_must_be_orthonormal_right_handed_and_positive)
{
  using A = std::array<std::array<double, 3>, 3>;
  BOOST_CHECK_THROW(gs::Voxel_frame({0., 0., 0.}, A{{{1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}}}, 0.),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::Voxel_frame({0., 0., 0.}, A{{{1., 0., 0.}, {0., 1., 0.}, {0., 0., -1.}}}, 1.),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::Voxel_frame({0., 0., 0.}, A{{{1., 0., 0.}, {1., 1., 0.}, {0., 0., 1.}}}, 1.),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::Voxel_frame({NAN, 0., 0.}, A{{{1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}}}, 1.),
                    std::invalid_argument);
}

// The shared search of the routing and the sheet lobes, in a 9 x 9 x 1 box: a wall at x = 4
// with one gap at y = 8 (the top row).
BOOST_AUTO_TEST_CASE(the_medial_path_search_finds_the_cheapest_path_around_a_wall)
{
  using Key = gs::Voxel_key;
  const gs::internal::Grid_layout layout(gs::Voxel_box{Key{0, 0, 0}, Key{9, 9, 1}});
  auto wall = [](const Key& k) { return k.x == 4 && k.y != 8; };
  auto step = [&](const Key& from, std::uint8_t, const Key& next, std::size_t) {
    return wall(next) ? std::nullopt : std::optional<double>(gs::internal::step_length(from, next));
  };
  const Key start{0, 0, 0}, goal{8, 0, 0};
  auto is_goal = [&](const Key& k) { return k == goal; };
  auto no_estimate = [](const Key&) { return 0.; };
  auto straight_line = [&](const Key& k) { return std::sqrt(double(gs::internal::squared_distance_between(k, goal))); };
  gs::internal::Medial_path_search<double> search;
  const std::vector<Key> dijkstra = search.cheapest_path(layout, start, is_goal, step, no_estimate);
  const std::vector<Key> a_star = search.cheapest_path(layout, start, is_goal, step, straight_line);
  auto cost = [](const std::vector<Key>& path) {
    double sum = 0;
    for(std::size_t i = 1; i < path.size(); ++i)
      sum += gs::internal::step_length(path[i - 1], path[i]);
    return sum;
  };
  BOOST_REQUIRE(!dijkstra.empty());
  BOOST_CHECK(dijkstra.front() == start);
  BOOST_CHECK(dijkstra.back() == goal);
  for(std::size_t i = 0; i < dijkstra.size(); ++i)
  {
    BOOST_CHECK(!wall(dijkstra[i]));
    if(i > 0)
      BOOST_CHECK(gs::internal::squared_distance_between(dijkstra[i - 1], dijkstra[i]) <= 3);
  }
  // Up to the gap and down again, 4 diagonal and 4 straight steps each way.
  BOOST_CHECK_CLOSE(cost(dijkstra), 8 + 8 * std::sqrt(2.), 1e-9);
  BOOST_CHECK_CLOSE(cost(a_star), cost(dijkstra), 1e-9);
  // The search cleared its arrays: the same search again finds the same path.
  BOOST_CHECK(search.cheapest_path(layout, start, is_goal, step, no_estimate) == dijkstra);
  // Sealed off (the gap closed), there is no path.
  auto sealed = [&](const Key& from, std::uint8_t, const Key& next, std::size_t) {
    return next.x == 4 ? std::nullopt : std::optional<double>(gs::internal::step_length(from, next));
  };
  BOOST_CHECK(search.cheapest_path(layout, start, is_goal, sealed, no_estimate).empty());
}

BOOST_AUTO_TEST_SUITE_END()
