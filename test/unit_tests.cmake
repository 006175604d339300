# The unit-test executable geodesic_skeleton_tests: every suite of GEODESIC_SKELETON_TEST_SUITES
# (test/CMakeLists.txt), each registered with CTest on its own.
find_package(Boost 1.66 REQUIRED COMPONENTS unit_test_framework)

set(test_sources test_main.cpp)
foreach(suite IN LISTS GEODESIC_SKELETON_TEST_SUITES)
  list(APPEND test_sources test_${suite}.cpp)
endforeach()

# The malformed meshes the tests read. A cache path, like the demo meshes' folder, so that
# builds of several checkouts can point at one copy and share compiled objects (ccache).
set(GEODESIC_SKELETON_BAD_MESH_DIR ${CMAKE_CURRENT_SOURCE_DIR}/data/bad_meshes CACHE PATH
  "Folder of the malformed meshes that the unit tests read")

add_executable(geodesic_skeleton_tests ${test_sources})
# The suites are compiled in two translation units (a unity build): they instantiate the
# same stages on the same mesh types, which each unit would otherwise compile again (this
# halves the build). The suites that run the whole pipeline (extract_control_skeleton() and
# what reads its result) are one unit, those of single stages the other; the two take about
# as long, one per core. Each suite keeps its helpers in its own namespace, the one
# BOOST_AUTO_TEST_SUITE opens. A unit hides an include that one suite forgets and another
# makes: GEODESIC_SKELETON_UNITY_TESTS=OFF compiles each suite on its own.
set(pipeline_suites
  extract_control_skeleton control_skeleton robustness game_characters skinning_weights gltf control_skeleton_json
  assimp_input)
foreach(suite IN LISTS GEODESIC_SKELETON_TEST_SUITES)
  if(suite IN_LIST pipeline_suites)
    set_source_files_properties(test_${suite}.cpp PROPERTIES UNITY_GROUP pipeline)
  else()
    set_source_files_properties(test_${suite}.cpp PROPERTIES UNITY_GROUP stages)
  endif()
endforeach()
set_target_properties(geodesic_skeleton_tests PROPERTIES UNITY_BUILD ${GEODESIC_SKELETON_UNITY_TESTS} UNITY_BUILD_MODE GROUP)
target_include_directories(geodesic_skeleton_tests PRIVATE include)
target_link_libraries(geodesic_skeleton_tests PRIVATE
  CGAL::Geodesic_skeleton Boost::unit_test_framework ${GEODESIC_SKELETON_FORMAT_LIBRARIES})
target_compile_definitions(geodesic_skeleton_tests PRIVATE
  BOOST_TEST_DYN_LINK
  GEODESIC_SKELETON_DATA_DIR="${GEODESIC_SKELETON_DATA_DIR}"
  GEODESIC_SKELETON_BAD_MESH_DIR="${GEODESIC_SKELETON_BAD_MESH_DIR}")

foreach(suite IN LISTS GEODESIC_SKELETON_TEST_SUITES)
  add_test(NAME ${suite}
           COMMAND geodesic_skeleton_tests --run_test=${suite} --log_level=test_suite)
endforeach()
# Bad input must never hang: the robustness suite takes a few seconds.
set_tests_properties(robustness PROPERTIES TIMEOUT 120)
