// Specification of CGAL/Geodesic_skeleton/classify_skeleton_points.h and
// CGAL/Geodesic_skeleton/prune_skeleton.h (the paper's Algorithm 1 and the snipping of
// spurious branches), on hand-made voxel skeletons and on both VoxelSet models.
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Skeleton_radius_in_voxels_map.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>

#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/graft_coarse_end_branches.h>
#include <CGAL/Geodesic_skeleton/route_lone_paths_through_the_middle.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <Geodesic_skeleton_test/shapes.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <boost/mpl/list.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <unordered_map>
#include <vector>

BOOST_AUTO_TEST_SUITE(prune_skeleton)

namespace gs = CGAL::Geodesic_skeleton;
using gs::Voxel_key;
using Voxel_set_models = boost::mpl::list<gs::Dense_voxel_grid, gs::Sparse_voxel_set>;

namespace {

template <typename VoxelSet>
VoxelSet voxel_set(const std::vector<Voxel_key>& voxels)
{
  VoxelSet set;
  set.reset(gs::Voxel_frame(), gs::Voxel_box{Voxel_key{-20, -20, -20}, Voxel_key{20, 20, 20}});
  for(const Voxel_key& k : voxels)
    set.insert(k);
  return set;
}

template <typename VoxelSet>
std::set<Voxel_key> contents(const VoxelSet& set)
{
  std::set<Voxel_key> out;
  set.for_each([&](const Voxel_key& k) { out.insert(k); });
  return out;
}

void add_segment(std::vector<Voxel_key>& v, Voxel_key from, Voxel_key step, int count)
{
  for(int i = 0; i < count; ++i)
    v.push_back(Voxel_key{from.x + i * step.x, from.y + i * step.y, from.z + i * step.z});
}

// Adds the voxels of the box from `min` to `max`, both corners included.
void add_box(std::vector<Voxel_key>& v, Voxel_key min, Voxel_key max)
{
  for(int z = min.z; z <= max.z; ++z)
    for(int y = min.y; y <= max.y; ++y)
      for(int x = min.x; x <= max.x; ++x)
        v.push_back(Voxel_key{x, y, z});
}

// Three arms (+x, -x, +y) of 7 voxels leaving a flat 3x3 cluster centred at the origin:
// a thick junction, as thinning leaves where limbs meet.
std::vector<Voxel_key> thick_junction_with_three_arms()
{
  std::vector<Voxel_key> v;
  for(int x = -1; x <= 1; ++x)
    for(int y = -1; y <= 1; ++y)
      v.push_back(Voxel_key{x, y, 0});
  add_segment(v, Voxel_key{2, 0, 0}, Voxel_key{1, 0, 0}, 7);
  add_segment(v, Voxel_key{-2, 0, 0}, Voxel_key{-1, 0, 0}, 7);
  add_segment(v, Voxel_key{0, 2, 0}, Voxel_key{0, 1, 0}, 7);
  return v;
}

// What Algorithm 1 leaves of it: the region is the 3x3 cluster and the three arm voxels
// touching it; its centroid is the origin; the shortest paths to the terminators (3,0,0),
// (-3,0,0), (0,3,0) are straight, so five voxels of the cluster go.
std::set<Voxel_key> thick_junction_pruned()
{
  std::vector<Voxel_key> v = thick_junction_with_three_arms();
  std::set<Voxel_key> left(v.begin(), v.end());
  for(const Voxel_key k : {Voxel_key{-1, -1, 0}, Voxel_key{0, -1, 0}, Voxel_key{1, -1, 0},
                           Voxel_key{-1, 1, 0}, Voxel_key{1, 1, 0}})
    left.erase(k);
  return left;
}

// A closed square loop of side 8 in the plane z = 0.
std::vector<Voxel_key> square_loop()
{
  std::vector<Voxel_key> v;
  add_segment(v, Voxel_key{0, 0, 0}, Voxel_key{1, 0, 0}, 8);
  add_segment(v, Voxel_key{8, 0, 0}, Voxel_key{0, 1, 0}, 8);
  add_segment(v, Voxel_key{8, 8, 0}, Voxel_key{-1, 0, 0}, 8);
  add_segment(v, Voxel_key{0, 8, 0}, Voxel_key{0, -1, 0}, 8);
  return v;
}

std::size_t components_of(const std::set<Voxel_key>& voxels)
{
  return gs::internal::voxel_components(std::vector<Voxel_key>(voxels.begin(), voxels.end())).size();
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(points_are_classified_as_in_definition_7, VoxelSet, Voxel_set_models)
{
  // A path with a clean T junction: (5,0,0) forks to +y.
  std::vector<Voxel_key> v;
  add_segment(v, Voxel_key{0, 0, 0}, Voxel_key{1, 0, 0}, 11);
  add_segment(v, Voxel_key{5, 1, 0}, Voxel_key{0, 1, 0}, 6);
  v.push_back(Voxel_key{15, 15, 15}); // a lone voxel
  const VoxelSet skeleton = voxel_set<VoxelSet>(v);
  std::unordered_map<Voxel_key, gs::Skeleton_point_class, gs::Voxel_key_hash> classes;
  const gs::Skeleton_point_counts counts =
      gs::classify_skeleton_points(skeleton, boost::make_assoc_property_map(classes));

  using C = gs::Skeleton_point_class;
  BOOST_TEST((classes.at(Voxel_key{0, 0, 0}) == C::end));
  BOOST_TEST((classes.at(Voxel_key{10, 0, 0}) == C::end));
  BOOST_TEST((classes.at(Voxel_key{5, 6, 0}) == C::end));
  BOOST_TEST((classes.at(Voxel_key{2, 0, 0}) == C::middle));
  BOOST_TEST((classes.at(Voxel_key{5, 3, 0}) == C::middle));
  // (4,0,0), (5,0,0), (6,0,0), (5,1,0) touch each other: degree 3 or 4 with neighbours of
  // degree 3 or more, so branched connection points.
  for(const Voxel_key k : {Voxel_key{4, 0, 0}, Voxel_key{5, 0, 0}, Voxel_key{6, 0, 0}, Voxel_key{5, 1, 0}})
    BOOST_TEST((classes.at(k) == C::branched_connection));
  BOOST_TEST((classes.at(Voxel_key{15, 15, 15}) == C::isolated));
  BOOST_TEST(counts.end == 3u);
  BOOST_TEST(counts.branched_connection == 4u);
  BOOST_TEST(counts.isolated == 1u);
  BOOST_TEST(counts.total() == v.size());
  BOOST_TEST(gs::count_skeleton_points(skeleton).middle == counts.middle);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_connection_point_has_only_end_and_middle_neighbours, VoxelSet, Voxel_set_models)
{
  // A star of three diagonal arms from the origin whose first voxels (1,1,0), (-1,1,0) and
  // (0,-1,1) are pairwise not 26-adjacent: the centre forks cleanly.
  std::vector<Voxel_key> v{Voxel_key{0, 0, 0}};
  add_segment(v, Voxel_key{1, 1, 0}, Voxel_key{1, 1, 0}, 3);
  add_segment(v, Voxel_key{-1, 1, 0}, Voxel_key{-1, 1, 0}, 3);
  add_segment(v, Voxel_key{0, -1, 1}, Voxel_key{0, -1, 1}, 3);
  const VoxelSet skeleton = voxel_set<VoxelSet>(v);
  std::unordered_map<Voxel_key, gs::Skeleton_point_class, gs::Voxel_key_hash> classes;
  gs::classify_skeleton_points(skeleton, boost::make_assoc_property_map(classes));
  BOOST_TEST(gs::skeleton_degree(skeleton, Voxel_key{0, 0, 0}) == 3);
  BOOST_TEST((classes.at(Voxel_key{0, 0, 0}) == gs::Skeleton_point_class::connection));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_thick_junction_is_pruned_to_the_shortest_paths, VoxelSet, Voxel_set_models)
{
  VoxelSet skeleton = voxel_set<VoxelSet>(thick_junction_with_three_arms());
  const gs::Pruning_report report =
      gs::prune_skeleton(skeleton, gs::parameters::combine(gs::parameters::spur_length_factor(0.0),
                                                           gs::parameters::limb_protrusion_factor(0.0)));

  const std::set<Voxel_key> expected = thick_junction_pruned();
  BOOST_TEST((contents(skeleton) == expected));
  BOOST_TEST(report.branched_regions == 1u);
  BOOST_TEST(report.removed_branched_points == 5u);
  BOOST_TEST(report.snipped_branches == 0u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_spurious_twig_is_snipped_and_real_limbs_are_kept, VoxelSet, Voxel_set_models)
{
  std::vector<Voxel_key> v = thick_junction_with_three_arms();
  // A twig of two voxels hanging from (5,0,0) towards -y: shorter than the radius there.
  v.push_back(Voxel_key{5, -1, 0});
  v.push_back(Voxel_key{5, -2, 0});
  VoxelSet skeleton = voxel_set<VoxelSet>(v);
  const auto radius = CGAL::Constant_property_map<Voxel_key, double>(3.0);
  const gs::Pruning_report report = gs::prune_skeleton(
      skeleton, gs::parameters::combine(gs::parameters::mat_radius_map(radius),
                                        gs::parameters::spur_length_factor(1.2)));

  const std::set<Voxel_key> expected = thick_junction_pruned();
  const std::set<Voxel_key> left = contents(skeleton);
  for(const Voxel_key& k : left)
    BOOST_TEST(expected.count(k) == 1u, k << " is expected");
  for(const Voxel_key& k : expected)
    BOOST_TEST(left.count(k) == 1u, k << " is left");
  BOOST_TEST(report.branched_regions == 2u);
  BOOST_TEST(report.snipped_branches >= 1u);
  BOOST_TEST(report.rounds >= 1u);
  // The three arms (9 voxels from the centre, 3 radii) are real limbs: all ends are kept.
  BOOST_TEST(gs::count_skeleton_points(skeleton).end == 3u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(short_arms_are_snipped_only_while_the_skeleton_goes_on, VoxelSet, Voxel_set_models)
{
  // All three arms are shorter than the threshold: the two shortest go, the last stays, so
  // the skeleton keeps a path rather than vanishing.
  VoxelSet skeleton = voxel_set<VoxelSet>(thick_junction_with_three_arms());
  const auto radius = CGAL::Constant_property_map<Voxel_key, double>(100.0);
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(radius));
  const std::set<Voxel_key> left = contents(skeleton);
  BOOST_TEST(left.size() >= 15u); // two arms of 7 and the centre
  BOOST_TEST(components_of(left) == 1u);
  BOOST_TEST(gs::count_skeleton_points(skeleton).end == 2u);
}

// A chain along x that steps down one voxel on each side of a face-adjacent pair a, b, and a
// voxel s diagonal to both (and to nothing else): s has two neighbours, so by voxel degrees
// it is a middle point, a terminator of the branched region {a, b}; the graph of to_graph()
// drops the longest edge of the triangle s, a, b (s-b), so s hangs on a as an end one step
// long, which the control skeleton would make an end point of.
std::vector<Voxel_key> chain_with_a_stub_on_a_step(Voxel_key& stub)
{
  std::vector<Voxel_key> v;
  add_segment(v, Voxel_key{-12, 0, 0}, Voxel_key{1, 0, 0}, 11);  // x = -12 .. -2
  v.push_back(Voxel_key{-1, -1, 0});
  v.push_back(Voxel_key{0, 0, 0}); // a
  v.push_back(Voxel_key{1, 0, 0}); // b
  v.push_back(Voxel_key{2, -1, 0});
  add_segment(v, Voxel_key{3, -2, 0}, Voxel_key{1, 0, 0}, 10);   // x = 3 .. 12
  stub = Voxel_key{0, 1, 1};
  v.push_back(stub);
  return v;
}

// A long chain along x and a short twig up +y from its middle, whose tip is a little
// triangle w, t, u (pairwise adjacent, t and u adjacent to nothing else): no voxel of the
// twig has degree 1, so only the graph shows its end.
std::vector<Voxel_key> chain_with_a_twig_ending_in_a_triangle(std::vector<Voxel_key>& chain)
{
  chain.clear();
  add_segment(chain, Voxel_key{-15, 0, 0}, Voxel_key{1, 0, 0}, 31);
  std::vector<Voxel_key> v = chain;
  add_segment(v, Voxel_key{0, 1, 0}, Voxel_key{0, 1, 0}, 3); // up to w = (0, 3, 0)
  v.push_back(Voxel_key{1, 4, 0});                           // t
  v.push_back(Voxel_key{0, 4, 1});                           // u
  return v;
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_stub_that_only_the_graph_shows_as_an_end_is_snipped, VoxelSet, Voxel_set_models)
{
  Voxel_key stub;
  const std::vector<Voxel_key> v = chain_with_a_stub_on_a_step(stub);
  VoxelSet skeleton = voxel_set<VoxelSet>(v);
  BOOST_TEST(gs::skeleton_degree(skeleton, stub) == 2);
  BOOST_TEST(gs::internal::skeleton_statistics_of_voxels(skeleton).end_points == 3u); // the graph's view
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(CGAL::Constant_property_map<Voxel_key, double>(3.0)));
  std::set<Voxel_key> expected(v.begin(), v.end());
  expected.erase(stub);
  BOOST_TEST((contents(skeleton) == expected));
  BOOST_TEST(gs::internal::skeleton_statistics_of_voxels(skeleton).end_points == 2u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_twig_whose_tip_is_a_triangle_is_snipped, VoxelSet, Voxel_set_models)
{
  std::vector<Voxel_key> chain;
  VoxelSet skeleton = voxel_set<VoxelSet>(chain_with_a_twig_ending_in_a_triangle(chain));
  BOOST_TEST(gs::count_skeleton_points(skeleton).end == 2u); // the chain's two ends only
  // The twig, about 5 voxels, is shorter than 1.2 radii of 5; the chain's halves are longer.
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(CGAL::Constant_property_map<Voxel_key, double>(5.0)));
  BOOST_TEST((contents(skeleton) == std::set<Voxel_key>(chain.begin(), chain.end())));
}

// A body seen from its skeleton, `scale` voxels per unit: a trunk along x (radius 6 units),
// a limb along +y from its middle (30 units, radius 2) and a bump along -y (9 units, its
// radius falling from the trunk's to 0.6 units, as a hip or a shoulder looks: longer than
// 1.2 radii at the junction, but its balls reach only 3.6 units out of the trunk's ball).
struct Body_with_a_limb_and_a_bump
{
  std::vector<Voxel_key> voxels;
  std::unordered_map<Voxel_key, double, gs::Voxel_key_hash> radius;
  Voxel_key limb_end, bump_end;
};

Body_with_a_limb_and_a_bump body_with_a_limb_and_a_bump(int scale)
{
  Body_with_a_limb_and_a_bump b;
  for(int x = -20 * scale; x <= 20 * scale; ++x)
  {
    b.voxels.push_back(Voxel_key{x, 0, 0});
    b.radius[b.voxels.back()] = 6.0 * scale;
  }
  for(int y = 1; y <= 30 * scale; ++y)
  {
    b.voxels.push_back(Voxel_key{0, y, 0});
    b.radius[b.voxels.back()] = 2.0 * scale;
  }
  for(int y = 1; y <= 9 * scale; ++y)
  {
    b.voxels.push_back(Voxel_key{0, -y, 0});
    b.radius[b.voxels.back()] = std::max(6.0 * scale - 0.6 * y, 0.6 * scale);
  }
  b.limb_end = Voxel_key{0, 30 * scale, 0};
  b.bump_end = Voxel_key{0, -9 * scale, 0};
  return b;
}

// (On a sparse set only: the bodies are larger than the dense test grid.)
BOOST_AUTO_TEST_CASE(a_bump_that_hardly_reaches_out_of_the_body_is_snipped_at_every_scale)
{
  using VoxelSet = gs::Sparse_voxel_set;
  for(int scale : {1, 2, 4})
  {
    BOOST_TEST_CONTEXT("scale " << scale)
    {
      const Body_with_a_limb_and_a_bump body = body_with_a_limb_and_a_bump(scale);
      const auto radius = boost::make_assoc_property_map(body.radius);
      VoxelSet skeleton = voxel_set<VoxelSet>(body.voxels);
      const gs::Pruning_report report = gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(radius));
      BOOST_TEST(!skeleton.contains(body.bump_end));
      BOOST_TEST(skeleton.contains(body.limb_end));
      BOOST_TEST(report.snipped_branches == 1u);
      BOOST_TEST(gs::count_skeleton_points(skeleton).end == 3u);
      BOOST_TEST(components_of(contents(skeleton)) == 1u);

      // Without the level of detail, the length test alone keeps the bump.
      VoxelSet every_branch = voxel_set<VoxelSet>(body.voxels);
      gs::prune_skeleton(every_branch, gs::parameters::combine(gs::parameters::mat_radius_map(radius),
                                                               gs::parameters::limb_protrusion_factor(0.0)));
      BOOST_TEST(every_branch.contains(body.bump_end));
      BOOST_TEST(gs::count_skeleton_points(every_branch).end == 4u);

      // A finer level of detail keeps it too: its protrusion is 0.6 of the trunk's radius.
      VoxelSet finer = voxel_set<VoxelSet>(body.voxels);
      gs::prune_skeleton(finer, gs::parameters::combine(gs::parameters::mat_radius_map(radius),
                                                        gs::parameters::limb_protrusion_factor(0.5)));
      BOOST_TEST(finer.contains(body.bump_end));
    }
  }
}

BOOST_AUTO_TEST_CASE(the_level_of_detail_is_relative_to_each_piece)
{
  using VoxelSet = gs::Sparse_voxel_set;
  // A second, thinner body far away, a quarter of the size: its limb is judged against its
  // own trunk, not against the first body's, and stays.
  Body_with_a_limb_and_a_bump big = body_with_a_limb_and_a_bump(4);
  const Body_with_a_limb_and_a_bump small = body_with_a_limb_and_a_bump(1);
  const Voxel_key away{0, 0, 500};
  for(const Voxel_key& k : small.voxels)
  {
    const Voxel_key moved = k + away;
    big.voxels.push_back(moved);
    big.radius[moved] = small.radius.at(k);
  }
  VoxelSet skeleton = voxel_set<VoxelSet>(big.voxels);
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(boost::make_assoc_property_map(big.radius)));
  BOOST_TEST(skeleton.contains(small.limb_end + away));
  BOOST_TEST(!skeleton.contains(small.bump_end + away));
  BOOST_TEST(skeleton.contains(big.limb_end));
  BOOST_TEST(!skeleton.contains(big.bump_end));
}

// piece_radius_map: the unit of a piece's level of detail (limb_protrusion_factor) is at
// least what the map gives, as extract_control_skeleton() gives the widest sheet of a piece
// read across close levels. A trunk along x (radius 6, 40 voxels on each side of the
// junction) and a limb along +y (20 voxels, radius 2), whose balls reach 16 voxels out of
// the trunk's: it stays at the piece's own largest radius (0.75 x 6 = 4.5 voxels) and at 20
// (15 voxels), and is snipped at 25 (18.75), the trunk's halves staying (40 voxels out).
BOOST_AUTO_TEST_CASE(a_piece_radius_map_sets_the_level_of_detail_of_the_piece)
{
  using VoxelSet = gs::Sparse_voxel_set;
  std::vector<Voxel_key> voxels;
  std::unordered_map<Voxel_key, double, gs::Voxel_key_hash> radius;
  for(int x = -40; x <= 40; ++x)
  {
    voxels.push_back(Voxel_key{x, 0, 0});
    radius[voxels.back()] = 6.0;
  }
  for(int y = 1; y <= 20; ++y)
  {
    voxels.push_back(Voxel_key{0, y, 0});
    radius[voxels.back()] = 2.0;
  }
  const Voxel_key limb_end{0, 20, 0};
  const auto mat_radius = gs::parameters::mat_radius_map(boost::make_assoc_property_map(radius));
  const auto pruned_with_piece_radius = [&](double piece_radius) {
    VoxelSet skeleton = voxel_set<VoxelSet>(voxels);
    gs::prune_skeleton(skeleton, gs::parameters::combine(gs::parameters::piece_radius_map(
                                                             CGAL::Constant_property_map<Voxel_key, double>(piece_radius)),
                                                         mat_radius));
    return skeleton;
  };
  VoxelSet without_map = voxel_set<VoxelSet>(voxels);
  gs::prune_skeleton(without_map, mat_radius);
  BOOST_TEST(without_map.contains(limb_end));
  BOOST_TEST((contents(pruned_with_piece_radius(0)) == contents(without_map)));
  BOOST_TEST(pruned_with_piece_radius(20).contains(limb_end));
  const VoxelSet wide = pruned_with_piece_radius(25);
  BOOST_TEST(!wide.contains(limb_end));
  BOOST_TEST(wide.contains(Voxel_key{-40, 0, 0}));
  BOOST_TEST(wide.contains(Voxel_key{40, 0, 0}));
}

// A spine along x (radius 6) with parallel teeth along +y (radius 3, 23 voxels long), as
// thinning leaves them in a thick sheet slanted in the grid. Each tooth reaches far out of
// its junction's ball, but `spacing` 2 puts every tooth inside the balls of the next one.
struct Comb
{
  std::vector<Voxel_key> voxels;
  std::unordered_map<Voxel_key, double, gs::Voxel_key_hash> radius;
  std::vector<Voxel_key> tips;
};

Comb comb(const std::vector<int>& teeth)
{
  Comb c;
  add_segment(c.voxels, Voxel_key{-18, -12, 0}, Voxel_key{1, 0, 0}, 37);
  for(const Voxel_key& k : c.voxels)
    c.radius[k] = 6.0;
  for(int x : teeth)
  {
    for(int y = -11; y <= 12; ++y)
    {
      c.voxels.push_back(Voxel_key{x, y, 0});
      c.radius[c.voxels.back()] = 3.0;
    }
    c.tips.push_back(c.voxels.back());
  }
  return c;
}

BOOST_AUTO_TEST_CASE_TEMPLATE(of_teeth_inside_each_others_balls_one_stays, VoxelSet, Voxel_set_models)
{
  const Comb teeth = comb({-3, -1, 1, 3});
  VoxelSet skeleton = voxel_set<VoxelSet>(teeth.voxels);
  BOOST_TEST(gs::count_skeleton_points(skeleton).end == 6u);
  const gs::Pruning_report report =
      gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(boost::make_assoc_property_map(teeth.radius)));
  // The spine's two ends and one tooth, whole.
  BOOST_TEST(gs::count_skeleton_points(skeleton).end == 3u);
  BOOST_TEST(report.snipped_branches == 3u);
  const auto stays = [&](const Voxel_key& tip) { return skeleton.contains(tip); };
  BOOST_TEST(std::count_if(teeth.tips.begin(), teeth.tips.end(), stays) == 1);
  // With the balls of the rest out of the test (their junction's ball only), every tooth
  // reaches 23 voxels out: all stay. The test's lever is the level of detail.
  VoxelSet all_teeth = voxel_set<VoxelSet>(teeth.voxels);
  gs::prune_skeleton(all_teeth, gs::parameters::combine(
                                    gs::parameters::mat_radius_map(boost::make_assoc_property_map(teeth.radius)),
                                    gs::parameters::limb_protrusion_factor(0.0)));
  BOOST_TEST(gs::count_skeleton_points(all_teeth).end == 6u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(limbs_side_by_side_stay, VoxelSet, Voxel_set_models)
{
  // Two teeth 6 voxels apart touch (radius 3 each) without either centre line entering the
  // other's balls: two limbs side by side, as fingers are. Both stay.
  const Comb fingers = comb({-3, 3});
  VoxelSet skeleton = voxel_set<VoxelSet>(fingers.voxels);
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(boost::make_assoc_property_map(fingers.radius)));
  for(const Voxel_key& tip : fingers.tips)
    BOOST_TEST(skeleton.contains(tip));
  BOOST_TEST(gs::count_skeleton_points(skeleton).end == 4u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_loop_keeps_its_cycle, VoxelSet, Voxel_set_models)
{
  // A square loop with a thick corner and a twig: pruning may thin the corner and snip the
  // twig, never open the loop.
  std::vector<Voxel_key> v = square_loop();
  v.push_back(Voxel_key{1, 1, 0});
  v.push_back(Voxel_key{2, 1, 0});
  v.push_back(Voxel_key{1, 2, 0});
  add_segment(v, Voxel_key{4, 1, 0}, Voxel_key{0, 1, 0}, 2); // twig inside the loop
  VoxelSet skeleton = voxel_set<VoxelSet>(v);
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(CGAL::Constant_property_map<Voxel_key, double>(2.0)));
  // The thick corner may be cut diagonally; everything away from it stays.
  const std::set<Voxel_key> left = contents(skeleton);
  for(const Voxel_key& k : square_loop())
    if(k.x + k.y >= 4)
      BOOST_TEST(left.count(k) == 1u, "loop voxel " << k << " kept");
  BOOST_TEST(left.count(Voxel_key{4, 1, 0}) == 0u);
  BOOST_TEST(left.count(Voxel_key{4, 2, 0}) == 0u);
  BOOST_TEST(components_of(left) == 1u);
  BOOST_TEST(gs::count_skeleton_points(skeleton).end == 0u);
  BOOST_TEST(gs::count_skeleton_points(skeleton).isolated == 0u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_plain_path_is_never_snipped, VoxelSet, Voxel_set_models)
{
  std::vector<Voxel_key> v;
  add_segment(v, Voxel_key{0, 0, 0}, Voxel_key{1, 1, 0}, 4);
  VoxelSet skeleton = voxel_set<VoxelSet>(v);
  gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(CGAL::Constant_property_map<Voxel_key, double>(50.0)));
  BOOST_TEST(skeleton.size() == 4u);
}

// The coarse end points of thick_junction_with_three_arms() at the tips of its arms, in grid
// coordinates (voxel centres), as a coarser grid would see them.
const std::array<double, 3> tip_of_plus_x_arm{8.5, 0.5, 0.5}, tip_of_minus_x_arm{-7.5, 0.5, 0.5},
    tip_of_plus_y_arm{0.5, 8.5, 0.5};

// What prune_skeleton() leaves of `voxels`, all of MAT radius 3, given the coarse end
// points `coarse` (none when null) and their tolerance, and its report.
template <typename VoxelSet>
std::pair<std::set<Voxel_key>, gs::Pruning_report> pruned_with_coarse_end_points(
    const std::vector<Voxel_key>& voxels, const std::vector<std::array<double, 3>>* coarse, double tolerance)
{
  VoxelSet skeleton = voxel_set<VoxelSet>(voxels);
  const gs::Pruning_report report = gs::prune_skeleton(
      skeleton, gs::parameters::combine(
                    gs::parameters::mat_radius_map(CGAL::Constant_property_map<Voxel_key, double>(3.0)),
                    gs::parameters::coarse_end_points(coarse), gs::parameters::coarse_end_point_tolerance(tolerance)));
  return std::make_pair(contents(skeleton), report);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(an_end_branch_that_a_coarser_skeleton_has_not_is_snipped, VoxelSet, Voxel_set_models)
{
  // Radius 3: each arm (8 voxels out of the cluster) reaches out more than the level of
  // detail and is longer than the spur length, so it stays on its own, but not 3 times so.
  auto pruned_with = [](const std::vector<std::array<double, 3>>* coarse, double tolerance) {
    return pruned_with_coarse_end_points<VoxelSet>(thick_junction_with_three_arms(), coarse, tolerance);
  };
  const Voxel_key end_of_plus_y_arm{0, 8, 0};

  // Without a coarser skeleton, the three arms stay.
  const auto [alone, alone_report] = pruned_with(nullptr, 4.0);
  BOOST_TEST(alone.count(end_of_plus_y_arm) == 1u);
  BOOST_TEST(alone_report.snipped_beyond_coarse_detail == 0u);

  // The coarser skeleton has the two x arms: the y arm, whose tip is 8 voxels from both, goes.
  const std::vector<std::array<double, 3>> two_ends{tip_of_plus_x_arm, tip_of_minus_x_arm};
  const auto [guided, guided_report] = pruned_with(&two_ends, 4.0);
  BOOST_TEST(guided.count(end_of_plus_y_arm) == 0u);
  BOOST_TEST(guided.count(Voxel_key{8, 0, 0}) == 1u);
  BOOST_TEST(guided.count(Voxel_key{-8, 0, 0}) == 1u);
  BOOST_TEST(guided_report.snipped_beyond_coarse_detail == 1u);
  BOOST_TEST(components_of(guided) == 1u);

  // A tolerance that takes in the +x arm's coarse end point (11.7 voxels from the y arm's
  // tip) does not keep the y arm: that point is paired with the +x arm's tip, on it, and
  // vouches for no other branch.
  const auto [paired_elsewhere, paired_elsewhere_report] = pruned_with(&two_ends, 12.0);
  BOOST_TEST(paired_elsewhere.count(end_of_plus_y_arm) == 0u);
  BOOST_TEST(paired_elsewhere.count(Voxel_key{8, 0, 0}) == 1u);
  BOOST_TEST(paired_elsewhere.count(Voxel_key{-8, 0, 0}) == 1u);
  BOOST_TEST(paired_elsewhere_report.snipped_beyond_coarse_detail == 1u);

  // A coarse end point 2.8 voxels from the y arm's tip and farther from the others keeps the
  // y arm (its tip is paired with it, so it is only cut back towards it); the -x arm, which
  // no coarse end point is paired with, goes.
  const std::vector<std::array<double, 3>> beside_the_y_tip{tip_of_plus_x_arm, {2.5, 6.5, 0.5}};
  const auto [matched, matched_report] = pruned_with(&beside_the_y_tip, 4.0);
  BOOST_TEST(matched.count(Voxel_key{0, 2, 0}) == 1u);
  BOOST_TEST(matched.count(Voxel_key{-8, 0, 0}) == 0u);
  BOOST_TEST(matched_report.snipped_beyond_coarse_detail == 1u);
  BOOST_TEST(matched_report.cut_back_branches >= 1u);

  // As many coarse end points as ends: nothing more is snipped, even where none matches.
  const std::vector<std::array<double, 3>> three_elsewhere{{0.5, -9.5, 0.5}, {0.5, 0.5, 9.5}, {0.5, 0.5, -9.5}};
  const auto [as_many, as_many_report] = pruned_with(&three_elsewhere, 4.0);
  BOOST_TEST(as_many.size() == alone.size());
  BOOST_TEST(as_many_report.snipped_beyond_coarse_detail == 0u);

  // One coarse end point: the skeleton still goes on past its junction, so two arms stay.
  const std::vector<std::array<double, 3>> one_end{tip_of_plus_x_arm};
  const auto [one, one_report] = pruned_with(&one_end, 4.0);
  BOOST_TEST(one.count(Voxel_key{8, 0, 0}) == 1u);
  BOOST_TEST(one_report.snipped_beyond_coarse_detail == 1u);
  BOOST_TEST(components_of(one) == 1u);
}

// A spine 21 voxels long along x and two parallel teeth, 8 voxels up y from x = -2 and from
// x = 1: the comb that a fine grid leaves along a thin rim, where a coarser grid has one end.
std::vector<Voxel_key> spine_with_two_teeth()
{
  std::vector<Voxel_key> v;
  add_segment(v, Voxel_key{-10, 0, 0}, Voxel_key{1, 0, 0}, 21);
  add_segment(v, Voxel_key{-2, 1, 0}, Voxel_key{0, 1, 0}, 8);
  add_segment(v, Voxel_key{1, 1, 0}, Voxel_key{0, 1, 0}, 8);
  return v;
}

BOOST_AUTO_TEST_CASE_TEMPLATE(of_two_teeth_that_end_near_one_coarse_end_point_the_farther_is_snipped, VoxelSet,
                              Voxel_set_models)
{
  // Radius 3: each tooth (8 voxels, 3 from the other) is no spur on its own, but is one
  // with the thresholds 3 times larger.
  auto pruned_with = [](const std::vector<std::array<double, 3>>* coarse) {
    return pruned_with_coarse_end_points<VoxelSet>(spine_with_two_teeth(), coarse, 4.0);
  };
  const Voxel_key tip_of_first_tooth{-2, 8, 0}, tip_of_second_tooth{1, 8, 0};
  const std::array<double, 3> first_end_of_spine{-9.5, 0.5, 0.5}, last_end_of_spine{10.5, 0.5, 0.5};

  const auto [alone, alone_report] = pruned_with(nullptr);
  BOOST_TEST(alone.count(tip_of_first_tooth) == 1u);
  BOOST_TEST(alone.count(tip_of_second_tooth) == 1u);

  // The coarser skeleton has one end between the two tips, 1 voxel from the first and 2
  // from the second (both within the tolerance of 4): it is paired with the first, and the
  // second tooth goes. With the end nearer the second tip, the first tooth goes.
  const std::vector<std::array<double, 3>> nearer_the_first{first_end_of_spine, last_end_of_spine, {-0.5, 8.5, 0.5}};
  const auto [first_kept, first_kept_report] = pruned_with(&nearer_the_first);
  BOOST_TEST(first_kept.count(tip_of_first_tooth) == 1u);
  BOOST_TEST(first_kept.count(Voxel_key{1, 2, 0}) == 0u);
  BOOST_TEST(first_kept_report.snipped_beyond_coarse_detail == 1u);
  BOOST_TEST(components_of(first_kept) == 1u);

  const std::vector<std::array<double, 3>> nearer_the_second{first_end_of_spine, last_end_of_spine, {0.5, 8.5, 0.5}};
  const auto [second_kept, second_kept_report] = pruned_with(&nearer_the_second);
  BOOST_TEST(second_kept.count(tip_of_second_tooth) == 1u);
  BOOST_TEST(second_kept.count(Voxel_key{-2, 2, 0}) == 0u);
  BOOST_TEST(second_kept_report.snipped_beyond_coarse_detail == 1u);
  BOOST_TEST(components_of(second_kept) == 1u);

  // A coarse end point near each tip: both teeth stay.
  const std::vector<std::array<double, 3>> one_per_tooth{first_end_of_spine, last_end_of_spine, {-1.5, 8.5, 0.5},
                                                         {1.5, 8.5, 0.5}};
  const auto [both, both_report] = pruned_with(&one_per_tooth);
  BOOST_TEST((both == alone));
  BOOST_TEST(both_report.snipped_beyond_coarse_detail == 0u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(an_end_branch_is_cut_back_to_where_the_coarser_skeleton_ends, VoxelSet,
                              Voxel_set_models)
{
  const auto pruned_with = pruned_with_coarse_end_points<VoxelSet>;
  const std::vector<Voxel_key> three_arms = thick_junction_with_three_arms();
  const std::set<Voxel_key> uncut = pruned_with(three_arms, nullptr, 2.0).first;
  // `uncut` without the voxels (0, y, 0) of the y arm (from (0, 2, 0) to (0, 8, 0)) past `y`.
  auto y_arm_up_to = [&](int y) {
    std::set<Voxel_key> expected = uncut;
    for(int past = y + 1; past <= 8; ++past)
      expected.erase(Voxel_key{0, past, 0});
    return expected;
  };

  // The coarser skeleton ends halfway along the y arm, 4 voxels from its tip: with a
  // tolerance of 2 the tip does not match it, but the arm runs on past it, and loses its
  // voxels past (0, 4, 0), the one nearest it. The x arms end on their coarse end points.
  const std::vector<std::array<double, 3>> ends_halfway{tip_of_plus_x_arm, tip_of_minus_x_arm, {0.5, 4.5, 0.5}};
  const auto [past, past_report] = pruned_with(three_arms, &ends_halfway, 2.0);
  BOOST_TEST((past == y_arm_up_to(4)));
  BOOST_TEST(past_report.cut_back_branches == 1u);
  BOOST_TEST(past_report.cut_back_points == 4u);
  BOOST_TEST(past_report.snipped_beyond_coarse_detail == 0u);

  // A coarse end point that the tip matches (2 voxels away) but that is nearer a voxel
  // further in: the tip reaches further than the coarser skeleton, and is cut back to it.
  const std::vector<std::array<double, 3>> near_the_tip{tip_of_plus_x_arm, tip_of_minus_x_arm, {0.5, 6.5, 0.5}};
  const auto [matched, matched_report] = pruned_with(three_arms, &near_the_tip, 2.5);
  BOOST_TEST((matched == y_arm_up_to(6)));
  BOOST_TEST(matched_report.cut_back_points == 2u);

  // A coarse end point on the face between two voxels, (0, 5, 0) and (0, 6, 0), is as near
  // both: the one nearer the tip stays, whichever way the rounding of a moved mesh tips it.
  for(const double y : {6.0, 6.0 + 1e-12, 6.0 - 1e-12})
  {
    const std::vector<std::array<double, 3>> on_a_face{tip_of_plus_x_arm, tip_of_minus_x_arm, {0.5, y, 0.5}};
    BOOST_TEST((pruned_with(three_arms, &on_a_face, 3.0).first == y_arm_up_to(6)));
  }

  // A coarse end point 2 voxels beside the y arm, farther than the tolerance (1) from every
  // voxel but inside the maximal balls (radius 3) of those near (0, 4, 0): the coarser grid
  // ended the arm there, across the part's thickness from the finer skeleton (as on the
  // mid-plane of a slab). The arm runs on past it, and is cut back to the voxel nearest it.
  const std::vector<std::array<double, 3>> beside_the_arm{tip_of_plus_x_arm, tip_of_minus_x_arm, {2.5, 4.5, 0.5}};
  const auto [in_a_ball, in_a_ball_report] = pruned_with(three_arms, &beside_the_arm, 1.0);
  BOOST_TEST((in_a_ball == y_arm_up_to(4)));
  BOOST_TEST(in_a_ball_report.cut_back_branches == 1u);

  // Coarse end points on the tips, or farther than the tolerance from every branch voxel
  // and outside their balls (5 voxels from the nearest), cut nothing.
  const std::vector<std::array<double, 3>> on_the_tips{tip_of_plus_x_arm, tip_of_minus_x_arm, tip_of_plus_y_arm};
  const auto [kept, kept_report] = pruned_with(three_arms, &on_the_tips, 2.0);
  BOOST_TEST((kept == uncut));
  BOOST_TEST(kept_report.cut_back_branches == 0u);
  const std::vector<std::array<double, 3>> off_the_arms{tip_of_plus_x_arm, tip_of_minus_x_arm, {5.5, 4.5, 0.5}};
  BOOST_TEST((pruned_with(three_arms, &off_the_arms, 2.0).first == uncut));

  // A path has no junction: its end that no coarse end point is near is cut back to the
  // coarse end point on the way, its other end stays.
  std::vector<Voxel_key> path;
  add_segment(path, Voxel_key{-10, 0, 0}, Voxel_key{1, 0, 0}, 21);
  const std::vector<std::array<double, 3>> start_and_middle{{-9.5, 0.5, 0.5}, {0.5, 0.5, 0.5}};
  const auto [shortened, shortened_report] = pruned_with(path, &start_and_middle, 2.0);
  std::set<Voxel_key> first_half;
  for(int x = -10; x <= 0; ++x)
    first_half.insert(Voxel_key{x, 0, 0});
  BOOST_TEST((shortened == first_half));
  BOOST_TEST(shortened_report.cut_back_points == 10u);

  // Coarse end points all along it: the path is cut back from its free end to the first one
  // met, never removed whole.
  const std::vector<std::array<double, 3>> along{{-9.5, 0.5, 0.5}, {4.5, 0.5, 0.5}, {-3.5, 0.5, 0.5}};
  const std::set<Voxel_key> to_the_first = pruned_with(path, &along, 2.0).first;
  BOOST_TEST(to_the_first.size() == 15u);
  BOOST_TEST(to_the_first.count(Voxel_key{4, 0, 0}) == 1u);
  BOOST_TEST(to_the_first.count(Voxel_key{5, 0, 0}) == 0u);

  // The coarser skeleton's two ends both near the path's -x end (a U whose ends lie close,
  // which the finer grid thinned straight): that end matches the one on its tip, and the +x
  // end runs on past the other (at -6.5, inside the balls of the voxels around it), but is
  // cut back at most to the path's middle, where no coarse end point is near. The path
  // stays whole; cut back to (-7, 0, 0), it would keep 4 of its 21 voxels.
  const std::vector<std::array<double, 3>> both_near_one_end{{-9.5, 0.5, 0.5}, {-6.5, 0.5, 0.5}};
  const auto [whole, whole_report] = pruned_with(path, &both_near_one_end, 2.0);
  BOOST_TEST(whole.size() == 21u);
  BOOST_TEST(whole_report.cut_back_branches == 0u);

  // A coarse end point just past the middle from the +x end: that end is cut back to the
  // middle voxel, (0, 0, 0), the nearest voxel of its half, and no further once that voxel
  // is its tip (the middle is the path's as it was before any cut).
  const std::vector<std::array<double, 3>> start_and_past_the_middle{{-9.5, 0.5, 0.5}, {-0.5, 0.5, 0.5}};
  const auto [to_the_middle, to_the_middle_report] = pruned_with(path, &start_and_past_the_middle, 2.0);
  BOOST_TEST((to_the_middle == first_half));
  BOOST_TEST(to_the_middle_report.cut_back_points == 10u);
}

// Four straight arms from a junction voxel at the origin: 8 voxels along +x, -x and -y,
// and a stub of 2 voxels along +y that the snipping takes.
std::vector<Voxel_key> plus_with_a_stub()
{
  std::vector<Voxel_key> v{Voxel_key{0, 0, 0}};
  add_segment(v, Voxel_key{1, 0, 0}, Voxel_key{1, 0, 0}, 8);
  add_segment(v, Voxel_key{-1, 0, 0}, Voxel_key{-1, 0, 0}, 8);
  add_segment(v, Voxel_key{0, -1, 0}, Voxel_key{0, -1, 0}, 8);
  add_segment(v, Voxel_key{0, 1, 0}, Voxel_key{0, 1, 0}, 2);
  return v;
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_snipped_branch_that_the_coarser_skeleton_ends_in_is_swapped_back_in, VoxelSet,
                              Voxel_set_models)
{
  auto pruned_with = [](const std::vector<std::array<double, 3>>* coarse) {
    return pruned_with_coarse_end_points<VoxelSet>(plus_with_a_stub(), coarse, 2.0);
  };
  const Voxel_key tip_of_stub{0, 2, 0}, tip_of_minus_y_arm{0, -8, 0};

  // Alone, the stub is snipped (shorter than 1.2 radii) and the -y arm stays.
  const auto [alone, alone_report] = pruned_with(nullptr);
  BOOST_TEST(alone.count(tip_of_stub) == 0u);
  BOOST_TEST(alone.count(tip_of_minus_y_arm) == 1u);
  BOOST_TEST(alone_report.swapped_for_coarse_end_branches == 0u);

  // The coarser skeleton ends in the stub and has no -y arm: as many end points, but not the
  // same ones. The stub comes back and the -y arm goes, all of it.
  const std::vector<std::array<double, 3>> stub_and_x_arms{tip_of_plus_x_arm, tip_of_minus_x_arm, {0.5, 2.5, 0.5}};
  const auto [swapped, swapped_report] = pruned_with(&stub_and_x_arms);
  BOOST_TEST(swapped.count(tip_of_stub) == 1u);
  BOOST_TEST(swapped.count(Voxel_key{0, 1, 0}) == 1u);
  for(int y = -8; y <= -1; ++y)
    BOOST_TEST(swapped.count(Voxel_key{0, y, 0}) == 0u);
  BOOST_TEST(swapped_report.swapped_for_coarse_end_branches == 1u);
  BOOST_TEST(swapped_report.snipped_beyond_coarse_detail == 0u);
  BOOST_TEST(components_of(swapped) == 1u);

  // When the coarser skeleton has the -y arm too, every end point matches: no swap, the
  // stub stays snipped.
  const std::vector<std::array<double, 3>> all_four{tip_of_plus_x_arm, tip_of_minus_x_arm, {0.5, 2.5, 0.5},
                                                    {0.5, -7.5, 0.5}};
  const auto [kept, kept_report] = pruned_with(&all_four);
  BOOST_TEST((kept == alone));
  BOOST_TEST(kept_report.swapped_for_coarse_end_branches == 0u);
}

BOOST_AUTO_TEST_CASE(absurd_parameters_give_clear_exceptions)
{
  gs::Sparse_voxel_set skeleton = voxel_set<gs::Sparse_voxel_set>(thick_junction_with_three_arms());
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::spur_length_factor(-1.0)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::spur_length_factor(std::nan(""))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::limb_protrusion_factor(-0.5)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::limb_protrusion_factor(std::nan(""))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::coarse_end_point_tolerance(-1.0)),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::coarse_end_point_tolerance(std::nan(""))),
                    std::invalid_argument);
  const std::vector<std::array<double, 3>> not_finite{{0.5, std::nan(""), 0.5}};
  const gs::Sparse_voxel_set before_the_throw = skeleton;
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::coarse_end_points(&not_finite)), std::invalid_argument);
  BOOST_TEST((contents(skeleton) == contents(before_the_throw)));
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::mat_radius_map(
                                                     CGAL::Constant_property_map<Voxel_key, double>(-2.0))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::sheet_radius_map(
                                                     CGAL::Constant_property_map<Voxel_key, double>(std::nan("")))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::piece_radius_map(
                                                     CGAL::Constant_property_map<Voxel_key, double>(-1.0))),
                    std::invalid_argument);
  BOOST_CHECK_THROW(gs::prune_skeleton(skeleton, gs::parameters::piece_radius_map(
                                                     CGAL::Constant_property_map<Voxel_key, double>(HUGE_VAL))),
                    std::invalid_argument);
  // A sheet radius map that refers to no radii reads 0 everywhere: the MAT radius judges.
  BOOST_TEST(get(gs::Sheet_radius_in_voxels_map{}, Voxel_key{1, 2, 3}) == 0.);
  gs::Sparse_voxel_set without_sheets = voxel_set<gs::Sparse_voxel_set>(thick_junction_with_three_arms());
  gs::Sparse_voxel_set by_mat_radius = without_sheets;
  gs::prune_skeleton(without_sheets, gs::parameters::sheet_radius_map(gs::Sheet_radius_in_voxels_map{}));
  gs::prune_skeleton(by_mat_radius);
  BOOST_TEST((contents(without_sheets) == contents(by_mat_radius)));
}

