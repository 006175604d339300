# `cmake --install` puts the headers and a package configuration in place, so that another
# project writes find_package(Geodesic_skeleton REQUIRED) and links CGAL::Geodesic_skeleton.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GEODESIC_SKELETON_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Geodesic_skeleton)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS Geodesic_skeleton EXPORT Geodesic_skeletonTargets)
install(EXPORT Geodesic_skeletonTargets
  NAMESPACE CGAL::
  DESTINATION ${GEODESIC_SKELETON_CMAKE_DIR})

configure_package_config_file(
  ${PROJECT_SOURCE_DIR}/cmake/Geodesic_skeletonConfig.cmake.in
  ${PROJECT_BINARY_DIR}/Geodesic_skeletonConfig.cmake
  INSTALL_DESTINATION ${GEODESIC_SKELETON_CMAKE_DIR})
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/Geodesic_skeletonConfigVersion.cmake
  COMPATIBILITY SameMinorVersion
  ARCH_INDEPENDENT)
install(FILES
  ${PROJECT_BINARY_DIR}/Geodesic_skeletonConfig.cmake
  ${PROJECT_BINARY_DIR}/Geodesic_skeletonConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/GeodesicSkeletonDependencies.cmake
  DESTINATION ${GEODESIC_SKELETON_CMAKE_DIR})
