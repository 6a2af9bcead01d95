// The single-source environment code (ibl/environment.h and the cube-map and distribution headers
// it includes), compiled as C++ for the host: namespace ibl, on the vocabulary of namespace
// single_source.
#pragma once

#include "single_source/host_vocabulary.hpp"

namespace ibl {
using namespace ::single_source;
#include "ibl/environment.h"
}  // namespace ibl

static_assert(sizeof(ibl::EnvironmentMap) == 16, "EnvironmentMap must match its OpenCL layout");
static_assert(sizeof(ibl::AliasEntry) == 8, "AliasEntry must match its OpenCL layout");
static_assert(sizeof(single_source::float4) == 16, "a texel is four packed floats, like an OpenCL float4");
