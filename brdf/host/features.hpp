// Which BRDF features (brdf/features.h) a set of materials needs, so a scene's kernel compiles only
// those: a gold-only scene gets neither the diffuse lobes nor Hyper-Cauchy nor the dielectric.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "brdf/brdf.hpp"

namespace brdf {

// Every switch of brdf/features.h, in its order, with whether one of the materials needs it.
std::vector<std::pair<std::string, bool>> used_features(const std::vector<Material>& materials);

// The switches as "#define BRDF_FEATURE_X 0|1" lines, for the top of a generated kernel source.
std::string feature_defines(const std::vector<Material>& materials);

// The same as OpenCL build options "-DBRDF_FEATURE_X=0 ...", for kernels built from fixed files.
std::string feature_build_options(const std::vector<Material>& materials);

}  // namespace brdf
