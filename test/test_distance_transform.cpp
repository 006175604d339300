// Specification of CGAL/Geodesic_skeleton/distance_transform.h.
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>

#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(distance_transform)

namespace gs = CGAL::Geodesic_skeleton;

namespace {

using Voxel_set_models = boost::mpl::list<gs::Dense_voxel_grid, gs::Sparse_voxel_set>;

// The definition, by brute force: the smallest squared distance to a voxel not in the set
// (the nearest outside voxel is at most one layer beyond the set's bounding box).
template <typename VoxelSet>
std::uint32_t brute_force(const VoxelSet& s, const gs::Voxel_key& k, const gs::Voxel_box& box)
{
  if(!s.contains(k))
    return 0;
  std::uint32_t best = 0xFFFFFFFFu;
  const gs::Voxel_box around = box.grown(1);
  for(int z = around.min.z; z < around.max.z; ++z)
    for(int y = around.min.y; y < around.max.y; ++y)
      for(int x = around.min.x; x < around.max.x; ++x)
        if(!s.contains(gs::Voxel_key{x, y, z}))
        {
          const std::uint32_t d2 = std::uint32_t((x - k.x) * (x - k.x) + (y - k.y) * (y - k.y) + (z - k.z) * (z - k.z));
          best = d2 < best ? d2 : best;
        }
  return best;
}

} // namespace

BOOST_AUTO_TEST_CASE_TEMPLATE(it_equals_the_brute_force_squared_distance, VoxelSet, Voxel_set_models)
{
  // Random blobs: a few balls of random centres and radii, so that the nearest outside
  // voxel is in every direction.
  std::mt19937 random(11);
  const gs::Voxel_box box{gs::Voxel_key{-4, 0, 2}, gs::Voxel_key{18, 14, 12}};
  for(int trial = 0; trial < 5; ++trial)
  {
    VoxelSet s;
    s.reset(gs::Voxel_frame(), box);
    for(int ball = 0; ball < 4; ++ball)
    {
      const int cx = box.min.x + int(random() % 22), cy = int(random() % 14), cz = 2 + int(random() % 10);
      const int r2 = 4 + int(random() % 30);
      for(int z = box.min.z; z < box.max.z; ++z)
        for(int y = box.min.y; y < box.max.y; ++y)
          for(int x = box.min.x; x < box.max.x; ++x)
            if((x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz) <= r2)
              s.insert(gs::Voxel_key{x, y, z});
    }
    const gs::Voxel_distance_field field = gs::distance_transform(s);
    int mismatches = 0;
    for(int z = box.min.z - 2; z < box.max.z + 2; ++z)
      for(int y = box.min.y - 2; y < box.max.y + 2; ++y)
        for(int x = box.min.x - 2; x < box.max.x + 2; ++x)
        {
          const gs::Voxel_key k{x, y, z};
          mismatches += field.squared_distance(k) != brute_force(s, k, box);
        }
    BOOST_TEST(mismatches == 0);
  }
}

BOOST_AUTO_TEST_CASE(a_single_voxel_has_distance_one_and_radius_half_a_voxel)
{
  gs::Sparse_voxel_set s;
  const gs::Voxel_frame frame({0., 0., 0.}, {{{1., 0., 0.}, {0., 1., 0.}, {0., 0., 1.}}}, 0.5);
  s.reset(frame, gs::Voxel_box{});
  s.insert(gs::Voxel_key{3, -4, 5});
  const auto field = gs::distance_transform(s);
  BOOST_TEST(field.squared_distance(gs::Voxel_key{3, -4, 5}) == 1u);
  BOOST_TEST(field.radius(gs::Voxel_key{3, -4, 5}) == 0.25);
  BOOST_TEST(!field.inside(gs::Voxel_key{4, -4, 5}));
  BOOST_TEST(field.max_squared_distance() == 1u);
}

BOOST_AUTO_TEST_CASE(a_long_bar_has_the_distance_of_its_cross_section)
{
  // A 200 x 9 x 7 bar: along its middle, the nearest outside voxel is across the thinner side.
  gs::Dense_voxel_grid g;
  g.reset(gs::Voxel_frame(), gs::Voxel_box{gs::Voxel_key{0, 0, 0}, gs::Voxel_key{200, 9, 7}});
  for(int z = 0; z < 7; ++z)
    for(int y = 0; y < 9; ++y)
      for(int x = 0; x < 200; ++x)
        g.insert(gs::Voxel_key{x, y, z});
  const auto field = gs::distance_transform(g);
  BOOST_TEST(field.squared_distance(gs::Voxel_key{100, 4, 3}) == 16u);
  BOOST_TEST(field.squared_distance(gs::Voxel_key{0, 4, 3}) == 1u);
  BOOST_TEST(field.squared_distance(gs::Voxel_key{100, 0, 0}) == 1u);
}

BOOST_AUTO_TEST_CASE(an_empty_set_or_too_little_memory_is_an_error)
{
  gs::Sparse_voxel_set empty;
  BOOST_CHECK_THROW(gs::distance_transform(empty), std::invalid_argument);
  gs::Sparse_voxel_set s;
  s.insert(gs::Voxel_key{0, 0, 0});
  s.insert(gs::Voxel_key{1000, 1000, 100});
  try
  {
    gs::distance_transform(s, gs::parameters::memory_limit(1e6));
    BOOST_FAIL("expected std::length_error");
  }
  catch(const std::length_error& e)
  {
    BOOST_TEST(std::string(e.what()).find("bytes") != std::string::npos);
  }
}

BOOST_AUTO_TEST_SUITE_END()