// The thinned voxel skeleton of a mesh, and its shape after to_graph(), before and after
// pruning with the MAT radius (in voxels) of its distance field.
struct Pruned_mesh_skeleton
{
  using Mesh = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  gs::Skeleton_point_counts thinned_points, pruned_points;
  gs::Skeleton_statistics thinned, pruned;

  Pruned_mesh_skeleton(const std::string& name, bool keep_surface_voxels,
                       int resolution = gs::default_voxel_resolution)
  {
    const Mesh mesh = Geodesic_skeleton_test::demo_mesh<Mesh>(name);
    gs::Sparse_voxel_set voxels;
    gs::voxelize(mesh, voxels, gs::parameters::combine(gs::parameters::keep_surface_voxels(keep_surface_voxels),
                                                       gs::parameters::resolution(resolution)));
    const gs::Voxel_distance_field field = gs::distance_transform(voxels);
    gs::Sheet_radii sheet_radii;
    // As extract_control_skeleton() thins: the parts thin at the default resolution are thin.
    gs::thin(voxels, field,
             gs::parameters::combine(
                 gs::parameters::sheet_radius_map(boost::associative_property_map<gs::Sheet_radii>(sheet_radii)),
                 gs::parameters::thin_part_radius(gs::default_thin_part_radius(resolution))));
    thinned_points = gs::count_skeleton_points(voxels);
    gs::Curve_skeleton<Mesh::Point, Mesh::Vertex_index> graph;
    gs::to_graph(voxels, field, mesh, graph);
    thinned = gs::skeleton_statistics(graph);
    // As extract_control_skeleton() prunes: by the MAT radius, or a sheet's half width.
    gs::prune_skeleton(voxels,
                       gs::parameters::combine(gs::parameters::mat_radius_map(gs::mat_radius_in_voxels_map(field)),
                                               gs::parameters::sheet_radius_map(gs::sheet_radius_in_voxels_map(sheet_radii))));
    pruned_points = gs::count_skeleton_points(voxels);
    gs::to_graph(voxels, field, mesh, graph);
    pruned = gs::skeleton_statistics(graph);
  }
};

