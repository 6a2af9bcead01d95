# The end of a cmake -P test driver: fails with `context` and the list `problems` joined, or
# reports `ok_text`. include() it, then call finish_driver().
macro(finish_driver context ok_text)
  if(problems)
    string(REPLACE ";" ", " problems "${problems}")
    message(FATAL_ERROR "${context}\n${problems}")
  endif()
  message(STATUS "ok: ${ok_text}")
endmacro()
