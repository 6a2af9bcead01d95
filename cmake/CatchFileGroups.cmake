# catch_file_groups(<target> SPEC <spec> PREFIX <prefix> WORKING_DIRECTORY <dir> [TIMEOUT <s>] [LABELS <l>]
#                   [NAME <name>] [BATCHES <"file file ..."> ...])
# Registers a Catch2 executable's test cases with ctest by source file: one ctest test per test file
# runs that file's cases that <spec> selects, except the [sweep] cases, each of which is a ctest test
# of its own (they are the long ones, so they start first and spread over the cores). The files of
# one BATCHES entry (short files: their cases take less than the process's start) share one test,
# named after them, "<prefix>test_a+test_b+..."
# NAME (default: the target) names the generated files, so one target can be registered twice
# with specs of their own..
# Why not one ctest test per case (catch_discover_tests): each test process loads OpenImageIO and
# its 260 shared libraries, 0.27 s of CPU before main (0.54 s under the sanitizers): 445 starts
# would take about 87 s of the test command's time on two cores, 136 take about 26 s, and batching
# the short files saves some 60 starts more. The cases are the
# same; a failing group's output names its failing case. The list is read off the built
# executable, as catch_discover_tests does.
set(_CATCH_FILE_GROUPS_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/catch_file_groups_discover.cmake)

function(catch_file_groups target)
  cmake_parse_arguments(ARG "" "SPEC;PREFIX;WORKING_DIRECTORY;TIMEOUT;LABELS;NAME" "BATCHES" ${ARGN})
  if(NOT ARG_NAME)
    set(ARG_NAME ${target})
  endif()
  set(batches "")
  foreach(batch IN LISTS ARG_BATCHES)
    string(STRIP "${batch}" batch)
    string(REGEX REPLACE " +" "+" batch "${batch}")
    list(APPEND batches "${batch}")
  endforeach()
  list(JOIN batches "|" batches)
  set(tests_file ${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_file_groups.cmake)
  set(include_file ${CMAKE_CURRENT_BINARY_DIR}/${ARG_NAME}_file_groups_include.cmake)
  add_custom_command(TARGET ${target} POST_BUILD BYPRODUCTS ${tests_file}
    COMMAND ${CMAKE_COMMAND} -D "EXECUTABLE=$<TARGET_FILE:${target}>" -D "SPEC=${ARG_SPEC}" -D "PREFIX=${ARG_PREFIX}"
            -D "WORKING_DIRECTORY=${ARG_WORKING_DIRECTORY}" -D "TIMEOUT=${ARG_TIMEOUT}" -D "LABELS=${ARG_LABELS}" -D "BATCHES=${batches}"
            -D "OUTPUT=${tests_file}" -P ${_CATCH_FILE_GROUPS_SCRIPT}
    VERBATIM)
  # Before the first build the executable cannot be listed: a test that fails says so.
  file(WRITE ${include_file}
    "if(EXISTS \"${tests_file}\")\n  include(\"${tests_file}\")\nelse()\n  add_test(${ARG_NAME}_NOT_BUILT ${ARG_NAME}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include_file})
endfunction()