// A thin plate (one, two or three voxels thick) with bumps along its rim, as a wing or a
// fin voxelizes: thinning burns it from the rim like a fire in the plane, and every bump
// leaves an end point (its medial ball, of the plate's half thickness, is maximal). Judged
// by that MAT radius, the twigs from the bumps to the middle line are tens of radii long
// and stay (11 to 29 end points here); judged by the plate's half width, which thin()
// measures (the sheet radius), they are spurs, and the middle line is left. The bumps are
// as wide as the plate is thick, or 2 voxels: narrower ones burn away whole, twig and all.
// Two voxels thick, the plate thinned layer by layer in index order before thin parts
// burnt by face direction, and kept a tangle that no radius prunes (7 end points).
BOOST_AUTO_TEST_CASE_TEMPLATE(a_thin_sheet_is_pruned_by_its_width, VoxelSet, Voxel_set_models)
{
  const int length = 60, width = 30, bump_period = 6;
  for(int thickness : {1, 2, 3})
  {
    const int bump_width = (std::max)(thickness, 2);
    VoxelSet plate;
    plate.reset(gs::Voxel_frame(), gs::Voxel_box{Voxel_key{-3, -3, 0}, Voxel_key{length + 3, width + 3, thickness}});
    for(int z = 0; z < thickness; ++z)
      for(int y = -2; y < width + 2; ++y)
        for(int x = -2; x < length + 2; ++x)
        {
          const bool in_x = x >= 0 && x < length, in_y = y >= 0 && y < width;
          const bool bump = (in_x && !in_y && x % bump_period < bump_width) ||
                            (in_y && !in_x && y % bump_period < bump_width);
          if((in_x && in_y) || bump)
            plate.insert(Voxel_key{x, y, z});
        }
    const gs::Voxel_distance_field distances = gs::distance_transform(plate);
    gs::Sheet_radii sheet_radii;
    gs::thin(plate, distances,
             gs::parameters::sheet_radius_map(boost::associative_property_map<gs::Sheet_radii>(sheet_radii)));
    VoxelSet by_thickness = plate;
    gs::prune_skeleton(by_thickness, gs::parameters::mat_radius_map(gs::mat_radius_in_voxels_map(distances)));
    gs::prune_skeleton(plate,
                       gs::parameters::combine(gs::parameters::mat_radius_map(gs::mat_radius_in_voxels_map(distances)),
                                               gs::parameters::sheet_radius_map(gs::sheet_radius_in_voxels_map(sheet_radii))));
    BOOST_TEST(gs::count_skeleton_points(by_thickness).end > 10u, "thickness " << thickness);
    BOOST_TEST(gs::count_skeleton_points(plate).end <= 3u, "thickness " << thickness);
    BOOST_TEST(gs::count_skeleton_points(plate).total() >= std::size_t(length - width), "thickness " << thickness);
  }
}

