// Specification of CGAL/Geodesic_skeleton/thin.h (and of its simple-point test).
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/internal/thin/simple_point.h>
#include <CGAL/Geodesic_skeleton/reach_sheet_lobes.h>
#include <CGAL/Geodesic_skeleton/thin.h>

#include <Geodesic_skeleton_test/characters.h>
#include <Geodesic_skeleton_test/voxel_skeleton.h>

#include <boost/mpl/list.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

BOOST_AUTO_TEST_SUITE(thin)

namespace gs = CGAL::Geodesic_skeleton;
namespace test = Geodesic_skeleton_test;

namespace {

using Voxel_set_models = boost::mpl::list<gs::Dense_voxel_grid, gs::Sparse_voxel_set>;

using Geodesic_skeleton_test::voxels_where;

// Topology of a set, independently of the package: 26-components, cavities (6-components
// of the background minus the outer one) and Euler characteristic.
struct Topology
{
  int components, cavities;
  long euler;
  bool operator==(const Topology& o) const
  {
    return components == o.components && cavities == o.cavities && euler == o.euler;
  }
};

// Adds to `seen` the 6-component of `start` through the voxels where `in_region(k)` holds.
template <typename Region>
void flood_6(const gs::Voxel_key& start, Region in_region, std::set<gs::Voxel_key>& seen)
{
  std::vector<gs::Voxel_key> stack{start};
  seen.insert(start);
  while(!stack.empty())
  {
    const gs::Voxel_key k = stack.back();
    stack.pop_back();
    for(const gs::Voxel_key& o : gs::neighbourhood_26())
    {
      const gs::Voxel_key n = k + o;
      if(gs::offset_order(o) == 1 && in_region(n) && seen.insert(n).second)
        stack.push_back(n);
    }
  }
}

template <typename VoxelSet>
int background_components_6(const VoxelSet& s, const gs::Voxel_box& box)
{
  auto in_background = [&](const gs::Voxel_key& k) { return box.contains(k) && !s.contains(k); };
  std::set<gs::Voxel_key> seen;
  int count = 0;
  for(int z = box.min.z; z < box.max.z; ++z)
    for(int y = box.min.y; y < box.max.y; ++y)
      for(int x = box.min.x; x < box.max.x; ++x)
      {
        const gs::Voxel_key start{x, y, z};
        if(!in_background(start) || seen.count(start))
          continue;
        ++count;
        flood_6(start, in_background, seen);
      }
  return count;
}

template <typename VoxelSet>
Topology topology(const VoxelSet& s, const gs::Voxel_box& box_with_margin)
{
  return Topology{test::components_26(s), background_components_6(s, box_with_margin) - 1,
                  test::euler_characteristic(s)};
}

// `count` random configurations, of densities from sparse to full in turn, so that both
// answers of a test are frequent.
std::vector<std::uint32_t> random_configurations(unsigned seed, int count)
{
  std::mt19937 random(seed);
  std::vector<std::uint32_t> configs;
  for(int trial = 0; trial < count; ++trial)
  {
    const unsigned density = 1 + trial % 7;
    std::uint32_t config = 0;
    for(int b = 0; b < 26; ++b)
      if(random() % 8 < density)
        config |= 1u << b;
    configs.push_back(config);
  }
  return configs;
}

// The voxels of a configuration around the origin (the centre itself not included).
gs::Sparse_voxel_set neighbours_of(std::uint32_t config)
{
  gs::Sparse_voxel_set around;
  for(int b = 0; b < 26; ++b)
    if(config & (1u << b))
      around.insert(gs::neighbourhood_26()[b]);
  return around;
}

// Simple by definition: deleting the centre of a 5x5x5 block holding the configuration
// changes neither the components, nor the cavities, nor the Euler characteristic.
bool simple_by_definition(std::uint32_t config)
{
  const gs::Voxel_box block{gs::Voxel_key{-2, -2, -2}, gs::Voxel_key{3, 3, 3}};
  const gs::Sparse_voxel_set without = neighbours_of(config);
  gs::Sparse_voxel_set with = without;
  with.insert(gs::Voxel_key{0, 0, 0});
  if(without.size() == 0)
    return false;
  return topology(with, block) == topology(without, block);
}

template <typename VoxelSet>
std::uint32_t configuration(const VoxelSet& s, const gs::Voxel_key& k)
{
  std::uint32_t config = 0;
  for(int b = 0; b < 26; ++b)
    if(s.contains(k + gs::neighbourhood_26()[b]))
      config |= 1u << b;
  return config;
}

// T6 by definition: the 6-components of the background in the 18-neighbourhood (centre
// excluded) that hold a face neighbour of the centre, grown through that background only.
int t6_by_definition(std::uint32_t config)
{
  std::set<gs::Voxel_key> background;
  for(int b = 0; b < 26; ++b)
    if(!(config & (1u << b)) && gs::offset_order(gs::neighbourhood_26()[b]) <= 2)
      background.insert(gs::neighbourhood_26()[b]);
  auto in_background = [&](const gs::Voxel_key& k) { return background.count(k) != 0; };
  std::set<gs::Voxel_key> seen;
  int count = 0;
  for(const gs::Voxel_key& start : background)
    if(gs::offset_order(start) == 1 && !seen.count(start))
    {
      ++count;
      flood_6(start, in_background, seen);
    }
  return count;
}

template <typename VoxelSet>
void thin_set(VoxelSet& s)
{
  const auto field = gs::distance_transform(s);
  gs::thin(s, field);
}

} // namespace

