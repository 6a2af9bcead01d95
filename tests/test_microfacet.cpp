// The microfacet distributions against their defining integrals: D is normalised (integral of
// D cos over the hemisphere is 1), Smith's Lambda makes the projected area of the visible facets
// equal to cos theta_o, Hyper-Cauchy of shape 2 is GGX, and the incomplete beta function behind
// the Hyper-Cauchy Lambda matches closed forms.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "tests/points_of_run.hpp"
#include "validation/random_inputs.hpp"
#include "validation/sphere_quadrature.hpp"

using namespace lab::validation;

namespace {

// GGX and Hyper-Cauchy at several widths (alpha_x, alpha_y), anisotropic ones included.
std::vector<brdf::Microfacet> distributions() {
    const float widths[][2] = {{0.01f, 0.01f}, {0.2f, 0.2f}, {1.0f, 1.0f}, {0.6f, 0.15f}, {0.05f, 0.3f}};
    std::vector<brdf::Microfacet> all;
    for (const auto& w : widths) {
        all.push_back(brdf::microfacet_make(BRDF_DISTRIBUTION_GGX, w[0], w[1], 2.0f));
        for (float shape : {1.6f, 2.0f, 3.0f, 8.0f, 16.0f})
            all.push_back(brdf::microfacet_make(BRDF_DISTRIBUTION_HYPER_CAUCHY, w[0], w[1], shape));
    }
    return all;
}

const char* name(const brdf::Microfacet& mf) { return mf.kind == BRDF_DISTRIBUTION_GGX ? "GGX" : "Hyper-Cauchy"; }

// Quadrature nodes clustered at the horizon by z = s^p, where heavy tails put D ~ z^(2g - 4):
// p (2g - 3) >= 2 makes max(0, wo.m) D(m) dz/ds smooth there.
double horizon_power(const brdf::Microfacet& mf) {
    return mf.kind == BRDF_DISTRIBUTION_HYPER_CAUCHY && mf.shape < 2.5f ? 2.0 / (2.0 * mf.shape - 3.0) : 1.0;
}

QuadratureLimits deep() {
    QuadratureLimits limits;
    limits.min_depth = 3;
    limits.max_depth = 24;
    return limits;
}

}  // namespace

TEST_CASE("microfacet D is normalised: integral of D cos over the hemisphere is 1", "[microfacet]") {
    for (const brdf::Microfacet& mf : distributions()) {
        // D cos ~ z^(2g - 3) at the horizon is integrable for g > 1.5; p = 3 smooths it
        double integral = integrate_hemisphere([&](brdf::float3 m) { return double(brdf::microfacet_d(mf, m)) * m.z; }, 1e-5,
                                               deep(), 3.0);
        INFO(name(mf) << " alpha " << mf.ax << " x " << mf.ay << " shape " << mf.shape << ": " << integral);
        CHECK(integral == Approx(1.0).margin(1e-4));
    }
}