BOOST_AUTO_TEST_CASE(pruning_keeps_the_components_and_the_handles_of_real_shapes)
{
  for(const char* name : {"eight.off", "double-torus-example.off", "elephant.off", "cow.off"})
  {
    const Pruned_mesh_skeleton s(name, true);
    BOOST_TEST(s.pruned.components == s.thinned.components, name);
    BOOST_TEST(s.pruned.cycles == s.thinned.cycles, name);
  }
}

// An end branch traced through a lump of branched points takes the lump with it when it is
// snipped; the voxels tucked into the lump (all their neighbours in it) go too. They were
// left behind before, as isolated voxels that the control skeleton made extra roots of: at
// 128, 22 of the 125 demo meshes lost their connectedness so, 6 at 64 (hand.off: 4 pieces
// at 128, spool.off and anchor.off: 5, lion.off: 3).
BOOST_AUTO_TEST_CASE(pruning_never_leaves_isolated_voxels_at_a_fine_resolution)
{
  for(const char* name : {"hand.off", "spool.off", "anchor.off", "lion.off"})
  {
    const Pruned_mesh_skeleton s(name, true, 128);
    BOOST_TEST(s.thinned.components == 1u, name);
    BOOST_TEST(s.pruned.components == 1u, name);
    BOOST_TEST(s.pruned_points.isolated == 0u, name);
  }
}