BOOST_AUTO_TEST_CASE(the_simple_point_test_agrees_with_the_definition)
{
  const auto& test = gs::internal::Simple_point_test::instance();
  int simple = 0, checked = 0;
  for(const std::uint32_t config : random_configurations(5, 3000))
  {
    const bool expected = simple_by_definition(config);
    BOOST_TEST(test.is_simple(config) == expected, "configuration " << config);
    simple += expected;
    ++checked;
  }
  BOOST_TEST(simple > checked / 10);
  BOOST_TEST(simple < checked * 9 / 10);
  BOOST_TEST(!test.is_simple(0));                 // isolated
  BOOST_TEST(!test.is_simple((1u << 26) - 1));    // interior
  BOOST_TEST(test.is_simple(1u << 4));            // curve end
  BOOST_TEST(!test.is_simple((1u << 4) | (1u << 21))); // middle of a curve
}

BOOST_AUTO_TEST_CASE(the_p_simple_test_agrees_with_its_definition)
{
  // x is P-simple iff it stays simple whatever subset of P is deleted with it: every
  // subset of P (at most 2^8 of them here) checked with is_simple(), which the test above
  // checks against the definition.
  const auto& test = gs::internal::Simple_point_test::instance();
  std::mt19937 random(17);
  int p_simple = 0, simple_not_p_simple = 0, checked = 0;
  for(const std::uint32_t config : random_configurations(13, 3000))
  {
    std::uint32_t in_p = 0;
    for(std::uint32_t bits = config; bits != 0 && gs::internal::bit_count(in_p) < 8; bits &= bits - 1)
      if(random() % 3 == 0)
        in_p |= bits & (~bits + 1u);
    bool expected = true;
    for(std::uint32_t deleted = in_p;; deleted = (deleted - 1) & in_p)
    {
      expected = expected && test.is_simple(config & ~deleted);
      if(deleted == 0)
        break;
    }
    BOOST_TEST(test.is_p_simple(config, in_p) == expected, "configuration " << config << ", P " << in_p);
    p_simple += expected;
    simple_not_p_simple += !expected && test.is_simple(config);
    ++checked;
  }
  BOOST_TEST(p_simple > checked / 20);
  BOOST_TEST(simple_not_p_simple > checked / 100); // the cases where P-simple is the stronger
  BOOST_TEST(test.is_p_simple(1u << 4, 0u));          // a curve end, P empty: simple
  BOOST_TEST(!test.is_p_simple(1u << 4, 1u << 4));    // a two-voxel piece both in P
}

