#include "validation/albedo.hpp"

#include <cmath>
#include <random>

namespace lab::validation {

AlbedoEstimate directional_albedo(const brdf::Material& m, brdf::float3 wo, int strata, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const long n = long(strata) * strata;
    double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
    for (int i = 0; i < strata; ++i) {
        for (int j = 0; j < strata; ++j) {
            // u.x stratified along a shuffled order of cells so lobe choice is balanced too
            long k = long(i) * strata + j;
            float ux = (float((k * 7919) % n) + uniform(rng)) / float(n);
            brdf::float3 u(std::fmin(ux, 0.99999994f), (float(i) + uniform(rng)) / float(strata), (float(j) + uniform(rng)) / float(strata));
            u.y = std::fmin(u.y, 0.99999994f);
            u.z = std::fmin(u.z, 0.99999994f);
            brdf::BsdfSample s = brdf::bsdf_sample(&m, wo, u);
            if (!s.flags || !(s.pdf > 0.0f)) continue;
            brdf::float3 w = s.f * (std::fabs(s.wi.z) / s.pdf);
            for (int c = 0; c < 3; ++c) {
                sum[c] += w[c];
                sum2[c] += double(w[c]) * w[c];
            }
        }
    }
    AlbedoEstimate e;
    for (int c = 0; c < 3; ++c) {
        double mean = sum[c] / double(n);
        double var = std::fmax(sum2[c] / double(n) - mean * mean, 0.0);
        e.value[c] = float(mean);
        e.std_error[c] = float(std::sqrt(var / double(n)));
    }
    return e;
}

}  // namespace lab::validation
