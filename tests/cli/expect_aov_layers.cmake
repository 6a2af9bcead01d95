# cmake -P driver: `dtoadq preview --aov albedo,normal,depth` (host build, a few paths) writes the
# first-hit AOVs as layers of its EXR that OpenImageIO (oiiotool) reads with the names Blender and
# Mitsuba give them: albedo.R/G/B, normal.X/Y/Z, depth.Z, beside R, G, B and the film's channels.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${EXE} preview --aov albedo,normal,depth --device host --spp 1 --size 16x12 --quiet -o aov.exr
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "preview --aov: status ${status}\n${out}\n${err}")
endif()
find_program(OIIOTOOL oiiotool REQUIRED)
execute_process(COMMAND ${OIIOTOOL} --info -v aov.exr WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE info)
foreach(expected "16 x   12, 17 channel, float" "channel list: [^\n]*R, G, B" "albedo\\.R" "albedo\\.G" "albedo\\.B" "normal\\.X" "normal\\.Y"
                 "normal\\.Z" "depth\\.Z" "film\\.sum\\.R")
  if(NOT info MATCHES "${expected}")
    message(FATAL_ERROR "aov.exr's header lacks '${expected}':\n${info}")
  endif()
endforeach()
message(STATUS "ok")