BOOST_AUTO_TEST_CASE(the_peeling_tests_agree_with_their_definitions)
{
  // object_is_split: T26 >= 2 (the object's voxels around the centre fall apart);
  // background_is_one_piece: T6 = 1.
  const auto& test = gs::internal::Simple_point_test::instance();
  int split = 0, one_piece = 0;
  for(const std::uint32_t config : random_configurations(11, 3000))
  {
    const gs::Sparse_voxel_set around = neighbours_of(config);
    const bool expected_split = around.size() > 0 && test::components_26(around) >= 2;
    const bool expected_one_piece = t6_by_definition(config) == 1;
    BOOST_TEST(test.object_is_split(config) == expected_split, "configuration " << config);
    BOOST_TEST(test.background_is_one_piece(config) == expected_one_piece, "configuration " << config);
    split += expected_split;
    one_piece += expected_one_piece;
  }
  BOOST_TEST(split > 100);
  BOOST_TEST(split < 2900);
  BOOST_TEST(one_piece > 100);
  BOOST_TEST(one_piece < 2900);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_ball_thins_to_one_voxel, VoxelSet, Voxel_set_models)
{
  const gs::Voxel_box box{gs::Voxel_key{-9, -9, -9}, gs::Voxel_key{10, 10, 10}};
  VoxelSet s = voxels_where<VoxelSet>(box, [](int x, int y, int z) { return x * x + y * y + z * z <= 64; });
  thin_set(s);
  BOOST_TEST(s.size() == 1u);
  s.for_each([](const gs::Voxel_key& k) { BOOST_TEST(std::abs(k.x) + std::abs(k.y) + std::abs(k.z) <= 1); });
}

BOOST_AUTO_TEST_CASE_TEMPLATE(topology_is_kept, VoxelSet, Voxel_set_models)
{
  const gs::Voxel_box box{gs::Voxel_key{-16, -16, -8}, gs::Voxel_key{17, 17, 9}};
  auto solid_torus = [](int x, int y, int z) {
    const double d = std::hypot(double(x), double(y)) - 10.;
    return d * d + z * z <= 16.;
  };
  auto two_balls = [](int x, int y, int z) {
    return (x - 8) * (x - 8) + y * y + z * z <= 25 || (x + 8) * (x + 8) + y * y + z * z <= 25;
  };
  auto shell = [](int x, int y, int z) { // a ball with a cavity
    const int r2 = x * x + y * y + z * z;
    return r2 <= 49 && r2 > 16;
  };
  auto two_tunnels = [](int x, int y, int z) { // a slab pierced twice
    return std::abs(z) <= 3 && std::abs(x) <= 14 && std::abs(y) <= 6 &&
           !((x - 7) * (x - 7) + y * y <= 9) && !((x + 7) * (x + 7) + y * y <= 9);
  };
  for(const auto& shape : {std::function<bool(int, int, int)>(solid_torus), std::function<bool(int, int, int)>(two_balls),
                           std::function<bool(int, int, int)>(shell), std::function<bool(int, int, int)>(two_tunnels)})
  {
    VoxelSet s = voxels_where<VoxelSet>(box, shape);
    const Topology before = topology(s, box.grown(1));
    thin_set(s);
    const Topology after = topology(s, box.grown(1));
    BOOST_TEST(before.components == after.components);
    BOOST_TEST(before.cavities == after.cavities);
    BOOST_TEST(before.euler == after.euler);
  }
  VoxelSet torus = voxels_where<VoxelSet>(box, solid_torus);
  thin_set(torus);
  BOOST_TEST(test::euler_characteristic(torus) == 0); // one cycle, one component
}

