/* The path tracer's program (kernels/path_tracer.cl) for `dtoadq bench breakdown`'s part builds: the
 * stand-ins of bench/kernels/part_standins.h, chosen by its -D options, declared after the scene and
 * before the path tracer, so that they redirect the path tracer's own calls only. Built in place of
 * the path tracer's program through OpenClTuning::program (bench/part_build.hpp). */
#pragma OPENCL FP_CONTRACT OFF

#include "scene/materials.h" /* the feature switches, before any brdf/ header */
#include "scene/generated.h"

#include "kernels/material_layout.h"
#include "bench/kernels/part_standins.h"
#include "kernels/path_tracer.cl"
