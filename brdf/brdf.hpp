// The single-source BRDF module, compiled as C++ for the host: namespace brdf.
#pragma once

#include "host/glm_builtins.hpp"

namespace brdf {
#include "bsdf.h"
}  // namespace brdf
