# The README's C++ block is real code: the marked part of
# examples/first_window/main.cpp ("// [readme]" to "// [/readme]"), verbatim
# (the example is built and run by CTest, and by the package test against the
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
# The end mark's own indentation is not part of the region.
string(REGEX REPLACE "[ ]+$" "" region "${region}")

foreach(name region)
  string(FIND "${readme}" "```cpp\n${${name}}```" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "README.md does not show the ${name} code verbatim in a ```cpp block")
  endif()
endforeach()
message(STATUS "README.md shows the example app's code verbatim")
