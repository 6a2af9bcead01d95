// Directional albedo: the fraction of light from one direction that the BSDF scatters,
// a(wo) = integral over the sphere of f(wo, wi) |cos theta_i| dwi, delta lobes included.
#pragma once

#include <cstdint>

#include "brdf/brdf.hpp"

namespace lab::validation {

struct AlbedoEstimate {
    brdf::float3 value;      // per channel
    brdf::float3 std_error;  // standard error of the mean, per channel
};

// Importance-sampled with the BSDF's own sampler over a jittered strata x strata grid of (u.y, u.z)
// (u.x, the lobe choice, is stratified too), so smooth integrands converge far faster than 1/sqrt(N).
AlbedoEstimate directional_albedo(const brdf::Material& m, brdf::float3 wo, int strata, uint64_t seed = 1);

}  // namespace lab::validation
