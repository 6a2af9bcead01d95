// The chi-square machinery itself: its distribution function, and that it catches a wrong pdf and
// every kind of broken sampler it promises to catch.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "tests/chi_square_suite.hpp"
#include "tests/lobe_material.hpp"
#include "validation/chi_square.hpp"
#include "validation/chi_square_distribution.hpp"

using namespace lab::validation;

namespace {

brdf::Material lambert() { return lobe_material(1, 0, 0, 0); }

brdf::Material ggx_metal(float roughness) {
    brdf::Material m = lobe_material(0, 1, 0, 0);
    m.metallic = 1.0f;
    m.roughness = roughness;
    return m;
}

// The suite's sample count and level (Sidak over its tests): a wrong pdf must fail even there.
ChiSquareOptions suite_options() { return chi_square_suite_options(); }

}  // namespace

TEST_CASE("chi-square distribution: closed forms and Sidak level", "[chi_square]") {
    for (double x : {0.1, 1.0, 3.0, 10.0, 40.0}) {
        CHECK(chi_square_survival(x, 2.0) == Approx(std::exp(-x / 2.0)).epsilon(1e-12));
        CHECK(chi_square_survival(x, 4.0) == Approx(std::exp(-x / 2.0) * (1.0 + x / 2.0)).epsilon(1e-12));
        CHECK(chi_square_survival(x, 1.0) == Approx(std::erfc(std::sqrt(x / 2.0))).epsilon(1e-10));
        CHECK(regularized_gamma_p(2.5, x) + regularized_gamma_q(2.5, x) == Approx(1.0).epsilon(1e-14));
    }
    // Large dof (the suite has thousands of cells): Wilson-Hilferty's cube-root normal approximation.
    for (double k : {500.0, 4900.0}) {
        for (double z : {-2.0, 0.0, 2.5}) {
            double c = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
            double x = k * c * c * c;
            CHECK(chi_square_survival(x, k) == Approx(0.5 * std::erfc(z / std::sqrt(2.0))).margin(2e-3));
        }
    }
    CHECK(chi_square_survival(20000.0, 4900.0) < 1e-300);
    CHECK(sidak_alpha(0.01, 1) == Approx(0.01).epsilon(1e-12));
    CHECK(sidak_alpha(0.01, 100) == Approx(1.0 - std::pow(0.99, 0.01)).epsilon(1e-12));
}

TEST_CASE("chi-square rejects a pdf that is 10% off on half the sphere", "[chi_square]") {
    brdf::Material m = lambert();
    brdf::float3 wo = brdf::direction_from_degrees(0.0f, 0.0f);
    // 1.1 on y > 0 (half the mass for normal incidence), renormalised: still integrates to 1
    DirectionDensity wrong = [&](brdf::float3 wi) {
        double p = brdf::bsdf_pdf(&m, wo, wi);
        return (wi.y > 0.0f ? 1.1 : 1.0) * p / 1.05;
    };
    ChiSquareResult truth = chi_square_test(bsdf_direction_sampler(m, wo), bsdf_direction_density(m, wo), suite_options());
    ChiSquareResult r = chi_square_test(bsdf_direction_sampler(m, wo), wrong, suite_options());
    INFO(describe(r));
    CHECK(truth.passed);
    CHECK(r.pdf_integral == Approx(1.0).margin(1e-4));
    CHECK_FALSE(r.passed);
    CHECK(r.p_value < 1e-10);
}

TEST_CASE("chi-square rejects samples drawn with a 10% different roughness", "[chi_square][sweep]") {
    brdf::Material claimed = ggx_metal(0.5f), drawn = ggx_metal(0.55f);
    for (float theta : {0.0f, 60.0f}) {
        brdf::float3 wo = brdf::direction_from_degrees(theta, 30.0f);
        ChiSquareResult r = chi_square_test(bsdf_direction_sampler(drawn, wo), bsdf_direction_density(claimed, wo), suite_options());
        INFO("theta " << theta << ": " << describe(r));
        CHECK_FALSE(r.passed);
    }
    brdf::Material hc = claimed, hc_drawn = claimed;
    hc.distribution = hc_drawn.distribution = BRDF_DISTRIBUTION_HYPER_CAUCHY;
    hc.hc_shape = 2.0f;
    hc_drawn.hc_shape = 2.2f;
    brdf::float3 wo = brdf::direction_from_degrees(45.0f, 0.0f);
    ChiSquareResult r = chi_square_test(bsdf_direction_sampler(hc_drawn, wo), bsdf_direction_density(hc, wo), suite_options());
    INFO("Hyper-Cauchy shape 2.2 sampled, 2 claimed: " << describe(r));
    CHECK_FALSE(r.passed);
}