BOOST_AUTO_TEST_CASE(pruning_leaves_no_more_branched_points_and_one_end_per_limb)
{
  // Ends of the pruned skeleton at the default resolution, counted on the pictures of
  // scripts/make_figures.sh. With the level of detail (limb_protrusion_factor 0.75): cow 5
  // (4 legs and head; its horns, ears, udder and thin tail reach out less than 0.75 of its
  // body's radius; a sixth end was a one-voxel stub at the tail's root until the snipping
  // looked at the graph's end branches); dino 7 (4 legs, tail, head, a crest spike); elephant 6 (the trunk, one chain
  // through each ear, three legs; the rest of the rear is in the loops of its handles; 10
  // before the graph's end branches were snipped: the ear chains had a twig or two at
  // their base). The camel's legs come within a voxel of each
  // other and its solid gets false loops unless the surface voxels whose centre is outside
  // are peeled (keep_surface_voxels(false)); then it has 4 legs and a head (its thin tail
  // is under the level of detail). Without the level of detail, the length test alone
  // leaves cow 11, dino 8, elephant 15 (the rims of its ears).
  // The elephant's mesh has three handles (V - E + F = -4), the others none; at this
  // resolution the solid keeps two of them (the third's hole is about a voxel wide and
  // closes: see real_handles_are_kept in test_cut_spurious_cycles.cpp).
  struct Expected { const char* mesh; bool keep_surface_voxels; std::size_t min_ends, max_ends, cycles; };
  for(const Expected& x : {Expected{"cow.off", true, 5, 6, 0}, Expected{"dino.off", true, 6, 8, 0},
                           Expected{"elephant.off", true, 6, 10, 2}, Expected{"camel.off", false, 5, 7, 0}})
  {
    const Pruned_mesh_skeleton s(x.mesh, x.keep_surface_voxels);
    BOOST_TEST(s.pruned_points.branched_connection <= s.thinned_points.branched_connection, x.mesh);
    BOOST_TEST(s.pruned.components == 1u, x.mesh);
    BOOST_TEST(s.pruned.cycles == x.cycles, x.mesh);
    BOOST_TEST(s.pruned.end_points >= x.min_ends, x.mesh);
    BOOST_TEST(s.pruned.end_points <= x.max_ends, x.mesh);
  }
}

