# unity_groups(<target> <dir> "<names of group 1>" "<names of group 2>" ...)
# Compiles each listed group of <dir>/<name>.cpp as one translation unit (CMake's unity build, GROUP
# mode). Files in no group, and every file added later, compile alone as before; so a new file can
# never clash with a name in another file, and a group changes only when someone edits this list.
# Inside a group, a file sees the file-scope names (anonymous namespaces included) and using-
# directives of the files before it: the groups hold files that compile together cleanly and have no
# using-directive at file scope except where every file of the group has the same one.
function(unity_groups target dir)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  set(index 0)
  foreach(group IN LISTS ARGN)
    string(REPLACE " " ";" names "${group}")
    foreach(name IN LISTS names)
      set_source_files_properties(${dir}/${name}.cpp PROPERTIES UNITY_GROUP ${target}_${index})
    endforeach()
    math(EXPR index "${index} + 1")
  endforeach()
endfunction()