// Projected area of the facets visible from wo, integral of max(0, wo.m) D(m) dm, integrated over
// the visible region only (so the integrand has no kink): in azimuth phi the facets facing wo are
// those with theta_m < atan(cot theta_o / -cos(phi - phi_o)) when cos(phi - phi_o) < 0, else all.
double projected_area(const brdf::Microfacet& mf, brdf::float3 wo, double tolerance) {
    const double two_pi = 2.0 * M_PI, p = horizon_power(mf);
    double theta_o = std::acos(double(wo.z)), phi_o = std::atan2(double(wo.y), double(wo.x));
    QuadratureLimits limits = deep();
    auto over_z = [&](double phi) {
        double c = std::cos(phi - phi_o);
        double z_min = 0.0;
        if (c < 0.0 && theta_o > 0.0) z_min = std::cos(std::atan(1.0 / (std::tan(theta_o) * -c)));
        // z = s^p clusters nodes at the horizon, where heavy tails put D ~ z^(2g - 4)
        auto integrand = [&](double s) {
            double z = std::pow(s, p), r = std::sqrt(std::fmax(0.0, 1.0 - z * z));
            brdf::float3 m(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
            double wo_m = double(wo.x) * m.x + double(wo.y) * m.y + double(wo.z) * m.z;
            return s > 0.0 ? p * std::pow(s, p - 1.0) * std::fmax(wo_m, 0.0) * brdf::microfacet_d(mf, m) : 0.0;
        };
        return adaptive_simpson(integrand, std::pow(z_min, 1.0 / p), 1.0, 0.1 * tolerance / two_pi, limits);
    };
    // split where the visible region starts to shrink, cos(phi - phi_o) = 0
    double a = phi_o + 0.5 * M_PI, b = phi_o + 1.5 * M_PI;
    return adaptive_simpson(over_z, a, b, 0.5 * tolerance, limits) +
           adaptive_simpson(over_z, b, a + two_pi, 0.5 * tolerance, limits);
}

// Every distribution at three of the six incident angles, drawn per run (tests/points_of_run.hpp).
TEST_CASE("Smith normalisation: integral of G1(wo) max(0, wo.m) D(m) dm is cos theta_o", "[microfacet][sweep]") {
    double worst = 0.0;
    const float thetas[6] = {0.0f, 30.0f, 60.0f, 80.0f, 89.0f, 89.9f};
    const std::vector<brdf::Microfacet> all = distributions();
    for (size_t k = 0; k < all.size(); ++k) {
        const brdf::Microfacet& mf = all[k];
        for (int t : sweep_points_of_run("Smith normalisation angles: distribution " + std::to_string(k), 6, 3)) {
            const float theta = thetas[t];
            brdf::float3 wo = brdf::direction_from_degrees(theta, 35.0f);
            // to 1e-5 of the area Smith predicts, cos / G1
            double g1 = brdf::microfacet_g1(mf, wo);
            double ratio = g1 * projected_area(mf, wo, 1e-5 * wo.z / g1) / wo.z;
            worst = std::fmax(worst, std::fabs(ratio - 1.0));
            INFO(name(mf) << " alpha " << mf.ax << " x " << mf.ay << " shape " << mf.shape << ", theta " << theta
                          << ": G1 " << brdf::microfacet_g1(mf, wo) << ", G1 projected area / cos " << ratio);
            CHECK(ratio == Approx(1.0).margin(1e-4));
        }
    }
    std::printf("Smith normalisation: largest |G1 * projected area / cos - 1| = %.2g\n", worst);
}

TEST_CASE("Hyper-Cauchy of shape 2 is GGX: D, Lambda, G1, G2", "[microfacet]") {
    UniformRandom rng(9);
    double worst_d = 0.0, worst_lambda = 0.0, worst_g = 0.0;
    for (int i = 0; i < 20000; ++i) {
        float ax = rng.uniform(0.01f, 1.0f), ay = i % 2 ? ax : rng.uniform(0.01f, 1.0f);
        brdf::Microfacet ggx = brdf::microfacet_make(BRDF_DISTRIBUTION_GGX, ax, ay, 2.0f);
        brdf::Microfacet hc = brdf::microfacet_make(BRDF_DISTRIBUTION_HYPER_CAUCHY, ax, ay, 2.0f);
        brdf::float3 m = uniform_hemisphere_direction(rng), wo = uniform_hemisphere_direction(rng),
                     wi = uniform_sphere_direction(rng);
        double d_ggx = brdf::microfacet_d(ggx, m), d_hc = brdf::microfacet_d(hc, m);
        double l_ggx = brdf::microfacet_lambda(ggx, wo), l_hc = brdf::microfacet_lambda(hc, wo);
        double g1 = std::fabs(brdf::microfacet_g1(hc, wo) / brdf::microfacet_g1(ggx, wo) - 1.0);
        double g2 = std::fabs(brdf::microfacet_g2(hc, wo, wi) / brdf::microfacet_g2(ggx, wo, wi) - 1.0);
        worst_d = std::fmax(worst_d, std::fabs(d_hc / d_ggx - 1.0));
        if (l_ggx > 0.0) worst_lambda = std::fmax(worst_lambda, std::fabs(l_hc / l_ggx - 1.0));
        worst_g = std::fmax(worst_g, std::fmax(g1, g2));
    }
    std::printf("Hyper-Cauchy 2 vs GGX: relative difference D %.2g, Lambda %.2g, G1/G2 %.2g\n", worst_d, worst_lambda,
                worst_g);
    CHECK(worst_d <= 1e-4);
    CHECK(worst_lambda <= 1e-4);
    CHECK(worst_g <= 1e-4);
}

TEST_CASE("incomplete beta function against closed forms", "[microfacet]") {
    for (float x : {0.001f, 0.1f, 0.37f, 0.5f, 0.8f, 0.999f}) {
        for (float b : {0.5f, 1.0f, 2.5f, 7.0f})
            CHECK(brdf::incomplete_beta(1.0f, b, x) == Approx(1.0 - std::pow(1.0 - double(x), double(b))).epsilon(2e-5));
        for (float a : {0.6f, 1.0f, 3.0f, 15.0f})
            CHECK(brdf::incomplete_beta(a, 1.0f, x) == Approx(std::pow(double(x), double(a))).epsilon(2e-5).margin(1e-30));
        // I_x(1/2, 1/2) = (2 / pi) asin(sqrt(x))
        CHECK(brdf::incomplete_beta(0.5f, 0.5f, x) == Approx(2.0 / M_PI * std::asin(std::sqrt(double(x)))).epsilon(2e-5));
        // symmetry I_x(a, b) = 1 - I_(1-x)(b, a), at the Hyper-Cauchy Lambda's b = 1/2
        CHECK(brdf::incomplete_beta(2.3f, 0.5f, x) + brdf::incomplete_beta(0.5f, 2.3f, 1.0f - x) == Approx(1.0).epsilon(2e-5));
    }
    for (float a : {0.6f, 1.5f, 4.0f, 15.0f}) CHECK(brdf::incomplete_beta(a, a, 0.5f) == Approx(0.5).epsilon(2e-5));
    // I_x(a, n - a + 1) = P(Binomial(n, x) >= a): I_0.3(2, 3) = 0.3483
    CHECK(brdf::incomplete_beta(2.0f, 3.0f, 0.3f) == Approx(0.3483).epsilon(2e-5));
    CHECK(brdf::incomplete_beta(2.0f, 3.0f, 0.0f) == 0.0f);
    CHECK(brdf::incomplete_beta(2.0f, 3.0f, 1.0f) == 1.0f);
}
