// The single Boost.Test entry point of the package's unit tests; the suites are in the
// test_<suite>.cpp files, one per public header.
#define BOOST_TEST_MODULE Geodesic_skeleton
#include <boost/test/unit_test.hpp>
