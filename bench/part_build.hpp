// `dtoadq bench breakdown`'s part builds: the path tracer's program with one part replaced or doubled
// (bench/kernels/part_standins.h), chosen by the define that names it (BENCH_STANDIN_RNG,
// BENCH_STANDIN_ENVIRONMENT, BENCH_STANDIN_BSDF, BENCH_TWICE_ENVIRONMENT).
#pragma once

#include <string>

#include "render/opencl_tuning.hpp"

namespace lab::bench {

// The entry file of the part builds' program, among the embedded kernel sources.
inline constexpr const char* kPartBuildProgram = "bench/kernels/path_tracer_standins.cl";

// Makes `tuning` build the part build that `define` chooses.
inline void use_part_build(render::OpenClTuning& tuning, const std::string& define) {
    tuning.program = kPartBuildProgram;
    tuning.extra_build_options += " -D" + define;
}

}  // namespace lab::bench
