# Included by the skeletonize checks (check_skeletonize.cmake, check_skinning.cmake): empties
# WORK_DIR, and run(ARGS...) runs PROGRAM with ARGS, fails the test when it fails, and
# leaves its standard output in `stdout`.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run)
  execute_process(COMMAND ${PROGRAM} ${ARGN} RESULT_VARIABLE result ERROR_VARIABLE err OUTPUT_VARIABLE out)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "skeletonize ${ARGN} failed (${result}):\n${err}")
  endif()
  set(stdout "${out}" PARENT_SCOPE)
endfunction()
