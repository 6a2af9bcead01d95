# cmake -P driver: `render --integrator bdpt --strategies DIR` writes one weighted and one
# unweighted EXR per strategy (s, t) of paths up to --max-vertices, and a contact sheet. EXE, SOURCE, WORK.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${EXE} render ${SOURCE}/scenes/cornell_box.json --integrator bdpt --max-vertices 4 --size 8x8 --spp 1 --quiet
                        --strategies ${WORK}/strategies -o ${WORK}/render.exr
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
set(problems)
if(NOT status EQUAL 0)
  list(APPEND problems "exit status ${status}: ${err}")
endif()
# paths of 2 to 4 vertices: k = s + t, every s in [0, k] with t >= 1
foreach(k 2 3 4)
  math(EXPR last "${k} - 1")
  foreach(s RANGE 0 ${last})
    math(EXPR t "${k} - ${s}")
    foreach(kind weighted unweighted)
      if(NOT EXISTS ${WORK}/strategies/s${s}_t${t}_${kind}.exr)
        list(APPEND problems "no s${s}_t${t}_${kind}.exr")
      endif()
    endforeach()
  endforeach()
endforeach()
if(NOT EXISTS ${WORK}/strategies/contact_sheet.png)
  list(APPEND problems "no contact_sheet.png")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/finish_driver.cmake)
finish_driver("render --strategies in ${WORK}" "strategy images and contact sheet")
