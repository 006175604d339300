# Installs the package into a scratch prefix, then configures, builds and runs the outside
# project in outside_project/, which finds it with find_package(Geodesic_skeleton).
# Variables: SOURCE_DIR, BINARY_DIR, DATA_DIR, CMAKE_CXX_COMPILER.
file(REMOVE_RECURSE ${BINARY_DIR})
set(prefix ${BINARY_DIR}/prefix)

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "install test, ${step} failed:\n${out}")
  endif()
  message(STATUS "install test, ${step}: ok")
endfunction()

run("configure the package"
  ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR}/package
  -DCMAKE_INSTALL_PREFIX=${prefix} -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
  -DGEODESIC_SKELETON_BUILD_EXAMPLES=OFF -DGEODESIC_SKELETON_BUILD_TESTS=OFF
  -DGEODESIC_SKELETON_BUILD_BENCHMARKS=OFF -DGEODESIC_SKELETON_BUILD_DOC=OFF
  -DGEODESIC_SKELETON_DATA_DIR=${DATA_DIR})
run("install the package" ${CMAKE_COMMAND} --install ${BINARY_DIR}/package)
run("configure the outside project"
  ${CMAKE_COMMAND} -S ${SOURCE_DIR}/test/install_test/outside_project -B ${BINARY_DIR}/outside
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER})
run("build the outside project" ${CMAKE_COMMAND} --build ${BINARY_DIR}/outside)
run("run the outside project" ${BINARY_DIR}/outside/outside_user ${DATA_DIR}/cow.off)
