# The README's C++ block is real code: the marked part of
# examples/first_window/main.cpp ("// [readme]" to "// [/readme]"), verbatim
# but for the marks' indentation (the example is built and run by CTest, and by the package test against the
# installed package).
#   cmake -DSOURCE_DIR=... -P readme_code.cmake
file(READ "${SOURCE_DIR}/README.md" readme)
file(READ "${SOURCE_DIR}/examples/first_window/main.cpp" app)

string(FIND "${app}" "// [readme]" begin)
string(FIND "${app}" "// [/readme]" end)
if(begin EQUAL -1 OR end EQUAL -1)
  message(FATAL_ERROR "examples/first_window/main.cpp has no // [readme] ... // [/readme] region")
endif()
string(SUBSTRING "${app}" ${begin} -1 rest)
string(FIND "${rest}" "\n" eol)
math(EXPR start "${begin} + ${eol} + 1")
math(EXPR length "${end} - ${start}")
string(SUBSTRING "${app}" ${start} ${length} region)
# The end mark's own indentation is not part of the region, and the README
# shows the code without the begin mark's indentation.
string(REGEX REPLACE "[ ]+$" "" region "${region}")
string(SUBSTRING "${app}" 0 ${begin} before)
string(FIND "${before}" "\n" line_start REVERSE)
math(EXPR indent_start "${line_start} + 1")
math(EXPR indent_length "${begin} - ${indent_start}")
if(indent_length GREATER 0)
  string(SUBSTRING "${app}" ${indent_start} ${indent_length} indent)
  string(REPLACE "\n${indent}" "\n" region "\n${region}")
  string(SUBSTRING "${region}" 1 -1 region)
endif()

foreach(name region)
  string(FIND "${readme}" "```cpp\n${${name}}```" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "README.md does not show the ${name} code verbatim in a ```cpp block")
  endif()
endforeach()
message(STATUS "README.md shows the example app's code verbatim")
