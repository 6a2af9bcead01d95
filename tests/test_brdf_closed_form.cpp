// Components of the BRDF module against closed-form values.
#include <catch2/catch.hpp>

#include <cmath>

#include "brdf/brdf.hpp"
#include "brdf/host/parameters.hpp"
#include "tests/lobe_material.hpp"

using brdf::float3;

namespace {

brdf::Material lambert(float albedo) {
    brdf::Material m = lobe_material(1, 0, 0, 0);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = albedo;
    return m;
}

float3 dir(float theta_deg, float phi_deg) {
    float t = theta_deg * float(M_PI) / 180.0f, p = phi_deg * float(M_PI) / 180.0f;
    return float3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

}  // namespace

TEST_CASE("Lambert is albedo / pi above the horizon and zero below", "[brdf]") {
    brdf::Material m = lambert(0.7f);
    for (float t : {0.0f, 30.0f, 60.0f, 89.0f}) {
        float3 f = brdf::bsdf_eval(&m, dir(20, 0), dir(t, 100));
        CHECK(f.x == Approx(0.7 / M_PI).epsilon(1e-6));
        CHECK(brdf::bsdf_pdf(&m, dir(20, 0), dir(t, 100)) == Approx(std::cos(t * M_PI / 180) / M_PI).epsilon(1e-5));
    }
    CHECK(brdf::bsdf_eval(&m, dir(20, 0), dir(100, 0)).x == 0.0f);
    CHECK(brdf::bsdf_eval(&m, dir(100, 0), dir(20, 0)).x == 0.0f);
}

TEST_CASE("Schlick and dielectric Fresnel at normal and grazing incidence", "[brdf]") {
    float3 f0(0.04f, 0.5f, 1.0f);
    float3 normal = brdf::fresnel_schlick(f0, 1.0f), grazing = brdf::fresnel_schlick(f0, 0.0f);
    CHECK(normal.x == Approx(0.04f));
    CHECK(normal.y == Approx(0.5f));
    CHECK(grazing.x == Approx(1.0f));
    CHECK(grazing.y == Approx(1.0f));
    for (float eta : {1.0f, 1.33f, 1.5f, 2.4f}) {
        float r0 = (eta - 1) * (eta - 1) / ((eta + 1) * (eta + 1));
        CHECK(brdf::fresnel_dielectric(1.0f, eta) == Approx(r0).margin(1e-7));
        CHECK(brdf::fresnel_dielectric(-1.0f, eta) == Approx(r0).margin(1e-7));  // same from inside
    }
    // total internal reflection beyond the critical angle, from inside glass
    float critical = std::asin(1.0f / 1.5f);
    CHECK(brdf::fresnel_dielectric(-std::cos(critical + 0.01f), 1.5f) == 1.0f);
    CHECK(brdf::fresnel_dielectric(-std::cos(critical - 0.05f), 1.5f) < 1.0f);
    // Brewster's angle: p-polarised reflectance vanishes, so F = r_s^2 / 2
    float brewster = std::atan(1.5f);
    float ci = std::cos(brewster), ct = std::cos(std::asin(std::sin(brewster) / 1.5f));
    float rs = (ci - 1.5f * ct) / (ci + 1.5f * ct);
    CHECK(brdf::fresnel_dielectric(ci, 1.5f) == Approx(0.5f * rs * rs).epsilon(1e-4));
}

TEST_CASE("Henyey-Greenstein phase integrates to one and has mean cosine g", "[brdf]") {
    for (float g : {-0.9f, -0.3f, 0.0f, 0.5f, 0.9f}) {
        double integral = 0, mean_cos = 0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
            double c = -1.0 + 2.0 * (i + 0.5) / n;  // uniform in cos: dw = 2 pi dc
            double p = brdf::henyey_greenstein_phase(float(c), g);
            integral += p * 2 * M_PI * 2.0 / n;
            mean_cos += c * p * 2 * M_PI * 2.0 / n;
        }
        CHECK(integral == Approx(1.0).epsilon(1e-3));
        CHECK(mean_cos == Approx(g).margin(2e-3));
    }
}

