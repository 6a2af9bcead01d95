// Helmholtz reciprocity in reflection: f(wo, wi) = f(wi, wo) for wo, wi in the upper hemisphere.
#pragma once

#include <cstdint>

#include "brdf/brdf.hpp"

namespace lab::validation {

struct ReciprocityResult {
    double max_relative_error = 0.0;  // max over pairs and channels of |f(wo,wi) - f(wi,wo)| / max(|.|, |.|)
    brdf::float3 wo{0.0f, 0.0f, 1.0f}, wi{0.0f, 0.0f, 1.0f};  // where it occurs
    brdf::float3 f_forward{0.0f}, f_reverse{0.0f};
    long pairs = 0;
};

// Relative difference of two BSDF values, the largest over channels; 0 where both are 0.
double relative_difference(brdf::float3 a, brdf::float3 b);

// `pairs` random direction pairs, uniform over the upper hemisphere.
ReciprocityResult reciprocity_error(const brdf::Material& material, long pairs, uint64_t seed = 1);

}  // namespace lab::validation
