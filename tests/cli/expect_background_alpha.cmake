# cmake -P driver: `dtoadq preview --background-opacity 0` (host build, a few paths) writes an alpha
# channel A beside R, G, B, which OpenImageIO reads: the model's pixels 1, the sky's 0, and the sky's
# RGB 0 (docs/environments.md, "Background"). At opacity 1 there is no A.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
find_program(OIIOTOOL oiiotool REQUIRED)
foreach(opacity 0 1)
  execute_process(COMMAND ${EXE} preview --background-opacity ${opacity} --ground off --device host --spp 2 --size 16x16 --quiet -o a${opacity}.exr
                  WORKING_DIRECTORY ${WORK} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "preview --background-opacity ${opacity}: status ${status}\n${out}\n${err}")
  endif()
  execute_process(COMMAND ${OIIOTOOL} --info -v a${opacity}.exr WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE info)
  if(opacity EQUAL 0 AND NOT info MATCHES "channel list: [^\n]*, A[,\n]")
    message(FATAL_ERROR "a0.exr lacks the channel A:\n${info}")
  endif()
  if(opacity EQUAL 1 AND info MATCHES "channel list: [^\n]*, A[,\n]")
    message(FATAL_ERROR "a1.exr has a channel A at opacity 1:\n${info}")
  endif()
endforeach()
# the top-left pixel sees the sky (the test model without its ground): alpha 0 and RGB 0; the centre
# sees the model: alpha 1
execute_process(COMMAND ${OIIOTOOL} a0.exr --ch R,G,B,A -o rgba.exr WORKING_DIRECTORY ${WORK})
execute_process(COMMAND ${OIIOTOOL} --dumpdata rgba.exr WORKING_DIRECTORY ${WORK} OUTPUT_VARIABLE dump)
if(NOT dump MATCHES "Pixel \\(0, 0\\): 0\\.0+ 0\\.0+ 0\\.0+ 0\\.0+\n")
  message(FATAL_ERROR "a0.exr's sky pixel is not 0 0 0 0:\n${dump}")
endif()
if(NOT dump MATCHES "Pixel \\(8, 8\\): [0-9.e+-]+ [0-9.e+-]+ [0-9.e+-]+ 1\\.0+\n")
  message(FATAL_ERROR "a0.exr's model pixel has no alpha 1:\n${dump}")
endif()
message(STATUS "ok")