// A T of square bars 5 voxels thick: a crossbar along x (|x| <= 15, |y| <= 2) and a leg
// along +y (|x| <= 2, 3 <= y <= 15), both |z| <= 2; and, with `island`, a cube apart.
template <typename VoxelSet>
VoxelSet t_shaped_solid(bool island)
{
  std::vector<Voxel_key> v;
  for(int z = -2; z <= 2; ++z)
    for(int y = -2; y <= 15; ++y)
      for(int x = -15; x <= 15; ++x)
        if(std::abs(y) <= 2 || std::abs(x) <= 2)
          v.push_back(Voxel_key{x, y, z});
  if(island)
    for(int z = 10; z <= 14; ++z)
      for(int y = -14; y <= -10; ++y)
        for(int x = 10; x <= 14; ++x)
          v.push_back(Voxel_key{x, y, z});
  return voxel_set<VoxelSet>(v);
}

// Whether the voxels of `set` are one 26-connected piece.
template <typename VoxelSet>
bool is_one_piece(const VoxelSet& set)
{
  const std::set<Voxel_key> all = contents(set);
  std::set<Voxel_key> seen{*all.begin()};
  std::vector<Voxel_key> stack{*all.begin()};
  while(!stack.empty())
  {
    const Voxel_key k = stack.back();
    stack.pop_back();
    for(const Voxel_key& o : gs::neighbourhood_26())
      if(all.count(k + o) != 0 && seen.insert(k + o).second)
        stack.push_back(k + o);
  }
  return seen.size() == all.size();
}

