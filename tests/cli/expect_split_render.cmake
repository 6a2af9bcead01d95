# cmake -P driver: one render split by sample range, merged, and resumed, through the command line
# (the sums themselves are checked by tests/test_render_sample_ranges.cpp). EXE, SOURCE, WORK.
# Renders parts 0:2 and 2:5 of the metaballs scene, merges them, and resumes the first part to 5
# samples; then every misuse must fail with one line naming the file and the field, and write nothing.
# Then the same for BDPT on the Cornell box (on the host build, which needs no kernel build): its
# parts merge and resume, and a part that differs in the integrator, the MIS heuristic or the path
# length is refused by both.
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

# BDPT: its settings are in the file, and what changes its estimate is compared
set(cornell ${SOURCE}/scenes/cornell_box.json --device host --size 12x12 --quiet)
set(bdpt ${cornell} --integrator bdpt)
run_ok("bdpt part 0:2" render ${bdpt} --samples 0:2 -o bdpt0.exr)
run_ok("bdpt part 2:4" render ${bdpt} --samples 2:4 -o bdpt1.exr)
run_ok("bdpt merge" merge bdpt0.exr bdpt1.exr -o bdpt.exr --quiet)
run_ok("bdpt resume 0:2 to 4" render ${bdpt} --resume bdpt0.exr --spp 4 -o bdpt_resumed.exr)
find_program(OIIOTOOL oiiotool REQUIRED)
execute_process(COMMAND ${OIIOTOOL} --info -v bdpt.exr WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE info)
foreach(expected "dtoadq:integrator: \"bdpt\"" "dtoadq:mis_heuristic: \"balance\"" "dtoadq:max_vertices: [0-9]+" "dtoadq:sample_ranges: \"0:4\"")
  if(NOT info MATCHES "${expected}")
    list(APPEND problems "the merged BDPT render's header lacks '${expected}'")
  endif()
endforeach()
run_ok("bdpt part, power heuristic" render ${bdpt} --mis power --samples 4:5 -o power.exr)
run_ok("bdpt part, shorter paths" render ${bdpt} --max-depth 3 --samples 4:5 -o short.exr)
run_ok("lt part" render ${cornell} --integrator lt --samples 4:5 -o lt.exr)
run_error("merge another MIS heuristic" m.exr "${E}power\\.exr: dtoadq:mis_heuristic: \"power\", but bdpt0\\.exr has \"balance\""
          merge bdpt0.exr power.exr -o m.exr)
run_error("merge another path length" m.exr "${E}short\\.exr: dtoadq:max_depth: \"3\", but bdpt0\\.exr has \"[0-9]+\""
          merge bdpt0.exr short.exr -o m.exr)
run_error("merge another integrator" m.exr "${E}lt\\.exr: dtoadq:integrator: \"lt\", but bdpt0\\.exr has \"bdpt\""
          merge bdpt0.exr lt.exr -o m.exr)
run_error("resume with another MIS heuristic" r.exr "${E}bdpt0\\.exr: dtoadq:mis_heuristic: \"balance\", but this render has \"power\""
          render ${bdpt} --mis power --resume bdpt0.exr --spp 4 -o r.exr)
run_error("resume with another path length" r.exr "${E}bdpt0\\.exr: dtoadq:max_depth: \"[0-9]+\", but this render has \"3\""
          render ${bdpt} --max-depth 3 --resume bdpt0.exr --spp 4 -o r.exr)
run_error("resume with the path tracer" r.exr "${E}bdpt0\\.exr: dtoadq:integrator: \"bdpt\", but this render has \"pt\""
          render ${cornell} --integrator pt --resume bdpt0.exr --spp 4 -o r.exr)

include(${CMAKE_CURRENT_LIST_DIR}/finish_driver.cmake)
finish_driver("split render in ${WORK}" "parts, merge and resume")
