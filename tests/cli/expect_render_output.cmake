# cmake -P driver: `dtoadq preview` run in an empty folder WORK (the test model is built in, the
# preset and environment come from SOURCE) writes a linear OpenEXR whose header carries the render's
# metadata and the film it was resolved from (docs/distributed.md) and an sRGB PNG beside it; `--time` renders until the time is up, then writes as well;
# `dtoadq render` of a scene file does the same, with and without the OpenCL device.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run)
  execute_process(COMMAND ${EXE} ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${EXE} ${ARGN}\nstatus ${status}\n${out}\n${err}")
  endif()
endfunction()

function(expect_magic file hex)
  if(NOT EXISTS ${WORK}/${file})
    message(FATAL_ERROR "${file} was not written")
  endif()
  string(LENGTH ${hex} digits)
  math(EXPR bytes "${digits} / 2")
  file(READ ${WORK}/${file} magic LIMIT ${bytes} HEX)
  if(NOT magic STREQUAL hex)
    message(FATAL_ERROR "${file} does not start with ${hex} (got ${magic})")
  endif()
endfunction()

run(preview --material ${SOURCE}/presets/gold.json --env ${SOURCE}/envmaps/studio.exr --spp 4 --size 48x32 --seed 3 --quiet -o out.exr)
expect_magic(out.exr 762f3101)
expect_magic(out.png 89504e470d0a1a0a)
find_program(OIIOTOOL oiiotool REQUIRED)
function(expect_header file)
  execute_process(COMMAND ${OIIOTOOL} --info -v ${file} WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE info)
  foreach(expected ${ARGN})
    if(NOT info MATCHES "${expected}")
      message(FATAL_ERROR "${file}'s header lacks '${expected}':\n${info}")
    endif()
  endforeach()
endfunction()
expect_header(out.exr "48 x   32, 13 channel, float" "channel list: R, G, B, film.nonfinite, film.splat.R, film.splat.G, film.splat.B, film.squares.R, film.squares.G, film.squares.B, film.sum.R, film.sum.G, film.sum.B" "dtoadq:sample_ranges: \"0:4\"" "dtoadq:spp: 4" "dtoadq:material: \"gold\"" "dtoadq:environment: \".*studio.exr\""
              "dtoadq:ibl_sampling: \"mis\"" "dtoadq:seed: \"3\"" "dtoadq:nonfinite_samples: \"0\"" "dtoadq:seconds: ")

run(preview --env constant:0.5,0.5,0.5 --time 1 --size 32x32 --quiet -o timed.png)
expect_magic(timed.png 89504e470d0a1a0a)

foreach(device cpu host)
  run(render ${SOURCE}/scenes/metaballs.json --spp 2 --size 32x24 --seed 5 --light-selection uniform --device ${device} --quiet
      -o scene_${device}.exr)
  expect_magic(scene_${device}.png 89504e470d0a1a0a)
  expect_header(scene_${device}.exr "32 x   24, 13 channel, float" "dtoadq:spp: 2" "dtoadq:integrator: \"pt\""
                "dtoadq:light_sampling: \"mis\"" "dtoadq:light_selection: \"uniform\"" "dtoadq:scene: \".*metaballs.json\"")
endforeach()
message(STATUS "ok")
