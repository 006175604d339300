# Functions of the scripts that read the Markdown documentation line by line
# (examples/check_manual_output.cmake, test/code_blocks/extract_code_blocks.cmake).
# markdown_lines(TEXT OUT_VAR): TEXT as a CMake list of its lines. Semicolons and square
# brackets are list syntax, so they travel as placeholders: pass each line through
# markdown_line() before using it.
function(markdown_lines text out_var)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<open>" text "${text}")
  string(REPLACE "]" "<close>" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(${out_var} "${lines}" PARENT_SCOPE)
endfunction()

# markdown_line(LINE OUT_VAR): an element of markdown_lines()'s list as the line it was.
function(markdown_line line out_var)
  string(REPLACE "<semicolon>" ";" line "${line}")
  string(REPLACE "<open>" "[" line "${line}")
  string(REPLACE "<close>" "]" line "${line}")
  set(${out_var} "${line}" PARENT_SCOPE)
endfunction()
