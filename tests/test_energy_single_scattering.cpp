// Lower bounds for the white furnace (tests/test_energy.cpp bounds albedo from above only): a
// conductor lobe must return exactly the energy single scattering on its microfacets returns, no
// less (a lobe that loses half, or all, of it fails) and no more. The reference is GGX's known
// single-scattering albedo, tabulated here by an independent quadrature of the textbook formulas
// (Walter et al. 2007; Heitz 2014, height-correlated Smith), sharing no code with brdf/. A smooth
// dielectric reflects plus transmits everything: R + T = 1 from both sides.
//
// When energy compensation exists (a material switch), the single-scattering check sets it off in
// `white_ggx_conductor` below; the compensated model then gets its own bound against 1.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "tests/lobe_material.hpp"
#include "validation/albedo.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- the independent reference: isotropic GGX, F = 1, in double ----------------------------------
double smith_lambda(double cos_theta, double alpha) {
    const double tan2 = (1.0 - cos_theta * cos_theta) / (cos_theta * cos_theta);
    return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

// E(mu_o) = integral of D(h) G2(o, i) / (4 mu_o mu_i) mu_i d(omega_i). With omega_i the reflection
// of o about h, d(omega_i) = 4 (o.h) d(omega_h), and D(h) cos(theta_h) d(omega_h) the distribution
// of normals whose inverse cdf is tan^2(theta_h) = alpha^2 u / (1 - u), phi_h = 2 pi v:
// E = integral over [0,1]^2 of G2(o, i) (o.h) / (mu_o cos theta_h) du dv, where i.z > 0 and o.h > 0.
// u = 1 - s^2 (du = 2 s ds) smooths the 1 / cos theta_h growth towards u = 1; the integrand is then
// continuous (G2 and o.h fall to 0 at the cuts), and the midpoint rule on an n x n grid converges
// as 1/n^2: n = 512 is within 1e-4 (checked against n = 256 below).
double ggx_single_scattering_albedo(double theta_o, double alpha, int n = 512) {
    const double mu_o = std::cos(theta_o), sin_o = std::sin(theta_o);
    const double lambda_o = smith_lambda(mu_o, alpha);
    double sum = 0.0;
    for (int a = 0; a < n; ++a) {
        const double s = (a + 0.5) / n, u = 1.0 - s * s, weight = 2.0 * s;
        const double tan2_h = alpha * alpha * u / (1.0 - u);
        const double cos_h = 1.0 / std::sqrt(1.0 + tan2_h), sin_h = std::sqrt(tan2_h) * cos_h;
        for (int b = 0; b < n; ++b) {
            const double phi = 2.0 * kPi * (b + 0.5) / n;
            const double hx = sin_h * std::cos(phi), hz = cos_h;  // h.y does not enter: o lies in the xz plane
            const double o_h = sin_o * hx + mu_o * hz;  // o = (sin_o, 0, mu_o)
            if (o_h <= 0.0) continue;
            const double iz = 2.0 * o_h * hz - mu_o;  // i = 2 (o.h) h - o
            if (iz <= 0.0) continue;
            const double g2 = 1.0 / (1.0 + lambda_o + smith_lambda(iz, alpha));
            sum += weight * g2 * o_h / (mu_o * cos_h);
        }
    }
    return sum / (double(n) * n);
}

// ---- the model under test ------------------------------------------------------------------------
brdf::Material white_ggx_conductor(float roughness, float albedo = 1.0f) {
    brdf::Material m = lobe_material(0, 1, 0, 0);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = albedo;  // F0 = 1: Schlick's Fresnel is 1 at every angle
    m.metallic = 1.0f;
    m.distribution = BRDF_DISTRIBUTION_GGX;
    m.roughness = roughness;  // alpha = roughness^2
    m.anisotropic = 0.0f;
    m.energy_compensation = 0;  // the single-scattering lobe: what the independent quadrature computes
    return m;
}

struct Comparison {
    double model, std_error, reference;
    bool agrees() const { return std::fabs(model - reference) <= 4.0 * std_error + 2e-4; }
};

Comparison compare(const brdf::Material& m, float theta_deg, double reference_alpha) {
    const lab::validation::AlbedoEstimate a = lab::validation::directional_albedo(m, brdf::direction_from_degrees(theta_deg, 0.0f), 128);
    return {double(a.value.x), double(a.std_error.x), ggx_single_scattering_albedo(theta_deg * kPi / 180.0, reference_alpha)};
}

}  // namespace