TEST_CASE("chi-square fails outright on broken samplers and densities", "[chi_square]") {
    brdf::Material m = lambert();
    brdf::float3 wo = brdf::direction_from_degrees(30.0f, 0.0f);
    DirectionSampler good = bsdf_direction_sampler(m, wo);
    DirectionDensity density = bsdf_direction_density(m, wo);
    ChiSquareOptions o;
    o.samples = 100000;

    SECTION("a direction that is not unit length") {
        DirectionSampler sampler = [&](brdf::float3 u) {
            DirectionSample s = good(u);
            if (u.x < 0.001f) s.wi *= 1.01f;
            return s;
        };
        ChiSquareResult r = chi_square_test(sampler, density, o);
        CHECK_FALSE(r.passed);
        CHECK(r.failure.find("outside the domain") != std::string::npos);
    }
    SECTION("a NaN direction") {
        DirectionSampler sampler = [&](brdf::float3 u) {
            DirectionSample s = good(u);
            if (u.x < 0.001f) s.wi.x = std::numeric_limits<float>::quiet_NaN();
            return s;
        };
        ChiSquareResult r = chi_square_test(sampler, density, o);
        CHECK(r.failure.find("outside the domain") != std::string::npos);
    }
    SECTION("a negative density") {
        DirectionDensity negative = [&](brdf::float3 wi) { return wi.z < -0.5f ? -1e-3 : density(wi); };
        ChiSquareResult r = chi_square_test(good, negative, o);
        CHECK(r.failure.find("density -0.001") != std::string::npos);
    }
    SECTION("a NaN density") {
        DirectionDensity nan = [&](brdf::float3 wi) { return wi.x > 0.9f ? std::nan("") : density(wi); };
        ChiSquareResult r = chi_square_test(good, nan, o);
        CHECK(r.failure.find("density nan") != std::string::npos);
    }
    SECTION("samples where the density is zero") {
        DirectionDensity half = [&](brdf::float3 wi) { return wi.y > 0.0f ? 2.0 * density(wi) : 0.0; };
        ChiSquareResult r = chi_square_test(good, half, o);
        CHECK(r.failure.find("integrates to 0") != std::string::npos);
    }
    SECTION("a density with more than unit mass") {
        DirectionDensity heavy = [&](brdf::float3 wi) { return 1.01 * density(wi); };
        ChiSquareResult r = chi_square_test(good, heavy, o);
        CHECK(r.failure.find("more than 1") != std::string::npos);
    }
    SECTION("a sampler that reports a broken promise") {
        DirectionSampler sampler = [&](brdf::float3 u) {
            DirectionSample s = good(u);
            if (u.x > 0.999f) s.defect = "returned pdf 1, bsdf_pdf gives 2";
            return s;
        };
        ChiSquareResult r = chi_square_test(sampler, density, o);
        CHECK(r.failure == "returned pdf 1, bsdf_pdf gives 2");
    }
    SECTION("failed samples the density does not account for") {
        DirectionSampler sampler = [&](brdf::float3 u) {
            DirectionSample s = good(u);
            if (u.x < 0.05f) s.kind = SampleKind::Failed;
            return s;
        };
        ChiSquareResult r = chi_square_test(sampler, density, o);
        INFO(describe(r));
        CHECK_FALSE(r.passed);
        CHECK(r.continuous_fraction == Approx(0.95).margin(0.005));
    }
    SECTION("the unbroken sampler passes") {
        ChiSquareResult r = chi_square_test(good, density, o);
        INFO(describe(r));
        CHECK(r.passed);
        CHECK(r.pdf_integral == Approx(1.0).margin(1e-5));
    }
}

TEST_CASE("chi-square results do not depend on the thread count", "[chi_square]") {
    brdf::Material m = ggx_metal(0.4f);
    brdf::float3 wo = brdf::direction_from_degrees(50.0f, 10.0f);
    ChiSquareOptions one, two;
    one.samples = two.samples = 200000;
    one.threads = 1;
    two.threads = 2;
    ChiSquareResult a = chi_square_bsdf(m, wo, one), b = chi_square_bsdf(m, wo, two);
    CHECK(a.statistic == b.statistic);
    CHECK(a.p_value == b.p_value);
}
