# embed_files(<target> NAMESPACE <ns> BASE <dir> FILES <files...>)
# Builds a static library <target> that holds the files' text, looked up by their path relative to
# BASE:  std::string_view <ns>::embedded_file(std::string_view path)  (empty view if absent), and
#        const std::vector<std::string_view>& <ns>::embedded_paths().
# The generated source is rebuilt whenever one of the files changes.
set(_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_generate.cmake)

function(embed_files target)
  cmake_parse_arguments(ARG "" "NAMESPACE;BASE" "FILES" ${ARGN})
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp)
  set(abs_files)
  foreach(f ${ARG_FILES})
    get_filename_component(a ${f} ABSOLUTE BASE_DIR ${ARG_BASE})
    list(APPEND abs_files ${a})
  endforeach()
  string(REPLACE ";" "|" files_arg "${abs_files}")
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DNAMESPACE=${ARG_NAMESPACE} -DBASE=${ARG_BASE} "-DFILES=${files_arg}" -P ${_EMBED_SCRIPT}
    DEPENDS ${abs_files} ${_EMBED_SCRIPT}
    COMMENT "Embedding ${target}"
    VERBATIM)
  add_library(${target} STATIC ${out})
endfunction()
