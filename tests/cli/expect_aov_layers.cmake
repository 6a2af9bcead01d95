# cmake -P driver: `dtoadq preview --aov albedo,normal,depth,slot,variance,samples` (host build, a
# few paths) writes the AOVs as layers of its EXR that OpenImageIO (oiiotool) reads with the names
# Blender and Mitsuba give them: albedo.R/G/B, normal.X/Y/Z, depth.Z, IndexMA.X, variance.R/G/B,
# samples.X, beside R, G, B and the film's channels (its squares among them); every pixel's
# samples.X is the spp (oiiotool's statistics of the channel: min and max 3). The light tracer,
# whose image is all splats, writes the variance too, from its film's per-pass squares
# (film.squares.passes), finite on every pixel.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${EXE} preview --aov albedo,normal,depth,slot,variance,samples --device host --spp 3 --size 16x12 --quiet -o aov.exr
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "preview --aov: status ${status}\n${out}\n${err}")
endif()
find_program(OIIOTOOL oiiotool REQUIRED)
execute_process(COMMAND ${OIIOTOOL} --info -v aov.exr WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE info)
foreach(expected "16 x   12, 25 channel, float" "channel list: [^\n]*R, G, B" "albedo\\.R" "albedo\\.G" "albedo\\.B" "normal\\.X" "normal\\.Y"
                 "normal\\.Z" "depth\\.Z" "IndexMA\\.X" "variance\\.R" "variance\\.G" "variance\\.B" "samples\\.X" "film\\.sum\\.R"
                 "film\\.squares\\.B")
  if(NOT info MATCHES "${expected}")
    message(FATAL_ERROR "aov.exr's header lacks '${expected}':\n${info}")
  endif()
endforeach()
execute_process(COMMAND ${OIIOTOOL} aov.exr --ch samples.X --printstats WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE stats)
if(NOT stats MATCHES "Stats Min: 3\\.0* " OR NOT stats MATCHES "Stats Max: 3\\.0* ")
  message(FATAL_ERROR "samples.X is not 3 on every pixel:\n${stats}")
endif()
execute_process(COMMAND ${EXE} render ${SOURCE}/scenes/metaballs.json --integrator lt --aov variance --spp 4 --size 16x16 --quiet -o lt.exr
                WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "render --integrator lt --aov variance: status ${status}\n${out}\n${err}")
endif()
execute_process(COMMAND ${OIIOTOOL} --info -v lt.exr WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE info)
foreach(expected "variance\\.R" "variance\\.B" "film\\.squares\\.passes")
  if(NOT info MATCHES "${expected}")
    message(FATAL_ERROR "lt.exr's header lacks '${expected}':\n${info}")
  endif()
endforeach()
execute_process(COMMAND ${OIIOTOOL} lt.exr --ch variance.R --printstats WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE stats)
if(NOT stats MATCHES "NanCount: 0" OR NOT stats MATCHES "InfCount: 0" OR stats MATCHES "Stats Max: 0\\.0* ")
  message(FATAL_ERROR "the light tracer's variance.R is not finite and positive somewhere:\n${stats}")
endif()
message(STATUS "ok")