BOOST_AUTO_TEST_CASE_TEMPLATE(the_limb_the_coarser_skeleton_ends_in_is_grafted_along_the_middle, VoxelSet,
                              Voxel_set_models)
{
  // The skeleton of the T's crossbar lacks the leg, which the coarser skeleton ends in: a
  // branch is grafted from the coarse end point to the crossbar's chain, inside the solid
  // and along the leg's axis, and the graph gets the coarser skeleton's three end points.
  const VoxelSet solid = t_shaped_solid<VoxelSet>(true);
  const gs::Voxel_distance_field distances = gs::distance_transform(solid);
  std::vector<Voxel_key> crossbar;
  add_segment(crossbar, Voxel_key{-12, 0, 0}, Voxel_key{1, 0, 0}, 25);
  const std::vector<std::array<double, 3>> ends{{-11.5, 0.5, 0.5}, {12.5, 0.5, 0.5}, {0.5, 13.5, 0.5}};

  VoxelSet skeleton = voxel_set<VoxelSet>(crossbar);
  BOOST_TEST(gs::graft_coarse_end_branches(skeleton, distances, ends) == 1u);
  BOOST_TEST(gs::internal::graph_end_points(skeleton).size() == 3u);
  BOOST_TEST(skeleton.contains(Voxel_key{0, 13, 0})); // the voxel holding the coarse end point
  BOOST_TEST(is_one_piece(skeleton));
  std::size_t grafted = 0;
  skeleton.for_each([&](const Voxel_key& k) {
    BOOST_TEST(distances.inside(k));
    if(k.y > 2) // on the leg: on its axis, not along a side
    {
      BOOST_TEST(std::abs(k.x) <= 1);
      BOOST_TEST(std::abs(k.z) <= 1);
      ++grafted;
    }
  });
  BOOST_TEST(grafted >= 11u);
  // Done once, nothing is left to graft.
  BOOST_TEST(gs::graft_coarse_end_branches(skeleton, distances, ends) == 0u);

  // As many end points as the coarser skeleton: nothing is grafted, even where it ends.
  VoxelSet as_many = voxel_set<VoxelSet>(crossbar);
  const std::vector<std::array<double, 3>> two_ends{{-11.5, 0.5, 0.5}, {0.5, 13.5, 0.5}};
  BOOST_TEST(gs::graft_coarse_end_branches(as_many, distances, two_ends) == 0u);
  BOOST_TEST(contents(as_many) == contents(voxel_set<VoxelSet>(crossbar)));

  // A coarse end point that the skeleton passes near (within the tolerance, or the MAT
  // radius there), outside the solid (near it, or beyond any grid), or in a piece without
  // skeleton gets no branch.
  for(const std::array<double, 3>& lacked : {std::array<double, 3>{0.5, 3.5, 0.5}, std::array<double, 3>{10.5, 10.5, 0.5},
                                             std::array<double, 3>{1e300, -1e300, 0.5},
                                             std::array<double, 3>{12.5, -11.5, 12.5}})
  {
    VoxelSet unchanged = voxel_set<VoxelSet>(crossbar);
    BOOST_TEST(gs::graft_coarse_end_branches(unchanged, distances, {ends[0], ends[1], lacked}) == 0u);
    BOOST_TEST(contents(unchanged) == contents(voxel_set<VoxelSet>(crossbar)));
  }
  // Within a larger tolerance, the crossbar passes near enough to the leg's end point.
  VoxelSet tolerant = voxel_set<VoxelSet>(crossbar);
  BOOST_TEST(gs::graft_coarse_end_branches(tolerant, distances, ends, gs::parameters::coarse_end_point_tolerance(14)) == 0u);

  // A coarse end point farther than the search's first window (33 voxels wide): the window
  // grows, and the graft meeting the skeleton at its end carries that branch on along the
  // bar's axis, without a new end point.
  std::vector<Voxel_key> bar_voxels;
  add_box(bar_voxels, Voxel_key{-19, -2, -2}, Voxel_key{19, 2, 2});
  const gs::Voxel_distance_field bar = gs::distance_transform(voxel_set<VoxelSet>(bar_voxels));
  std::vector<Voxel_key> stub;
  add_segment(stub, Voxel_key{-17, 0, 0}, Voxel_key{1, 0, 0}, 3);
  VoxelSet carried_on = voxel_set<VoxelSet>(stub);
  const std::vector<std::array<double, 3>> bar_ends{{-16.5, 0.5, 0.5}, {-14.5, 0.5, 0.5}, {17.5, 0.5, 0.5}};
  BOOST_TEST(gs::graft_coarse_end_branches(carried_on, bar, bar_ends) == 1u);
  std::vector<Voxel_key> axis;
  add_segment(axis, Voxel_key{-17, 0, 0}, Voxel_key{1, 0, 0}, 35);
  BOOST_TEST(contents(carried_on) == contents(voxel_set<VoxelSet>(axis)));

  VoxelSet bad = voxel_set<VoxelSet>(crossbar);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BOOST_CHECK_THROW(gs::graft_coarse_end_branches(bad, distances, {ends[0], ends[1], {0.5, nan, 0.5}}), std::invalid_argument);
  BOOST_CHECK_THROW(gs::graft_coarse_end_branches(bad, distances, ends, gs::parameters::coarse_end_point_tolerance(-1)),
                    std::invalid_argument);
  BOOST_TEST(contents(bad) == contents(voxel_set<VoxelSet>(crossbar)));
}

