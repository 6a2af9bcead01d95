// validation/sampling_efficiency: known answers for materials whose best strategy is known.
#include <catch2/catch.hpp>

#include <cmath>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "tests/lobe_material.hpp"
#include "validation/sampling_efficiency.hpp"

namespace {

brdf::Material lambert() { return lobe_material(1, 0, 0, 0); }

const brdf::float3 kWo(0.5f, 0.0f, 0.8660254f);  // 30 degrees

}  // namespace

TEST_CASE("sampling efficiency: Lambert is sampled perfectly by both strategies", "[sampling_efficiency]") {
    lab::validation::SamplingEfficiency e = lab::validation::sampling_efficiency(lambert(), kWo, 20000);
    CHECK(e.ratio == 1.0);
    CHECK(e.mean_bsdf == Approx(0.8).epsilon(1e-5));
    CHECK(e.mean_cosine == Approx(0.8).epsilon(1e-5));
    CHECK_FALSE(e.has_delta_lobe);
}

TEST_CASE("sampling efficiency: a rough metal's own sampler beats cosine sampling", "[sampling_efficiency]") {
    brdf::Material m = lambert();
    m.metallic = 1.0f;
    m.roughness = 0.3f;
    lab::validation::SamplingEfficiency e = lab::validation::sampling_efficiency(m, kWo, 100000);
    CHECK(e.ratio > 10.0);
    // both estimate the same albedo: within a few standard errors of each other
    double se = std::sqrt(e.variance_bsdf / e.samples + e.variance_cosine / e.samples);
    CHECK(std::fabs(e.mean_bsdf - e.mean_cosine) < 5.0 * se);
}

TEST_CASE("sampling efficiency: the 2017 model samples cosine-weighted, so the ratio is 1", "[sampling_efficiency]") {
    brdf::Material m = brdf::default_material();
    m.model = BRDF_MODEL_DTOADQ2017;
    lab::validation::SamplingEfficiency e = lab::validation::sampling_efficiency(m, kWo, 100000);
    CHECK(e.ratio == Approx(1.0).epsilon(0.05));
}

TEST_CASE("sampling efficiency: delta lobes are excluded and reported", "[sampling_efficiency]") {
    brdf::Material glass = lambert();
    glass.weight_diffuse = 0.0f;
    glass.weight_transmission = 1.0f;
    glass.roughness = 0.0f;
    lab::validation::SamplingEfficiency e = lab::validation::sampling_efficiency(glass, kWo, 10000);
    CHECK(e.has_delta_lobe);
    CHECK(e.delta_fraction == 1.0);
    CHECK_FALSE(e.continuous_part);
    CHECK(std::isnan(e.ratio));

    brdf::Material coated = lambert();
    coated.weight_specular = 1.0f;  // half the weight is the mirror, picked by its Fresnel reflectance at wo
    e = lab::validation::sampling_efficiency(coated, kWo, 20000);
    CHECK(e.has_delta_lobe);
    brdf::LobeChoice choice = brdf::lab_lobe_choice(&coated, brdf::lab_lobe_weights(&coated), brdf::microfacet_from_material(&coated), brdf::bsdf_tables(), kWo);
    CHECK(e.delta_fraction == Approx(choice.specular).margin(4.0 * std::sqrt(choice.specular * (1.0 - choice.specular) / 20000.0)));
    CHECK(e.mean_cosine == Approx(0.4).epsilon(1e-4));  // the diffuse half of albedo 0.8
    CHECK(e.mean_bsdf == Approx(0.4).epsilon(0.03));
}

TEST_CASE("sampling efficiency: a faint or broad lobe beside a diffuse one is sampled cosine-weighted",
          "[sampling_efficiency]") {
    // rubber's rough sheen (roughness 0.8) is no more peaked than cosine at 0 and 45 deg, and skin's
    // phase function (g = -0.3) peaks less densely than cosine sampling there: their samplers would
    // lose directions below the horizon or undersample the diffuse lobe, so the lab's sampler is the
    // cosine one but for at most 1e-3 of its samples (each of which costs about 1e-3 of the squared
    // mean in variance: below the cosine estimator's own noise for these lobes)
    for (const char* path : {"presets/rubber.json", "presets/skin.json"})
        for (float theta : {0.0f, 45.0f}) {
            brdf::Material m = brdf::load_preset(path).material;
            brdf::float3 wo = brdf::direction_from_degrees(theta, 0.0f);
            brdf::LobeChoice c = brdf::lab_lobe_choice(&m, brdf::lab_lobe_weights(&m), brdf::microfacet_from_material(&m), brdf::bsdf_tables(), wo);
            INFO(path << " at " << theta << " deg: glossy " << c.glossy << ", subsurface " << c.subsurface);
            CHECK(c.cosine > 0.999f);
        }
    // at 75 deg skin's back-scattering peak is denser than cosine sampling there, and its sampler pays
    // (measured about 5.7; a ratio estimate from 20000 samples each is within 20 % of it)
    brdf::Material skin = brdf::load_preset("presets/skin.json").material;
    lab::validation::SamplingEfficiency e = lab::validation::sampling_efficiency(skin, brdf::direction_from_degrees(75.0f, 0.0f), 20000);
    CHECK(e.ratio > 2.0);
}
