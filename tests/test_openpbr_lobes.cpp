// The OpenPBR Surface lobes of the BRDF module against closed forms and independent computations.
#include <catch2/catch.hpp>

#include <cmath>

#include "brdf/brdf.hpp"

using brdf::float3;

TEST_CASE("F82 tint: white is Schlick exactly, 1/7 reaches tint times Schlick, values stay in [0, 1]", "[brdf][openpbr]") {
    const float f0s[] = {0.0f, 0.04f, 0.3f, 0.7f, 0.95f, 1.0f};
    const float tints[] = {0.0f, 0.2f, 0.5f, 0.9f, 1.0f};
    for (float f0 : f0s) {
        float3 f0v(f0, 0.5f * f0, 1.0f - f0);
        for (int i = 0; i <= 200; ++i) {
            float mu = i / 200.0f;
            float3 schlick = brdf::fresnel_schlick(f0v, mu), f82 = brdf::fresnel_f82_tint(f0v, float3(1.0f), mu);
            CHECK(f82.x == schlick.x);  // b = 0 exactly: the same bits
            CHECK(f82.y == schlick.y);
            CHECK(f82.z == schlick.z);
        }
        for (float tint : tints) {
            // OpenPBR 1.1: at mu_bar = 1/7 the curve equals tint x F_Schlick(mu_bar), in double here
            double mu_bar = 1.0 / 7.0, expected = tint * (f0 + (1.0 - f0) * std::pow(1.0 - mu_bar, 5));
            float3 at_bar = brdf::fresnel_f82_tint(float3(f0), float3(tint), 1.0f / 7.0f);
            INFO("F0 " << f0 << ", tint " << tint);
            CHECK(at_bar.x == Approx(expected).margin(1e-6));  // float rounding of a few operations on values <= 1
            // normal incidence is F0, grazing incidence 1, whatever the tint
            CHECK(brdf::fresnel_f82_tint(float3(f0), float3(tint), 1.0f).x == f0);
            CHECK(brdf::fresnel_f82_tint(float3(f0), float3(tint), 0.0f).x == Approx(1.0f).margin(1e-7));
            for (int i = 0; i <= 1000; ++i) {
                float f = brdf::fresnel_f82_tint(float3(f0), float3(tint), i / 1000.0f).x;
                INFO("mu " << i / 1000.0f << ": " << f);
                CHECK((f >= 0.0f && f <= 1.0f));
            }
        }
    }
}
