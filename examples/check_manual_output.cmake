# cmake -DPROGRAM=<exe> -DARGUMENTS=<a;b;...> -DMANUAL=<doc/manual.md> -DNAME=<example>
#       -P check_manual_output.cmake
# Runs PROGRAM and checks that its output is what the manual says it prints, so that the
# manual's numbers and the program cannot drift apart. In MANUAL, the quoted output is the
# fenced block (``` ... ```) that follows the line `<!-- output of NAME -->` (an HTML
# comment, which Doxygen does not show). Each line of the block must match a line of the
# program's standard output, in the same order and on consecutive lines, except that
#   - a block line that is just `...` stands for any number of output lines, and
#   - `...` inside a block line stands for any text (a timing, a file path).
# The first block line may match any output line. The test fails when PROGRAM fails, when
# the manual has no such block, or when a line does not match.

execute_process(COMMAND ${PROGRAM} ${ARGUMENTS}
  RESULT_VARIABLE result
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
message("stdout:\n${out}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed (${result}):\n${err}")
endif()

file(READ ${MANUAL} manual)
set(marker "<!-- output of ${NAME} -->")
string(FIND "${manual}" "${marker}" marker_at)
if(marker_at EQUAL -1)
  message(FATAL_ERROR "${MANUAL} has no line '${marker}' before the output it quotes")
endif()
string(SUBSTRING "${manual}" ${marker_at} -1 manual)
if(NOT manual MATCHES "^[^\n]*\n```[^\n]*\n(.*)")
  message(FATAL_ERROR "'${marker}' in ${MANUAL} is not followed by a fenced block")
endif()
set(block "${CMAKE_MATCH_1}")
string(FIND "${block}" "```" block_end)
if(block_end EQUAL -1)
  message(FATAL_ERROR "the block after '${marker}' in ${MANUAL} is not closed")
endif()
string(SUBSTRING "${block}" 0 ${block_end} block)

include(${CMAKE_CURRENT_LIST_DIR}/../cmake/MarkdownLines.cmake)

string(REGEX REPLACE "\n$" "" block "${block}")
string(REGEX REPLACE "\n$" "" out "${out}")
markdown_lines("${block}" expected_lines)
markdown_lines("${out}" output_lines)
list(LENGTH output_lines output_count)
if(expected_lines STREQUAL "")
  message(FATAL_ERROR "the block after '${marker}' in ${MANUAL} is empty")
endif()

set(position 0)      # the next output line to match
set(skipping ON)     # may the next expected line match further down?
foreach(expected IN LISTS expected_lines)
  markdown_line("${expected}" expected)
  if(expected STREQUAL "...")
    set(skipping ON)
    continue()
  endif()
  # The expected line as an anchored regular expression, `...` as any text.
  string(REGEX REPLACE "([][\\^$.|?*+(){}])" "\\\\\\1" pattern "${expected}")
  string(REPLACE "\\.\\.\\." ".*" pattern "${pattern}")
  set(found OFF)
  while(position LESS output_count)
    list(GET output_lines ${position} line)
    markdown_line("${line}" line)
    math(EXPR position "${position} + 1")
    if(line MATCHES "^${pattern}$")
      set(found ON)
      break()
    endif()
    if(NOT skipping)
      break()
    endif()
  endwhile()
  if(NOT found)
    message(FATAL_ERROR "${NAME}: the manual (${MANUAL}) quotes the line\n  ${expected}\n"
                        "which the program's output above does not have there")
  endif()
  set(skipping OFF)
endforeach()
message(STATUS "${NAME}: the output matches the manual")
