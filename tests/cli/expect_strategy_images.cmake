# cmake -P driver: `render --integrator bdpt --strategies DIR` writes one weighted and one
# unweighted EXR per strategy (s, t) of paths up to --max-depth + 2 vertices, and a contact sheet;
# the MIS-weighted images sum to the bdpt image of the same seed and samples. EXE, SOURCE, WORK;
# INTEGRATOR (default bdpt): bdpt-cache the same, its light-vertex cache at its default counts
# (fewer light subpaths than pixels and one connection per camera vertex, so the tolerance's
# counts below hold for it too: each sample of a pixel adds at most `own` terms, and at most
# width x height light subpaths splat).
#
# The scene (scenes/depth_of_field.json: an environment, a sphere light, a thin lens) makes BDPT's
# connections draw random numbers (which light, which point on it, which lens point). Each strategy
# draws them from a stream of its own (kernels/bdpt.h), and the subpaths come before any connection,
# so a strategy rendered alone adds, bit for bit, the contributions it adds to the whole image. The
# sums then differ only in their order of float additions, and the tolerance is the bound on that.
if(NOT DEFINED INTEGRATOR)
  set(INTEGRATOR bdpt)
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(width 8)
set(height 8)
set(spp 2)
set(max_depth 2)
math(EXPR max_vertices "${max_depth} + 2")
execute_process(COMMAND ${EXE} render ${SOURCE}/scenes/depth_of_field.json --integrator ${INTEGRATOR} --max-depth ${max_depth}
                        --size ${width}x${height} --spp ${spp} --quiet --strategies ${WORK}/strategies -o ${WORK}/render.exr
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
set(problems)
if(NOT status EQUAL 0)
  list(APPEND problems "exit status ${status}: ${err}")
endif()
# paths of 2 to max_vertices vertices: k = s + t, every s in [0, k) with t >= 1, but s = t = 1 (a
# light seen directly: s = 0, t = 2 makes it, as in pbrt-v4)
set(weighted)      # the weighted images, for the sum
set(own 0)         # strategies with t >= 2: added to the sample's own pixel
set(splatting 0)   # strategies with t = 1: splatted where they land
foreach(k RANGE 2 ${max_vertices})
  math(EXPR last "${k} - 1")
  foreach(s RANGE 0 ${last})
    math(EXPR t "${k} - ${s}")
    if(s EQUAL 1 AND t EQUAL 1)
      continue()
    endif()
    foreach(kind weighted unweighted)
      if(NOT EXISTS ${WORK}/strategies/s${s}_t${t}_${kind}.exr)
        list(APPEND problems "no s${s}_t${t}_${kind}.exr")
      endif()
    endforeach()
    list(APPEND weighted s${s}_t${t}_weighted.exr)
    if(t EQUAL 1)
      math(EXPR splatting "${splatting} + 1")
    else()
      math(EXPR own "${own} + 1")
    endif()
  endforeach()
endforeach()
if(NOT EXISTS ${WORK}/strategies/contact_sheet.png)
  list(APPEND problems "no contact_sheet.png")
endif()

# The tolerance, from the float additions on each side (every term a contribution >= 0, so n
# additions in any order are within (n - 1) u of the exact sum, relative, u = 2^-24): a pixel of the
# bdpt image sums at most spp x own terms in its own accumulation and, in its splat buffer, at most
# every t = 1 contribution of the image, width x height x spp x splatting; then one addition and
# the division by spp. Each strategy image sums fewer of the same terms, and oiiotool adds the K
# images in K - 1 more. So |bdpt - sum| <= (2 n + K) u times the larger side, n the bdpt pixel's count.
list(LENGTH weighted images)
math(EXPR n "${spp} * ${own} + ${width} * ${height} * ${spp} * ${splatting} + 2")
math(EXPR units "2 * ${n} + ${images}")
math(EXPR tolerance_digits "${units} * 596046448")  # u = 5.96046448e-8
set(tolerance "${tolerance_digits}e-16")

find_program(OIIOTOOL oiiotool REQUIRED)
find_program(IDIFF idiff REQUIRED)
# sum.exr: the RGB of the images named, added in float
function(sum_images out)
  set(args)
  set(first TRUE)
  foreach(image ${ARGN})
    list(APPEND args ${WORK}/strategies/${image} --ch R,G,B)
    if(NOT first)
      list(APPEND args --add)
    endif()
    set(first FALSE)
  endforeach()
  execute_process(COMMAND ${OIIOTOOL} ${args} -d float -o ${WORK}/${out} RESULT_VARIABLE status ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    set(problems ${problems} "oiiotool sum: ${err}" PARENT_SCOPE)
  endif()
endfunction()
# 0: every pixel's channels within the tolerance of the bdpt image's
function(compare_with_render sum result)
  execute_process(COMMAND ${IDIFF} -fail 0 -failrelative ${tolerance} -warn 0 -warnrelative ${tolerance} ${WORK}/${sum} ${WORK}/render_rgb.exr
                  RESULT_VARIABLE status OUTPUT_VARIABLE report)
  set(${result} ${status} PARENT_SCOPE)
  set(report "${report}" PARENT_SCOPE)
endfunction()

if(NOT problems)
  execute_process(COMMAND ${OIIOTOOL} ${WORK}/render.exr --ch R,G,B -d float -o ${WORK}/render_rgb.exr)
  sum_images(sum.exr ${weighted})
  compare_with_render(sum.exr same)
  if(NOT same EQUAL 0)
    list(APPEND problems "the ${images} weighted strategy images do not sum to the ${INTEGRATOR} image within ${tolerance} (relative):\n${report}")
  endif()
  # without one strategy (s = 1, t = 2: next-event estimation at the first bounce) the sum must not match
  list(REMOVE_ITEM weighted s1_t2_weighted.exr)
  sum_images(sum_without_one.exr ${weighted})
  compare_with_render(sum_without_one.exr same)
  if(same EQUAL 0)
    list(APPEND problems "the weighted strategy images without s1_t2 still sum to the ${INTEGRATOR} image within ${tolerance}")
  endif()
endif()
include(${CMAKE_CURRENT_LIST_DIR}/finish_driver.cmake)
finish_driver("render --strategies in ${WORK}"
              "strategy images and contact sheet; their weighted sum is the ${INTEGRATOR} image within ${units} u (${tolerance}) relative, and without s1_t2 is not")