TEST_CASE("a smooth mirror returns its Fresnel reflectance as a flagged delta sample", "[brdf]") {
    brdf::Material m = lobe_material(0, 0, 1, 0);
    m.metallic = 1.0f;
    m.albedo[0] = 0.9f, m.albedo[1] = 0.5f, m.albedo[2] = 0.2f;
    float3 wo = dir(40, 30);
    brdf::BsdfSample s = brdf::bsdf_sample(&m, wo, float3(0.3f, 0.5f, 0.5f));
    REQUIRE(s.flags == (BSDF_REFLECTION | BSDF_DELTA));
    CHECK(s.wi.x == Approx(-wo.x));
    CHECK(s.wi.z == Approx(wo.z));
    float3 weight = s.f * (std::fabs(s.wi.z) / s.pdf);
    float3 expected = brdf::fresnel_schlick(float3(0.9f, 0.5f, 0.2f), wo.z);
    CHECK(weight.x == Approx(expected.x));
    CHECK(weight.z == Approx(expected.z));
    CHECK(brdf::bsdf_pdf(&m, wo, s.wi) == 0.0f);  // delta lobes are not in the continuous pdf
}

TEST_CASE("smooth glass refracts by Snell's law and weights by Fresnel", "[brdf]") {
    brdf::Material m = lobe_material(0, 0, 0, 1);
    m.roughness = 0.0f;
    m.ior = 1.5f;
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    float3 wo = dir(50, 0);
    float fr = brdf::fresnel_dielectric(wo.z, 1.5f);
    brdf::BsdfSample t = brdf::bsdf_sample(&m, wo, float3(0.999f, 0.5f, 0.5f));
    REQUIRE(t.flags == (BSDF_TRANSMISSION | BSDF_DELTA));
    double sin_t = std::sqrt(1.0 - double(t.wi.z) * t.wi.z);
    CHECK(sin_t * 1.5 == Approx(std::sin(50 * M_PI / 180)).epsilon(1e-5));
    CHECK(t.pdf == Approx(1.0f - fr));
    CHECK(t.f.x * std::fabs(t.wi.z) / t.pdf == Approx(1.0f));
    brdf::BsdfSample r = brdf::bsdf_sample(&m, wo, float3(0.0f, 0.5f, 0.5f));
    REQUIRE(r.flags == (BSDF_REFLECTION | BSDF_DELTA));
    CHECK(r.pdf == Approx(fr));
}

TEST_CASE("tangent rotation turns the anisotropic lobe about the normal", "[brdf]") {
    brdf::Material m = lobe_material(0, 1, 0, 0);
    m.metallic = 1.0f;
    m.roughness = 0.4f;
    m.anisotropic = 0.8f;
    brdf::Material turned = m;
    turned.tangent_rotation = float(M_PI) / 3.0f;
    for (float phi : {0.0f, 20.0f, 75.0f}) {
        float3 a = brdf::bsdf_eval(&m, dir(40, phi), dir(35, phi + 150));
        float3 b = brdf::bsdf_eval(&turned, dir(40, phi + 60), dir(35, phi + 210));
        CHECK(b.x == Approx(a.x).epsilon(1e-4));
    }
    // and it is anisotropic: a half vector tilted along the tangent or along the bitangent differs
    CHECK(brdf::bsdf_eval(&m, dir(40, 0), dir(10, 0)).x > 1.5f * brdf::bsdf_eval(&m, dir(40, 90), dir(10, 90)).x);
}

TEST_CASE("all-zero lobe weights are a black material whose samples fail", "[brdf]") {
    brdf::Material m = lobe_material(0, 0, 0, 0);
    CHECK(brdf::bsdf_eval(&m, dir(10, 0), dir(20, 40)).x == 0.0f);
    CHECK(brdf::bsdf_pdf(&m, dir(10, 0), dir(20, 40)) == 0.0f);
    CHECK(brdf::bsdf_sample(&m, dir(10, 0), float3(0.5f)).flags == 0);
}
