# cmake -P driver: runs EXE with ARGS ('|'-separated) and passes when its exit status is STATUS and
# its standard output and error together match EXPECT.
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status STREQUAL STATUS OR NOT "${out}${err}" MATCHES "${EXPECT}")
  message(FATAL_ERROR "${EXE} ${args}\nexit status ${status} (expected ${STATUS}); output should match '${EXPECT}':\n${out}\n${err}")
endif()
message(STATUS "ok: exit status ${status}")
