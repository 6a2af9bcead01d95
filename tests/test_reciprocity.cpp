// Helmholtz reciprocity of the default model in reflection, over random materials spanning every
// parameter's range (ends included) and random direction pairs.
#include <catch2/catch.hpp>

#include <cstdio>

#include "brdf/brdf.hpp"
#include "validation/random_inputs.hpp"
#include "validation/reciprocity.hpp"

using namespace lab::validation;

TEST_CASE("the default model is reciprocal in reflection to 1e-4", "[reciprocity]") {
    UniformRandom rng(20240);
    ReciprocityResult worst;
    brdf::Material worst_material{};
    const int materials = 2000;
    const long pairs = 500;
    for (int i = 0; i < materials; ++i) {
        // a fifth of the parameters at an end of their range: F0 = 0, roughness 0, albedo 0...
        brdf::Material m = i % 2 ? random_material(rng, BRDF_MODEL_LAB) : random_edge_material(rng, BRDF_MODEL_LAB, 0.2f);
        ReciprocityResult r = reciprocity_error(m, pairs, uint64_t(i) + 1);
        if (r.max_relative_error > worst.max_relative_error || i == 0) {
            worst = r;
            worst_material = m;
        }
    }
    std::printf("reciprocity: %d materials x %ld pairs, worst relative error %.3g\n", materials, pairs,
                worst.max_relative_error);
    const brdf::Material& m = worst_material;
    INFO("worst " << worst.max_relative_error << " at wo (" << worst.wo.x << ", " << worst.wo.y << ", " << worst.wo.z
                  << ") wi (" << worst.wi.x << ", " << worst.wi.y << ", " << worst.wi.z << "): f " << worst.f_forward.x << " "
                  << worst.f_forward.y << " " << worst.f_forward.z << " vs " << worst.f_reverse.x << " " << worst.f_reverse.y
                  << " " << worst.f_reverse.z << "; albedo " << m.albedo[0] << " " << m.albedo[1] << " " << m.albedo[2]
                  << " metallic " << m.metallic << " fresnel " << m.fresnel << " roughness " << m.roughness);
    CHECK(worst.max_relative_error <= 1e-4);
}

TEST_CASE("relative difference takes the largest channel, relative to the larger value", "[reciprocity]") {
    CHECK(relative_difference(brdf::float3(1.0f, 2.0f, 0.0f), brdf::float3(1.0f, 2.0f, 0.0f)) == 0.0);
    CHECK(relative_difference(brdf::float3(1.0f, 2.0f, 4.0f), brdf::float3(1.0f, 2.0f, 5.0f)) == Approx(0.2));
    CHECK(relative_difference(brdf::float3(1.0f, 0.0f, 0.0f), brdf::float3(1.0f, 1e-30f, 0.0f)) == Approx(1.0));
}
