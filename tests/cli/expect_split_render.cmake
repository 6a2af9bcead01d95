# cmake -P driver: one render split by sample range, merged, and resumed, through the command line
# (the sums themselves are checked by tests/test_render_sample_ranges.cpp). EXE, SOURCE, WORK.
# Renders parts 0:2 and 2:5 of the metaballs scene, merges them, and resumes the first part to 5
# samples; then every misuse must fail with one line naming the file and the field, and write nothing.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(problems)
set(scene ${SOURCE}/scenes/metaballs.json)
set(common ${scene} --size 12x12 --quiet)

function(run_ok what)
  execute_process(COMMAND ${EXE} ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    set(problems ${problems} "${what}: exit ${status}: ${err}" PARENT_SCOPE)
  endif()
endfunction()

# Fails unless the command exits 2 with one line on standard error matching `expect`, leaving `absent` unwritten.
function(run_error what absent expect)
  execute_process(COMMAND ${EXE} ${ARGN} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
  string(REGEX REPLACE "\n$" "" line "${err}")
  if(NOT status EQUAL 2 OR line MATCHES "\n" OR NOT line MATCHES "${expect}" OR EXISTS ${WORK}/${absent})
    set(problems ${problems} "${what}: exit ${status}, standard error '${err}', expected '${expect}'" PARENT_SCOPE)
  endif()
endfunction()

run_ok("part 0:2" render ${common} --samples 0:2 -o part0.exr)
run_ok("part 2:5" render ${common} --samples 2:5 -o part1.exr)
run_ok("merge" merge part0.exr part1.exr -o merged.exr --quiet)
foreach(f merged.exr merged.png)
  if(NOT EXISTS ${WORK}/${f})
    list(APPEND problems "merge wrote no ${f}")
  endif()
endforeach()
run_ok("resume 0:2 to 5" render ${common} --resume part0.exr --spp 5 -o resumed.exr)

set(E "^dtoadq: error: ")
# the merged file holds 0:5, so part 1 again overlaps it
run_error("merge overlap" m.exr "${E}part1\\.exr: dtoadq:sample_ranges: 2:5 overlaps the samples of the parts before it \\(0:5\\)"
          merge merged.exr part1.exr -o m.exr)
run_ok("part with another seed" render ${common} --seed 9 --samples 5:6 -o other.exr)
run_error("merge other seed" m.exr "${E}other\\.exr: dtoadq:seed: \"9\", but part0\\.exr has \"0\"" merge part0.exr other.exr -o m.exr)
run_error("resume another size" r.exr "${E}part0\\.exr: size: 12x12, but this render is 12x10"
          render ${scene} --size 12x10 --quiet --resume part0.exr --spp 5 -o r.exr)
run_error("resume another scene" r.exr "${E}part0\\.exr: dtoadq:scene: .*metaballs\\.json\", but this render has .*cornell_box\\.json"
          render ${SOURCE}/scenes/cornell_box.json --size 12x12 --quiet --resume part0.exr --spp 5 -o r.exr)
run_error("resume without more samples" r.exr "${E}--spp: 2 samples per pixel in all, but part0\\.exr already holds 2"
          render ${common} --resume part0.exr --spp 2 -o r.exr)
run_error("resume a PNG" r.exr "${E}part0\\.png: has no film to merge or resume" render ${common} --resume part0.png --spp 5 -o r.exr)
run_error("samples backwards" r.exr "${E}--samples: expected A:B" render ${common} --samples 5:2 -o r.exr)
run_error("samples and spp" r.exr "${E}--samples: gives the sample count itself" render ${common} --samples 0:2 --spp 4 -o r.exr)
run_error("merge to a PNG" m.png "${E}m\\.png: merge writes an \\.exr" merge part0.exr part1.exr -o m.png)

include(${CMAKE_CURRENT_LIST_DIR}/finish_driver.cmake)
finish_driver("split render in ${WORK}" "parts, merge and resume")
