# cmake -DPROGRAM=<exe> -DARGUMENTS=<a;b;...> [-DEXPECTED_STDERR=<regex>] -P expect_failure.cmake
# Passes when PROGRAM exits with a non-zero exit code (a crash does not count: CMake then
# reports a signal name, not a number) and its stderr is non-empty and matches
# EXPECTED_STDERR. A sanitizer report (scripts/run_sanitizer_tests.sh) is never a clean
# failure, whatever the exit code.
execute_process(COMMAND ${PROGRAM} ${ARGUMENTS}
  RESULT_VARIABLE result
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
message("exit: ${result}\nstdout: ${out}\nstderr: ${err}")
if(NOT result MATCHES "^[0-9]+$")
  message(FATAL_ERROR "${PROGRAM} crashed (${result}) instead of failing cleanly")
endif()
if(err MATCHES "(Address|Leak|UndefinedBehavior)Sanitizer|runtime error:")
  message(FATAL_ERROR "${PROGRAM} has a sanitizer report instead of failing cleanly")
endif()
if(result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} succeeded on bad input; a non-zero exit code was expected")
endif()
if(err STREQUAL "")
  message(FATAL_ERROR "${PROGRAM} failed without a message on stderr")
endif()
if(DEFINED EXPECTED_STDERR AND NOT err MATCHES "${EXPECTED_STDERR}")
  message(FATAL_ERROR "stderr does not match '${EXPECTED_STDERR}'")
endif()
