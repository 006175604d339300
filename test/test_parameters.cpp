// Specification of CGAL/Geodesic_skeleton/parameters.h: the package's own named parameters
// live beside CGAL's, and packs of either kind join with combine().
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <boost/test/unit_test.hpp>

#include <type_traits>

BOOST_AUTO_TEST_SUITE(parameters)

namespace gs = CGAL::Geodesic_skeleton;
namespace params = CGAL::Geodesic_skeleton::parameters;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;

BOOST_AUTO_TEST_CASE(a_package_parameter_is_found_by_its_tag)
{
  const auto np = params::edge_weight_map(42);
  BOOST_TEST(choose_parameter(get_parameter(np, gs::internal_np::edge_weight_map_tag), 0) == 42);
}

BOOST_AUTO_TEST_CASE(an_absent_parameter_falls_back_to_the_default)
{
  const auto np = params::edge_weight_map(42);
  BOOST_TEST(choose_parameter(get_parameter(np, gs::internal_np::vertex_predecessor_map_tag), 7) == 7);
  BOOST_TEST(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 9) == 9);
}

BOOST_AUTO_TEST_CASE(combine_joins_package_and_cgal_parameters)
{
  const auto np = params::combine(params::edge_weight_map(1),
                                  params::number_of_iterations(2),
                                  params::vertex_predecessor_map(3));
  BOOST_TEST(choose_parameter(get_parameter(np, gs::internal_np::edge_weight_map_tag), 0) == 1);
  BOOST_TEST(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 0) == 2);
  BOOST_TEST(choose_parameter(get_parameter(np, gs::internal_np::vertex_predecessor_map_tag), 0) == 3);
}

BOOST_AUTO_TEST_CASE(combine_keeps_the_first_value_of_a_repeated_name)
{
  const auto np = params::combine(params::edge_weight_map(1), params::edge_weight_map(2));
  BOOST_TEST(choose_parameter(get_parameter(np, gs::internal_np::edge_weight_map_tag), 0) == 1);
}

BOOST_AUTO_TEST_CASE(combine_with_default_values_changes_nothing)
{
  const auto np = params::combine(params::edge_weight_map(5), CGAL::parameters::default_values());
  BOOST_TEST(choose_parameter(get_parameter(np, gs::internal_np::edge_weight_map_tag), 0) == 5);
  // Copied to a local: CGAL declares `value` without defining it, so it must not be bound
  // to a reference (BOOST_TEST does) in an unoptimised build.
  const bool predecessor_map_is_default =
      CGAL::parameters::is_default_parameter<decltype(np), gs::internal_np::vertex_predecessor_map_t>::value;
  BOOST_TEST(predecessor_map_is_default);
}

BOOST_AUTO_TEST_SUITE_END()
