# Run after the Catch2 executable EXECUTABLE is built (cmake/CatchFileGroups.cmake): writes OUTPUT,
# the ctest tests of its cases that SPEC selects, one per [sweep] case and one per source file for
# the rest. Catch's -# gives each case the tag [#<file name>].

function(list_catch output_var)
  execute_process(COMMAND ${EXECUTABLE} "-#" ${ARGN} OUTPUT_VARIABLE out RESULT_VARIABLE rc WORKING_DIRECTORY ${WORKING_DIRECTORY})
  if(rc LESS 0 OR NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "${EXECUTABLE} ${ARGN}: ${rc}\n${out}")
  endif()
  string(REPLACE ";" "\\;" out "${out}")
  string(REPLACE "\n" ";" out "${out}")
  set(${output_var} "${out}" PARENT_SCOPE)
endfunction()

set(properties "WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==]")
if(TIMEOUT)
  string(APPEND properties " TIMEOUT ${TIMEOUT}")
endif()
if(LABELS)
  string(APPEND properties " LABELS ${LABELS}")
endif()
set(script "")
function(add_catch_test name spec)
  string(APPEND script "add_test([==[${PREFIX}${name}]==] [==[${EXECUTABLE}]==] \"-#\" [==[${spec}]==] --warn NoTests)\n"
                       "set_tests_properties([==[${PREFIX}${name}]==] PROPERTIES ${properties})\n")
  set(script "${script}" PARENT_SCOPE)
endfunction()

# The sweeps first: the longest tests, started while the other core has the short ones to run.
list_catch(names "${SPEC}[sweep]" --list-test-names-only)
foreach(name IN LISTS names)
  if(name STREQUAL "")
    continue()
  endif()
  set(escaped "${name}")
  foreach(char "\\" "," "[" "]")
    string(REPLACE "${char}" "\\${char}" escaped "${escaped}")
  endforeach()
  add_catch_test("${name}" "${escaped}")
endforeach()

# Then every file that has a selected case that is not a sweep: --list-tags prints "  <count>  [#file]".
list_catch(lines "${SPEC}~[sweep]" --list-tags)
foreach(line IN LISTS lines)
  if(line MATCHES "^ *[0-9]+ +\\[#([A-Za-z0-9_]+)\\]$")
    add_catch_test("${CMAKE_MATCH_1}" "[#${CMAKE_MATCH_1}]${SPEC}~[sweep]")
  endif()
endforeach()
file(WRITE ${OUTPUT} "${script}")
