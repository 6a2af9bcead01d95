#include "validation/sampling_efficiency.hpp"

#include <cmath>
#include <limits>

#include "validation/energy.hpp"
#include "validation/uniform_random.hpp"

namespace lab::validation {

namespace {

// Running mean and variance (Welford), in double: the estimator's values span many decades.
struct Moments {
    long n = 0;
    double mean = 0.0, m2 = 0.0;
    void add(double x) {
        ++n;
        double d = x - mean;
        mean += d / double(n);
        m2 += d * (x - mean);
    }
    double variance() const { return n > 1 ? m2 / double(n - 1) : 0.0; }
};

double channel_mean(brdf::float3 v) { return (double(v.x) + double(v.y) + double(v.z)) / 3.0; }

bool has_rough_transmission(const brdf::Material& material) {
    brdf::Material m = brdf::material_clamped(&material);
    return transmits(m) && !brdf::microfacet_is_smooth(brdf::microfacet_from_material(&m));
}

}  // namespace

SamplingEfficiency sampling_efficiency(const brdf::Material& material, brdf::float3 wo, long samples, uint64_t seed) {
    SamplingEfficiency e;
    e.samples = samples;
    e.two_sided = has_rough_transmission(material);

    Moments bsdf, cosine;
    long delta = 0, failed = 0;
    UniformRandom rng_bsdf(seed), rng_cosine(seed + 1);
    for (long k = 0; k < samples; ++k) {
        brdf::BsdfSample s = brdf::bsdf_sample(&material, wo, rng_bsdf.next_float3());
        double value = 0.0;
        if (s.flags & BSDF_DELTA) ++delta;
        else if (!s.flags) ++failed;
        else if (s.flags && s.pdf > 0.0f) value = channel_mean(s.f) * std::fabs(s.wi.z) / s.pdf;
        bsdf.add(value);

        brdf::float3 u = rng_cosine.next_float3();
        brdf::float3 wi = brdf::square_to_cosine_hemisphere(u.y, u.z);
        float pdf = brdf::cosine_hemisphere_pdf(wi.z);
        if (e.two_sided) {
            if (u.x < 0.5f) wi.z = -wi.z;  // lower hemisphere, mirrored
            pdf *= 0.5f;
        }
        double c = 0.0;
        if (pdf > 0.0f) c = channel_mean(brdf::bsdf_eval(&material, wo, wi)) * std::fabs(wi.z) / pdf;
        cosine.add(c);
    }
    e.mean_bsdf = bsdf.mean;
    e.mean_cosine = cosine.mean;
    e.variance_bsdf = bsdf.variance();
    e.variance_cosine = cosine.variance();
    e.has_delta_lobe = delta > 0;
    e.delta_fraction = samples > 0 ? double(delta) / double(samples) : 0.0;
    e.failed_fraction = samples > 0 ? double(failed) / double(samples) : 0.0;
    e.continuous_part = e.mean_bsdf > 0.0 || e.mean_cosine > 0.0;
    // variances below this share of the squared mean are rounding: the estimator is constant
    double zero = 1e-12 * std::fmax(e.mean_bsdf * e.mean_bsdf, e.mean_cosine * e.mean_cosine);
    if (!e.continuous_part) e.ratio = std::numeric_limits<double>::quiet_NaN();
    else if (e.variance_bsdf <= zero && e.variance_cosine <= zero) e.ratio = 1.0;
    else if (e.variance_bsdf <= zero) e.ratio = std::numeric_limits<double>::infinity();
    else e.ratio = e.variance_cosine / e.variance_bsdf;
    return e;
}

}  // namespace lab::validation
