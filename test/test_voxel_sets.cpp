// Specification of the VoxelSet concept's models (Dense_voxel_grid.h, Sparse_voxel_set.h),
// of Voxel_key.h and of Voxel_frame.h.
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

namespace gs = CGAL::Geodesic_skeleton;

namespace {

using Voxel_set_models = boost::mpl::list<gs::Dense_voxel_grid, gs::Sparse_voxel_set>;

const gs::Voxel_box test_box{gs::Voxel_key{-3, -2, -1}, gs::Voxel_key{5, 6, 7}};

template <typename VoxelSet>
std::set<gs::Voxel_key> keys_of(const VoxelSet& s)
{
  std::set<gs::Voxel_key> keys;
  s.for_each([&](const gs::Voxel_key& k) { keys.insert(k); });
  return keys;
}

} // namespace

BOOST_AUTO_TEST_SUITE(voxel_sets)

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
  BOOST_TEST((keys_of(s) == reference));
  for(const gs::Voxel_key& k : reference)
    BOOST_TEST(s.bounding_box().contains(k));
  BOOST_TEST(!s.contains(gs::Voxel_key{100, 100, 100}));
  s.clear();
  BOOST_TEST(s.size() == 0u);
  BOOST_TEST(keys_of(s).empty());
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

BOOST_AUTO_TEST_SUITE_END()
