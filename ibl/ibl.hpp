// The single-source environment code (ibl/environment.h and the cube-map and distribution headers
// it includes), compiled as C++ for the host: namespace ibl, on the vocabulary of namespace brdf.
#pragma once

// First: brdf/common.h belongs to namespace brdf, and its include guard keeps it there.
#include "brdf/brdf.hpp"

namespace ibl {
using namespace ::brdf;
#include "ibl/environment.h"
}  // namespace ibl

static_assert(sizeof(ibl::EnvironmentMap) == 16, "EnvironmentMap must match its OpenCL layout");
static_assert(sizeof(brdf::float4) == 16, "a texel is four packed floats, like an OpenCL float4");
