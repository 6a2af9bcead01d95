// How much the material's own sampler helps: the variance of the one-sample estimator
// f |cos theta_i| / pdf of the directional albedo, with bsdf_sample() against plain cosine-weighted
// hemisphere sampling, for one wo. The estimator's value is the mean of its three RGB channels.
// Delta lobes (mirror, smooth refraction) are out of reach of cosine sampling, so both estimators
// measure only the continuous part: a delta sample from bsdf_sample() counts as 0.
#pragma once

#include <cstdint>

#include "brdf/brdf.hpp"

namespace lab::validation {

struct SamplingEfficiency {
    long samples = 0;                // per strategy
    double mean_bsdf = 0.0;          // both estimate the continuous part's directional albedo
    double mean_cosine = 0.0;
    double variance_bsdf = 0.0;      // per-sample variance of the estimator
    double variance_cosine = 0.0;
    double ratio = 0.0;              // variance_cosine / variance_bsdf; > 1: the material's sampler is better;
                                     // 1 when both are 0 (e.g. Lambert); NaN without a continuous part
    bool has_delta_lobe = false;     // bsdf_sample() returned delta samples; they were excluded
    double delta_fraction = 0.0;     // share of bsdf_sample() draws that were delta
    double failed_fraction = 0.0;    // share of bsdf_sample() draws that failed (flags 0): each adds a 0
    bool two_sided = false;          // cosine sampling covered both hemispheres (rough transmission)
    bool continuous_part = true;     // false when the continuous part is 0 (a smooth mirror or glass)
};

// wo in the local frame with wo.z > 0. Two-sided cosine sampling (a hemisphere picked with
// probability 1/2) is used where the material has rough transmission, so both strategies cover
// the whole continuous part. Deterministic for a seed.
SamplingEfficiency sampling_efficiency(const brdf::Material& material, brdf::float3 wo, long samples, uint64_t seed = 1);

}  // namespace lab::validation
