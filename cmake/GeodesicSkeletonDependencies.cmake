# The package's dependencies, found the same way in the build tree and in the installed
# package configuration (Geodesic_skeletonConfig.cmake includes this file too).
find_package(CGAL REQUIRED)
find_package(Boost 1.66 REQUIRED)
# With CGAL 5.5, Eigen3 must be found before CGAL_Eigen3_support is included.
find_package(Eigen3 3.1.0 REQUIRED)
include(CGAL_Eigen3_support)
if(NOT TARGET CGAL::Eigen3_support)
  message(FATAL_ERROR "Geodesic_skeleton needs Eigen3 (Debian: libeigen3-dev)")
endif()
