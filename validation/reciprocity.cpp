#include "validation/reciprocity.hpp"

#include <cmath>
#include <limits>

#include "validation/random_inputs.hpp"
#include "validation/uniform_random.hpp"

namespace lab::validation {

double relative_difference(brdf::float3 a, brdf::float3 b) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        double x = a[c], y = b[c];
        double scale = std::fmax(std::fabs(x), std::fabs(y));
        // below the smallest normal float, rounding is absolute and a ratio means nothing
        if (!(scale >= std::numeric_limits<float>::min())) continue;
        worst = std::fmax(worst, std::fabs(x - y) / scale);
    }
    if (!brdf::finite3(a) || !brdf::finite3(b)) return std::numeric_limits<double>::infinity();
    return worst;
}

ReciprocityResult reciprocity_error(const brdf::Material& material, long pairs, uint64_t seed) {
    ReciprocityResult r;
    UniformRandom rng(seed);
    for (long i = 0; i < pairs; ++i) {
        brdf::float3 wo = uniform_hemisphere_direction(rng), wi = uniform_hemisphere_direction(rng);
        brdf::float3 forward = brdf::bsdf_eval(&material, wo, wi), reverse = brdf::bsdf_eval(&material, wi, wo);
        double e = relative_difference(forward, reverse);
        if (e > r.max_relative_error || i == 0) {
            r.max_relative_error = e;
            r.wo = wo;
            r.wi = wi;
            r.f_forward = forward;
            r.f_reverse = reverse;
        }
    }
    r.pairs = pairs;
    return r;
}

}  // namespace lab::validation
