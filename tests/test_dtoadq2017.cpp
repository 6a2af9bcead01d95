// What the 2017 model fails and what it passes, pinned down so the lab's report can quote it:
// it is not reciprocal, it gains energy, its Hyper-Cauchy lobe peaks at retro-reflection, its
// values are clamped to 1; its cosine sampler is consistent with its pdf.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "validation/chi_square.hpp"
#include "validation/energy.hpp"
#include "validation/random_inputs.hpp"
#include "validation/reciprocity.hpp"

using namespace lab::validation;

namespace {

// presets/dtoadq2017_typical.json
brdf::Material typical() {
    brdf::Material m = brdf::default_material();
    m.model = BRDF_MODEL_DTOADQ2017;
    m.albedo[0] = 0.8f;
    m.albedo[1] = 0.55f;
    m.albedo[2] = 0.35f;
    m.roughness = 0.4f;
    m.metallic = 0.5f;
    m.fresnel = 0.5f;
    m.subsurface = 0.2f;
    m.hc_shape = 2.0f;
    m.weight_diffuse = m.weight_glossy = 0.5f;
    return m;
}

}  // namespace

// The figures docs/dtoadq2017.md quotes, pinned: each must stay within the noise of its estimator,
// a figure that does not come from the value it checks.

TEST_CASE("dtoadq2017 is not reciprocal", "[dtoadq2017]") {
    // The worst error over 100000 random pairs is a maximum, whose noise has no closed form: it is
    // measured over five other seeds. The pin must lie within four of their standard deviations.
    const double pinned = 0.545;
    ReciprocityResult r = reciprocity_error(typical(), 100000, 1);
    double sum = 0.0, sum_sq = 0.0;
    for (uint64_t seed = 2; seed <= 6; ++seed) {
        double e = reciprocity_error(typical(), 100000, seed).max_relative_error;
        sum += e;
        sum_sq += e * e;
    }
    const double mean = sum / 5.0, sd = std::sqrt(std::max(0.0, (sum_sq - 5.0 * mean * mean) / 4.0));
    std::printf("dtoadq2017: worst reciprocity error %.3g (pinned %.3g; other seeds %.3g +- %.2g)\n", r.max_relative_error, pinned,
                mean, sd);
    CHECK(std::fabs(r.max_relative_error - pinned) <= 4.0 * sd + 5e-4);  // + the pin's rounding to 3 digits
    CHECK(std::fabs(mean - pinned) <= 4.0 * sd + 5e-4);
}

TEST_CASE("dtoadq2017 gains energy in the white furnace", "[dtoadq2017]") {
    brdf::Material m = typical();
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    AlbedoPeak peak = max_directional_albedo(m, FurnaceOptions());
    const double pinned = 2.258;
    std::printf("dtoadq2017: largest albedo %.4f +- %.1e at theta %.1f (pinned %.3f)\n", peak.albedo, peak.std_error, peak.theta_deg,
                pinned);
    CHECK(peak.theta_deg == 85.0f);
    CHECK(std::fabs(peak.albedo - pinned) <= 4.0 * peak.std_error + 5e-4);
}

TEST_CASE("dtoadq2017's Hyper-Cauchy lobe peaks at retro-reflection, not at the mirror direction", "[dtoadq2017]") {
    brdf::Material m = typical();
    m.metallic = 1.0f;
    m.roughness = 0.2f;
    m.subsurface = 0.0f;
    m.weight_diffuse = 0.0f;
    m.weight_glossy = 1.0f;
    for (float theta : {30.0f, 45.0f, 60.0f}) {
        brdf::float3 wo = brdf::direction_from_degrees(theta, 0.0f);
        brdf::float3 mirror(-wo.x, -wo.y, wo.z);
        float retro = brdf::bsdf_eval(&m, wo, wo).x, specular = brdf::bsdf_eval(&m, wo, mirror).x;
        INFO("theta " << theta << ": f(wo, wo) " << retro << ", f(wo, mirror) " << specular);
        CHECK(retro > specular);
        // the lab model with the same parameters peaks where a mirror does
        brdf::Material lab = m;
        lab.model = BRDF_MODEL_LAB;
        CHECK(brdf::bsdf_eval(&lab, wo, mirror).x > brdf::bsdf_eval(&lab, wo, wo).x);
    }
}

TEST_CASE("dtoadq2017 clamps every value to 1", "[dtoadq2017]") {
    UniformRandom rng(17);
    float largest = 0.0f;
    long clamped = 0;
    for (int i = 0; i < 200000; ++i) {
        brdf::Material m = random_material(rng, BRDF_MODEL_DTOADQ2017);
        brdf::float3 f = brdf::bsdf_eval(&m, uniform_hemisphere_direction(rng), uniform_hemisphere_direction(rng));
        largest = std::fmax(largest, brdf::max_component(f));
        clamped += brdf::max_component(f) == 1.0f;
    }
    // the count is binomial: the pinned fraction p gives a standard deviation sqrt(n p (1 - p))
    const double n = 200000.0, pinned = 11973.0, p = pinned / n, sd = std::sqrt(n * p * (1.0 - p));
    std::printf("dtoadq2017: largest value %.3f, %ld of 200000 random evaluations clamped to 1 (pinned %.0f +- %.0f)\n", largest,
                clamped, pinned, sd);
    CHECK(largest == 1.0f);
    CHECK(std::fabs(double(clamped) - pinned) <= 4.0 * sd);
}

TEST_CASE("dtoadq2017's cosine sampler passes the chi-square test", "[dtoadq2017]") {
    brdf::Material m = typical();
    double smallest = 1.0;
    for (float theta : {0.0f, 28.0f, 52.0f, 71.0f, 86.0f}) {
        ChiSquareOptions options;
        options.tests = 5;
        options.seed = uint64_t(theta) + 5000;
        ChiSquareResult r = chi_square_bsdf(m, brdf::direction_from_degrees(theta, 60.0f), options);
        INFO("theta " << theta << ": " << describe(r));
        CHECK(r.passed);
        smallest = std::fmin(smallest, r.p_value);
    }
    std::printf("dtoadq2017: chi-square of the cosine sampler, smallest p-value %.3g over 5 directions\n", smallest);
}