BOOST_AUTO_TEST_CASE_TEMPLATE(the_result_is_thin, VoxelSet, Voxel_set_models)
{
  const gs::Voxel_box box{gs::Voxel_key{-20, -12, -12}, gs::Voxel_key{21, 13, 13}};
  // A "T" of two bars of different thickness.
  VoxelSet s = voxels_where<VoxelSet>(box, [](int x, int y, int z) {
    return (std::abs(x) <= 18 && y * y + z * z <= 16) || (x >= 0 && x <= 6 && std::abs(y) <= 11 && std::abs(z) <= 2);
  });
  thin_set(s);
  const auto& test = gs::internal::Simple_point_test::instance();
  int removable = 0;
  s.for_each([&](const gs::Voxel_key& k) {
    const std::uint32_t c = configuration(s, k);
    removable += test.is_simple(c) && gs::internal::bit_count(c) != 1;
  });
  BOOST_TEST(removable == 0);
  BOOST_TEST(s.size() > 20u);
  BOOST_TEST(s.size() < 80u);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(a_bar_thins_to_its_axis, VoxelSet, Voxel_set_models)
{
  // A cylinder of radius 6 voxels along x, from x = 0 to 59 (centres on the axis y = z = 0).
  const gs::Voxel_box box{gs::Voxel_key{0, -7, -7}, gs::Voxel_key{60, 8, 8}};
  VoxelSet s = voxels_where<VoxelSet>(box, [](int, int y, int z) { return y * y + z * z <= 36; });
  thin_set(s);
  int min_x = 1000, max_x = -1000;
  s.for_each([&](const gs::Voxel_key& k) {
    BOOST_TEST(std::hypot(double(k.y), double(k.z)) <= 1.0);
    min_x = std::min(min_x, k.x);
    max_x = std::max(max_x, k.x);
  });
  BOOST_TEST(min_x <= 7); // ends within about a radius of the caps
  BOOST_TEST(max_x >= 52);
  BOOST_TEST(test::components_26(s) == 1);
}

// The sheet radius (Voxel_skeleton::sheet_radii): in a sheet one voxel thick, where the MAT
// radius is half a voxel everywhere, the kept middle line gets the sheet's half width, the
// number of rounds its level burnt from the rim; in a bar, whose levels are shells, nothing.
BOOST_AUTO_TEST_CASE_TEMPLATE(thin_measures_the_half_width_of_a_thin_sheet, VoxelSet, Voxel_set_models)
{
  const int length = 60, width = 30;
  VoxelSet sheet = voxels_where<VoxelSet>(gs::Voxel_box{gs::Voxel_key{0, 0, 0}, gs::Voxel_key{length, width, 1}},
                                          [](int, int, int) { return true; });
  const gs::Voxel_distance_field sheet_distances = gs::distance_transform(sheet);
  gs::Voxel_skeleton skeleton;
  gs::thin(sheet, sheet_distances, skeleton);
  const gs::Sheet_radii& radii = skeleton.sheet_radii;
  BOOST_TEST(radii.size() == sheet.size()); // one radius per voxel kept
  BOOST_TEST((test::keys_of(skeleton.voxels) == test::keys_of(sheet)));
  BOOST_TEST(skeleton.radius_voxel_size == sheet.frame().voxel_size());
  int middle = 0;
  sheet.for_each([&](const gs::Voxel_key& k) {
    BOOST_TEST(get(gs::mat_radius_in_voxels_map(sheet_distances), k) < 1.);
    if(k.x < 20 || k.x >= 40)
      return;
    ++middle;
    BOOST_TEST(std::abs(k.y - (width - 1) / 2.) <= 1.);
    BOOST_TEST(radii.at(k) >= width / 2. - 2.);
    BOOST_TEST(radii.at(k) <= width / 2. + 1.);
  });
  BOOST_TEST(middle == 20); // one voxel per column

  VoxelSet bar = voxels_where<VoxelSet>(gs::Voxel_box{gs::Voxel_key{0, -7, -7}, gs::Voxel_key{40, 8, 8}},
                                        [](int, int y, int z) { return y * y + z * z <= 25; });
  const gs::Voxel_distance_field bar_distances = gs::distance_transform(bar);
  gs::thin(bar, bar_distances, skeleton);
  BOOST_TEST(radii.size() == bar.size());
  bar.for_each([&](const gs::Voxel_key& k) {
    BOOST_TEST(radii.at(k) <= 1.);
    BOOST_TEST(radii.at(k) <= get(gs::mat_radius_in_voxels_map(bar_distances), k)); // the MAT radius judges
  });
}

// A sheet 3.5 to 4.4 voxels thick and slanted in the grid (a wing at resolution 128 that
// is about two voxels thick at 64) has middle voxels at 2 and at sqrt(5) from the outside,
// side by side along its stair steps: with the default thin-part radius, both sheets below
// thin to a comb of three to five chains, with sheet radii of at most 5. With a thin-part
// radius of 2 sqrt(2) (the default of extract_control_skeleton() at 128) they burn at one
// level, from the sheet's rim: one chain runs along the sheet's middle and its sheet
// radius is the sheet's half width.
BOOST_AUTO_TEST_CASE_TEMPLATE(a_thicker_thin_sheet_burns_from_its_rim, VoxelSet, Voxel_set_models)
{
  const double half_width = 15;
  // (At steeper slants, 37 degrees, such a sheet still thins to a comb of chains: its
  // middle voxels step across more than one level.)
  const struct { double thickness, slant_degrees; } sheets[] = {{3.5, 10}, {4.4, 25}};
  for(const auto& sheet : sheets)
  {
    BOOST_TEST_CONTEXT("thickness " << sheet.thickness << ", slant " << sheet.slant_degrees << " degrees")
    {
      const double c = std::cos(sheet.slant_degrees * M_PI / 180), s = std::sin(sheet.slant_degrees * M_PI / 180);
      VoxelSet set = voxels_where<VoxelSet>(
          gs::Voxel_box{gs::Voxel_key{0, -25, -25}, gs::Voxel_key{60, 26, 26}}, [&](int, int y, int z) {
            return std::abs(c * y + s * z) <= half_width && std::abs(-s * y + c * z) <= sheet.thickness / 2;
          });
      const gs::Voxel_distance_field distances = gs::distance_transform(set);
      std::uint32_t deepest = 0;
      set.for_each([&](const gs::Voxel_key& k) { deepest = (std::max)(deepest, distances.squared_distance(k)); });
      BOOST_TEST_REQUIRE(deepest > 2u); // thicker than a thin part of the default radius
      BOOST_TEST_REQUIRE(deepest <= 8u);

      gs::Voxel_skeleton skeleton;
      gs::thin(set, distances, skeleton, gs::parameters::thin_part_radius(gs::default_thin_part_radius(128)));
      const gs::Sheet_radii& radii = skeleton.sheet_radii;
      int middle = 0;
      set.for_each([&](const gs::Voxel_key& k) {
        if(k.x < 20 || k.x >= 40)
          return;
        ++middle;
        BOOST_TEST(radii.at(k) >= half_width - 5);
        BOOST_TEST(radii.at(k) <= half_width + 1);
      });
      BOOST_TEST(middle == 20); // one voxel per column: one chain
    }
  }
}

// A plate 7 voxels thick, 30 wide, slanted in two directions of the grid (its normal 20
// degrees off the z axis, turned 10 degrees about it), thinned with the default thin-part
// radius: its middle lies on levels less than half a voxel apart, side by side in strips,
// and each level's rounds measure a strip (at most 4 voxels here). The sheet radius read
// across close levels (Voxel_skeleton::slanted_sheet_radii) measures the plate, its half width; it is
// never below the one read at one level, and equals it in a sheet parallel to the grid.
BOOST_AUTO_TEST_CASE_TEMPLATE(the_sheet_radius_across_close_levels_measures_a_slanted_plate, VoxelSet,
                              Voxel_set_models)
{
  const double half_width = 15, thickness = 7;
  const double turn = 10 * M_PI / 180, tilt = 20 * M_PI / 180;
  const std::array<double, 3> normal{std::cos(turn) * std::sin(tilt), std::sin(turn) * std::sin(tilt), std::cos(tilt)};
  const std::array<double, 3> across{-std::sin(turn), std::cos(turn), 0.};
  const std::array<double, 3> along{normal[1] * across[2] - normal[2] * across[1],
                                    normal[2] * across[0] - normal[0] * across[2],
                                    normal[0] * across[1] - normal[1] * across[0]};
  auto plate = [&](int x, int y, int z) {
    auto dot = [&](const std::array<double, 3>& w) { return w[0] * x + w[1] * y + w[2] * z; };
    return std::abs(dot(normal)) <= thickness / 2 && std::abs(dot(across)) <= half_width &&
           std::abs(dot(along)) <= half_width;
  };
  const auto radii_of = [](VoxelSet set) {
    const gs::Voxel_distance_field distances = gs::distance_transform(set);
    gs::Voxel_skeleton skeleton;
    gs::thin(set, distances, skeleton);
    BOOST_TEST(skeleton.sheet_radii.size() == set.size());
    BOOST_TEST(skeleton.slanted_sheet_radii.size() == set.size());
    return std::make_pair(skeleton.sheet_radii, skeleton.slanted_sheet_radii);
  };

  const auto [at_one_level, across_levels] =
      radii_of(voxels_where<VoxelSet>(gs::Voxel_box{gs::Voxel_key{-25, -25, -25}, gs::Voxel_key{26, 26, 26}}, plate));
  BOOST_TEST(test::largest_sheet_radius(at_one_level) <= 5.);
  BOOST_TEST(test::largest_sheet_radius(across_levels) >= half_width - 3);
  BOOST_TEST(test::largest_sheet_radius(across_levels) <= half_width + 2);
  for(const auto& [k, radius] : at_one_level)
    BOOST_TEST(across_levels.at(k) >= radius);

  const auto [flat_at_one_level, flat_across_levels] = radii_of(voxels_where<VoxelSet>(
      gs::Voxel_box{gs::Voxel_key{0, 0, 0}, gs::Voxel_key{40, 30, 7}}, [](int, int, int) { return true; }));
  BOOST_TEST(test::largest_sheet_radius(flat_at_one_level) >= half_width - 3);
  BOOST_TEST((flat_at_one_level == flat_across_levels));
}

BOOST_AUTO_TEST_CASE(the_default_thin_part_radius_grows_above_the_default_resolution)
{
  BOOST_TEST(gs::default_thin_part_radius(64) == std::sqrt(2.));
  BOOST_TEST(gs::default_thin_part_radius(48) == std::sqrt(2.));
  BOOST_TEST(gs::default_thin_part_radius(4) == std::sqrt(2.));
  BOOST_TEST(gs::default_thin_part_radius(96) == 1.5 * std::sqrt(2.));
  BOOST_TEST(gs::default_thin_part_radius(128) == 2 * std::sqrt(2.));
}

BOOST_AUTO_TEST_CASE(a_thin_part_radius_out_of_range_is_refused)
{
  const gs::Voxel_box box{gs::Voxel_key{0, 0, 0}, gs::Voxel_key{10, 3, 3}};
  for(double radius : {-1., 1000.5, std::nan(""), HUGE_VAL})
  {
    gs::Sparse_voxel_set bar = voxels_where<gs::Sparse_voxel_set>(box, [](int, int, int) { return true; });
    const gs::Voxel_distance_field distances = gs::distance_transform(bar);
    BOOST_CHECK_THROW(gs::thin(bar, distances, gs::parameters::thin_part_radius(radius)), std::invalid_argument);
    BOOST_TEST(bar.size() == 90u); // refused before any voxel went
  }
}

BOOST_AUTO_TEST_CASE(both_models_give_the_same_skeleton)
{
  const gs::Voxel_box box{gs::Voxel_key{-16, -16, -8}, gs::Voxel_key{17, 17, 9}};
  auto shape = [](int x, int y, int z) {
    return (std::hypot(double(x), double(y)) - 10.) * (std::hypot(double(x), double(y)) - 10.) + z * z <= 16. ||
           (x * x + y * y <= 9 && std::abs(z) <= 6) || (std::abs(x) <= 12 && y * y + z * z <= 4);
  };
  auto dense = voxels_where<gs::Dense_voxel_grid>(box, shape);
  auto sparse = voxels_where<gs::Sparse_voxel_set>(box, shape);
  thin_set(dense);
  thin_set(sparse);
  BOOST_TEST((test::keys_of(dense) == test::keys_of(sparse)));
}

// The round numbers behind the sheet radii take 2 bytes per voxel of the box: only a call
// that asks for the radii (either reading) pays them (5 bytes per box voxel without, 7
// with, plus 12 per voxel).
BOOST_AUTO_TEST_CASE(the_sheet_radii_cost_memory_only_when_asked_for)
{
  const gs::Voxel_box box{gs::Voxel_key{0, -7, -7}, gs::Voxel_key{40, 8, 8}};
  auto round_bar = [](int, int y, int z) { return y * y + z * z <= 25; };
  const gs::Sparse_voxel_set bar = voxels_where<gs::Sparse_voxel_set>(box, round_bar);
  const gs::Voxel_distance_field distances = gs::distance_transform(bar);
  // The bar's bounding box is 40 x 11 x 11 voxels; thin() grows it by two on each side.
  const double box_voxels = (40. + 4.) * (11. + 4.) * (11. + 4.);
  const double between = 6. * box_voxels + 28. * double(bar.size());

  gs::Sparse_voxel_set unlimited = bar, limited = bar;
  gs::thin(unlimited, distances);
  BOOST_CHECK_NO_THROW(gs::thin(limited, distances, gs::parameters::memory_limit(between)));
  BOOST_TEST(unlimited.size() >= 30u); // the bar's axis
  BOOST_TEST((test::keys_of(limited) == test::keys_of(unlimited)));

  gs::Sparse_voxel_set with_radii = bar;
  gs::Voxel_skeleton skeleton;
  BOOST_CHECK_THROW(gs::thin(with_radii, distances, skeleton, gs::parameters::memory_limit(between)),
                    std::length_error);
}

// reach_sheet_lobes(): a thick plate tapering to its rim thins from the rim inwards, level by
// level, to a point or to stubs; each of its arms then gets a path from its far end to them.
namespace {

// A thick starfish of `arms` arms, lens-shaped: its outline runs from 7 to 36 voxels from
// the centre, its half thickness falls linearly from 10 voxels at the centre to 0 at the rim.
bool in_starfish(int arms, double turn, int x, int y, int z)
{
  const double rho = std::hypot(double(x), double(y));
  const double rim = 36. * test::starfish_rim(arms, turn, std::atan2(double(y), double(x)));
  return rho < rim && std::abs(z) <= 10. * (1. - rho / rim);
}

// The end points (one 26-neighbour) of a voxel set.
template <typename VoxelSet>
std::vector<gs::Voxel_key> end_points(const VoxelSet& s)
{
  std::vector<gs::Voxel_key> ends;
  s.for_each([&](const gs::Voxel_key& k) {
    if(gs::internal::bit_count(configuration(s, k)) == 1)
      ends.push_back(k);
  });
  return ends;
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(reach_sheet_lobes_gives_each_arm_of_a_thick_starfish_a_branch, VoxelSet,
                              Voxel_set_models)
{
  const int arms = 5;
  const double turn = 0.3; // no arm along a grid axis
  const gs::Voxel_box box{gs::Voxel_key{-40, -40, -12}, gs::Voxel_key{41, 41, 13}};
  VoxelSet s = voxels_where<VoxelSet>(box, [&](int x, int y, int z) { return in_starfish(arms, turn, x, y, z); });
  const gs::Voxel_distance_field distances = gs::distance_transform(s);
  gs::thin(s, distances);
  for(const gs::Voxel_key& e : end_points(s)) // the premise: thinning burns the arms to stubs
    BOOST_TEST(std::hypot(double(e.x), double(e.y)) < 20.); // the arms reach 36 out
  VoxelSet unchanged = s;
  BOOST_TEST(gs::reach_sheet_lobes(unchanged, distances, gs::parameters::sheet_lobe_reach_factor(0)).lobes_reached == 0u);
  BOOST_TEST(unchanged.size() == s.size());

  const gs::Sheet_lobes_report report = gs::reach_sheet_lobes(s, distances);
  BOOST_TEST(report.lobes_reached == std::size_t(arms));
  BOOST_TEST(report.voxels_added > 0u);
  BOOST_TEST(test::components_26(s) == 1);
  // One end per arm, at least two thirds of the way out along it.
  std::vector<int> ends_per_arm(arms, 0);
  for(const gs::Voxel_key& e : end_points(s))
  {
    const test::Starfish_arm a = test::starfish_arm(arms, turn, double(e.x), double(e.y));
    BOOST_TEST(std::abs(a.off_axis) < test::pi / arms / 2);
    BOOST_TEST(std::hypot(double(e.x), double(e.y)) > 24.);
    ++ends_per_arm[std::size_t(a.arm)];
  }
  for(int arm = 0; arm < arms; ++arm)
    BOOST_TEST(ends_per_arm[std::size_t(arm)] == 1, "arm " << arm);
}

BOOST_AUTO_TEST_CASE(reach_sheet_lobes_leaves_a_limb_and_a_wing_alone)
{
  // A bar's skeleton, its axis, holds its whole medial sheet in its balls; a thin sheet (a
  // wing, two voxels thick) is not searched: thinning keeps its middle curve already.
  const gs::Voxel_box box{gs::Voxel_key{0, -7, -7}, gs::Voxel_key{60, 31, 8}};
  gs::Dense_voxel_grid s = voxels_where<gs::Dense_voxel_grid>(
      box, [](int x, int y, int z) { return y * y + z * z <= 36 || (x >= 20 && x < 40 && y >= 0 && y < 30 && z >= 0 && z < 2); });
  const gs::Voxel_distance_field distances = gs::distance_transform(s);
  gs::thin(s, distances);
  const std::size_t thinned = s.size();
  const gs::Sheet_lobes_report report = gs::reach_sheet_lobes(s, distances);
  BOOST_TEST(report.lobes_reached == 0u);
  BOOST_TEST(s.size() == thinned);
}

BOOST_AUTO_TEST_CASE(reach_sheet_lobes_refuses_a_factor_out_of_range)
{
  const gs::Voxel_box box{gs::Voxel_key{-9, -9, -9}, gs::Voxel_key{10, 10, 10}};
  gs::Dense_voxel_grid s = voxels_where<gs::Dense_voxel_grid>(box, [](int x, int y, int z) { return x * x + y * y + z * z <= 64; });
  const gs::Voxel_distance_field distances = gs::distance_transform(s);
  for(double bad : {-1., 101., std::nan("")})
    BOOST_CHECK_THROW(gs::reach_sheet_lobes(s, distances, gs::parameters::sheet_lobe_reach_factor(bad)), std::invalid_argument);
  BOOST_CHECK_THROW(gs::reach_sheet_lobes(s, distances, gs::parameters::thin_part_radius(-1.)), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(an_empty_set_is_an_error)
{
  gs::Sparse_voxel_set empty;
  BOOST_CHECK_THROW(gs::thin(empty, gs::Voxel_distance_field()), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