// A slab 37 voxels wide and 9 thick, as a thick, flat part (a dome, a lens) is: its medial
// surface is a sheet, the plane z = 0, on which thinning may leave any curve.
std::vector<Voxel_key> slab_voxels()
{
  std::vector<Voxel_key> v;
  add_box(v, Voxel_key{-18, -18, -4}, Voxel_key{18, 18, 4});
  return v;
}

// A lone path on the slab's middle plane from (10, -3, 0) to (10, 3, 0) that detours as a
// U to x = -15 and back.
std::vector<Voxel_key> u_across_the_slab()
{
  std::vector<Voxel_key> u;
  add_segment(u, Voxel_key{10, -3, 0}, Voxel_key{-1, 0, 0}, 25);
  add_segment(u, Voxel_key{-15, -2, 0}, Voxel_key{0, 1, 0}, 5);
  add_segment(u, Voxel_key{-14, 3, 0}, Voxel_key{1, 0, 0}, 25);
  return u;
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_lone_path_that_detours_across_a_thick_sheet_is_routed_through_the_middle, VoxelSet,
                              Voxel_set_models)
{
  const gs::Voxel_distance_field slab = gs::distance_transform(voxel_set<VoxelSet>(slab_voxels()));
  const std::vector<Voxel_key> u = u_across_the_slab();

  // The U costs 9.4 times the straight path between its ends along the middle plane (12.5
  // and 1.33 MAT radii): it is replaced by that path, and the ends stay.
  VoxelSet routed = voxel_set<VoxelSet>(u);
  BOOST_TEST(gs::internal::graph_end_points(routed).size() == 2u);
  BOOST_TEST(gs::route_lone_paths_through_the_middle(routed, slab) == 1u);
  std::vector<Voxel_key> straight;
  add_segment(straight, Voxel_key{10, -3, 0}, Voxel_key{0, 1, 0}, 7);
  BOOST_TEST(contents(routed) == contents(voxel_set<VoxelSet>(straight)));
  // Routed once, it is the path through the middle: nothing changes any more.
  BOOST_TEST(gs::route_lone_paths_through_the_middle(routed, slab) == 0u);
  BOOST_TEST(contents(routed) == contents(voxel_set<VoxelSet>(straight)));

  // A factor larger than the detour, or 0, leaves the U.
  for(const double factor : {0.0, 10.0})
  {
    VoxelSet kept = voxel_set<VoxelSet>(u);
    BOOST_TEST(gs::route_lone_paths_through_the_middle(kept, slab, gs::parameters::lone_path_detour_factor(factor)) == 0u);
    BOOST_TEST(contents(kept) == contents(voxel_set<VoxelSet>(u)));
  }
  // A factor just under the detour routes it.
  VoxelSet routed_at_9 = voxel_set<VoxelSet>(u);
  BOOST_TEST(gs::route_lone_paths_through_the_middle(routed_at_9, slab, gs::parameters::lone_path_detour_factor(9)) == 1u);

  // With a branch, the U is no lone path: unchanged.
  std::vector<Voxel_key> branched = u;
  add_segment(branched, Voxel_key{0, -4, 0}, Voxel_key{0, -1, 0}, 8);
  VoxelSet with_branch = voxel_set<VoxelSet>(branched);
  BOOST_TEST(gs::route_lone_paths_through_the_middle(with_branch, slab) == 0u);
  BOOST_TEST(contents(with_branch) == contents(voxel_set<VoxelSet>(branched)));

  // A path through the middle that would touch another piece of the skeleton (here a
  // crossing the whole thickness where it passes) would join the two: the U stays.
  std::vector<Voxel_key> blocked = u;
  add_segment(blocked, Voxel_key{10, 0, -4}, Voxel_key{0, 0, 1}, 9);
  VoxelSet with_crossing = voxel_set<VoxelSet>(blocked);
  gs::route_lone_paths_through_the_middle(with_crossing, slab);
  for(const Voxel_key& k : u)
    BOOST_TEST(with_crossing.contains(k));

  // Along a bent part (a U-shaped tube), the path bends with the part: the straight segment
  // between its ends leaves the solid, and the path stays, even at the factor 1.
  std::vector<Voxel_key> tube_voxels;
  add_box(tube_voxels, Voxel_key{-10, -6, -2}, Voxel_key{10, -2, 2});
  add_box(tube_voxels, Voxel_key{-15, -6, -2}, Voxel_key{-11, 6, 2});
  add_box(tube_voxels, Voxel_key{-10, 2, -2}, Voxel_key{10, 6, 2});
  const gs::Voxel_distance_field tube = gs::distance_transform(voxel_set<VoxelSet>(tube_voxels));
  std::vector<Voxel_key> bent;
  add_segment(bent, Voxel_key{10, -4, 0}, Voxel_key{-1, 0, 0}, 23);
  add_segment(bent, Voxel_key{-13, -3, 0}, Voxel_key{0, 1, 0}, 7);
  add_segment(bent, Voxel_key{-12, 4, 0}, Voxel_key{1, 0, 0}, 23);
  VoxelSet along_the_tube = voxel_set<VoxelSet>(bent);
  BOOST_TEST(gs::internal::graph_end_points(along_the_tube).size() == 2u);
  BOOST_TEST(gs::route_lone_paths_through_the_middle(along_the_tube, tube, gs::parameters::lone_path_detour_factor(1)) == 0u);
  BOOST_TEST(contents(along_the_tube) == contents(voxel_set<VoxelSet>(bent)));

  // Along a bar, a straight lone path is the path through the middle: unchanged.
  std::vector<Voxel_key> bar_voxels;
  add_box(bar_voxels, Voxel_key{-17, -2, -2}, Voxel_key{17, 2, 2});
  const gs::Voxel_distance_field bar = gs::distance_transform(voxel_set<VoxelSet>(bar_voxels));
  std::vector<Voxel_key> axis;
  add_segment(axis, Voxel_key{-15, 0, 0}, Voxel_key{1, 0, 0}, 31);
  VoxelSet along_the_bar = voxel_set<VoxelSet>(axis);
  BOOST_TEST(gs::route_lone_paths_through_the_middle(along_the_bar, bar, gs::parameters::lone_path_detour_factor(1)) == 0u);
  BOOST_TEST(contents(along_the_bar) == contents(voxel_set<VoxelSet>(axis)));

  VoxelSet bad = voxel_set<VoxelSet>(u);
  for(const double factor : {-1.0, 1001.0, std::numeric_limits<double>::quiet_NaN()})
    BOOST_CHECK_THROW(gs::route_lone_paths_through_the_middle(bad, slab, gs::parameters::lone_path_detour_factor(factor)),
                      std::invalid_argument);
  BOOST_TEST(contents(bad) == contents(voxel_set<VoxelSet>(u)));
}

BOOST_AUTO_TEST_SUITE_END()
