# cmake -DDOXYGEN=<doxygen> -DDOXYFILE=<Doxyfile> -DWARNINGS=<warning log> -P check_doxygen_warnings.cmake
# Runs Doxygen and fails when it cannot run or when its warning log (WARN_LOGFILE) is not
# empty; the warnings are printed, one per line, "file:line: text".
file(REMOVE ${WARNINGS})
execute_process(COMMAND ${DOXYGEN} ${DOXYFILE}
  RESULT_VARIABLE result
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "doxygen failed (${result}):\n${out}\n${err}")
endif()
if(NOT EXISTS ${WARNINGS})
  message(FATAL_ERROR "doxygen wrote no warning log ${WARNINGS}; check WARN_LOGFILE in ${DOXYFILE}")
endif()
file(READ ${WARNINGS} warnings)
string(STRIP "${warnings}" warnings)
if(NOT warnings STREQUAL "")
  # Printed as they are (message() would re-wrap the lines), then the test fails.
  execute_process(COMMAND ${CMAKE_COMMAND} -E cat ${WARNINGS})
  message(FATAL_ERROR "Doxygen warned (undocumented public API or broken references); "
                      "the warnings are above and in ${WARNINGS}")
endif()
message(STATUS "Doxygen: no warnings")