TEST_CASE("energy: the reference quadrature converges and knows GGX's loss", "[energy]") {
    // a smooth surface loses nothing; the loss grows with roughness and at grazing angles
    CHECK(ggx_single_scattering_albedo(0.3, 1e-3) == Approx(1.0).margin(1e-4));
    for (double alpha : {0.04, 0.36, 1.0})
        for (double theta : {0.0, 1.0, 1.4})
            CHECK(std::fabs(ggx_single_scattering_albedo(theta, alpha) - ggx_single_scattering_albedo(theta, alpha, 256)) < 1e-4);
    // rough surfaces lose energy to masking and to reflections below the horizon
    CHECK(ggx_single_scattering_albedo(0.0, 0.04) > 0.99);
    CHECK(ggx_single_scattering_albedo(0.0, 1.0) < 0.7);
}

TEST_CASE("energy: a white GGX conductor returns exactly its single-scattering albedo", "[energy]") {
    // 4 standard errors of the stratified estimate, plus the reference's quadrature error (< 1e-4)
    // and float rounding of the model.
    double smallest = 1.0;
    for (float roughness : {0.2f, 0.4f, 0.6f, 0.8f, 1.0f})
        for (float theta : {0.0f, 30.0f, 60.0f, 75.0f, 85.0f}) {
            const Comparison c = compare(white_ggx_conductor(roughness), theta, double(roughness) * roughness);
            smallest = std::fmin(smallest, c.reference);
            INFO("roughness " << roughness << ", theta " << theta << ": model " << c.model << " +- " << c.std_error << ", reference "
                              << c.reference);
            CHECK(c.agrees());
        }
    std::printf("energy: white GGX conductors match their single-scattering albedo (smallest %.4f)\n", smallest);
}

TEST_CASE("energy: the single-scattering check fails a lobe that loses or gains energy", "[energy]") {
    // what the check above catches: a lobe at half its energy, one at 98 %, one with no energy, and
    // a roughness mapped to alpha = roughness instead of roughness^2
    CHECK_FALSE(compare(white_ggx_conductor(0.6f, 0.5f), 30.0f, 0.36).agrees());
    CHECK_FALSE(compare(white_ggx_conductor(0.6f, 0.98f), 30.0f, 0.36).agrees());
    CHECK_FALSE(compare(white_ggx_conductor(0.6f, 0.0f), 30.0f, 0.36).agrees());
    CHECK_FALSE(compare(white_ggx_conductor(0.8f), 75.0f, 0.8).agrees());
}

TEST_CASE("energy: a smooth dielectric reflects plus transmits everything, from both sides", "[energy]") {
    for (float ior : {1.01f, 1.33f, 1.5f, 2.4f, 3.0f})
        for (float theta : {0.0f, 30.0f, 60.0f, 85.0f, 100.0f, 150.0f, 179.0f}) {
            brdf::Material m = lobe_material(0, 0, 0, 1);
            m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
            m.ior = ior;
            m.roughness = 0.0f;
            const lab::validation::AlbedoEstimate a =
                lab::validation::directional_albedo(m, brdf::direction_from_degrees(theta, 0.0f), 16);
            INFO("ior " << ior << ", theta " << theta << ": R + T = " << a.value.x);
            CHECK(a.value.x == Approx(1.0).margin(1e-4));
        }
}
