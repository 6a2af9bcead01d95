// Feature switches (brdf/features.h): a kernel built with only the features its materials need
// gives exactly the results of the full build, and the switched-off parts never reach its source.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/features.hpp"
#include "brdf/host/preset.hpp"
#include "kernels/host/brdf_batch.hpp"
#include "kernels/host/embedded_sources.hpp"
#include "opencl/kernel_source.hpp"
#include "opencl/runtime.hpp"
#include "tests/bundled_presets_of_run.hpp"
#include "tests/lobe_material.hpp"
#include "validation/uniform_random.hpp"

namespace fs = std::filesystem;
using brdf::float3;

namespace {

bool feature_on(const std::vector<brdf::Material>& materials, const std::string& name) {
    for (const auto& [feature, on] : brdf::used_features(materials))
        if (feature == name) return on;
    FAIL("no feature " << name);
    return false;
}

// The kernel source a scene holding `materials` would get: its switches, then the module.
lab::opencl::AssembledSource assembled_with(const std::vector<brdf::Material>& materials) {
    std::string prelude = brdf::feature_defines(materials) + "#include \"brdf/bsdf.h\"\n";
    return lab::opencl::assemble_source("generated/features_test.h", [&](const std::string& path) -> std::string_view {
        if (path == "generated/features_test.h") return prelude;
        return lab::kernels::embedded_kernel_file(path);
    });
}

bool contains_file(const lab::opencl::AssembledSource& source, const std::string& file) {
    for (const auto& origin : source.origin)
        if (origin.file == file) return true;
    return false;
}

}  // namespace

TEST_CASE("used_features follows the lobes a material can reach", "[features]") {
    brdf::Material lambert = lobe_material(1, 0, 0, 0);
    CHECK(feature_on({lambert}, "BRDF_FEATURE_DIFFUSE"));
    CHECK_FALSE(feature_on({lambert}, "BRDF_FEATURE_GLOSSY"));
    CHECK_FALSE(feature_on({lambert}, "BRDF_FEATURE_GGX"));
    CHECK_FALSE(feature_on({lambert}, "BRDF_FEATURE_RETROREFLECTION"));
    CHECK_FALSE(feature_on({lambert}, "BRDF_FEATURE_DTOADQ2017"));

    brdf::Material metal = lobe_material(1, 0, 0, 0);
    metal.metallic = 1.0f;  // moves the diffuse weight onto the glossy lobe
    CHECK_FALSE(feature_on({metal}, "BRDF_FEATURE_DIFFUSE"));
    CHECK(feature_on({metal}, "BRDF_FEATURE_GLOSSY"));
    CHECK(feature_on({metal}, "BRDF_FEATURE_GGX"));
    CHECK_FALSE(feature_on({metal}, "BRDF_FEATURE_HYPER_CAUCHY"));
    metal.distribution = BRDF_DISTRIBUTION_HYPER_CAUCHY;
    CHECK(feature_on({metal}, "BRDF_FEATURE_HYPER_CAUCHY"));
    CHECK_FALSE(feature_on({metal}, "BRDF_FEATURE_GGX"));

    brdf::Material glass = lobe_material(0, 0, 0, 1);
    glass.roughness = 0.0f;  // smooth: a delta lobe, no distribution needed
    CHECK(feature_on({glass}, "BRDF_FEATURE_TRANSMISSION"));
    CHECK_FALSE(feature_on({glass}, "BRDF_FEATURE_GGX"));
    CHECK(feature_on({glass, metal}, "BRDF_FEATURE_HYPER_CAUCHY"));
}

TEST_CASE("used_features: an openpbr material compiles only the layers it uses", "[features][openpbr]") {
    brdf::Material plain = brdf::default_material(BRDF_MODEL_OPENPBR);  // rough specular over EON diffuse
    CHECK(feature_on({plain}, "BRDF_FEATURE_OPENPBR"));
    CHECK(feature_on({plain}, "BRDF_FEATURE_DIFFUSE"));
    CHECK(feature_on({plain}, "BRDF_FEATURE_GGX"));
    for (const char* off : {"BRDF_FEATURE_LAB_MODEL", "BRDF_FEATURE_COAT", "BRDF_FEATURE_FUZZ", "BRDF_FEATURE_THIN_FILM", "BRDF_FEATURE_SUBSURFACE",
                            "BRDF_FEATURE_TRANSMISSION", "BRDF_FEATURE_HYPER_CAUCHY", "BRDF_FEATURE_ENERGY_COMPENSATION"}) {
        INFO(off);
        CHECK_FALSE(feature_on({plain}, off));
    }
    brdf::Material layered = plain;
    layered.coat_weight = 1.0f, layered.fuzz_weight = 0.5f, layered.thin_film_weight = 1.0f;
    for (const char* on : {"BRDF_FEATURE_COAT", "BRDF_FEATURE_FUZZ", "BRDF_FEATURE_THIN_FILM"}) {
        INFO(on);
        CHECK(feature_on({layered}, on));
    }
    brdf::Material metal = plain;  // the film on the metal, with no dielectric under it
    metal.metallic = 1.0f, metal.thin_film_weight = 1.0f;
    CHECK(feature_on({metal}, "BRDF_FEATURE_THIN_FILM"));
    CHECK_FALSE(feature_on({metal}, "BRDF_FEATURE_DIFFUSE"));
    metal.thin_film_thickness = 0.0f;  // a film of thickness 0 is no film on the metal
    CHECK_FALSE(feature_on({metal}, "BRDF_FEATURE_THIN_FILM"));
    CHECK(feature_on({metal}, "BRDF_FEATURE_ENERGY_COMPENSATION"));
    // a material's emission: compiled only where a material emits (a colour of 0 emits nothing)
    CHECK_FALSE(feature_on({plain}, "BRDF_FEATURE_EMISSION"));
    brdf::Material glow = plain;
    glow.emission_luminance = 100.0f;
    CHECK(feature_on({plain, glow}, "BRDF_FEATURE_EMISSION"));
    CHECK(contains_file(assembled_with({glow}), "brdf/emission.h"));
    CHECK_FALSE(contains_file(assembled_with({plain}), "brdf/emission.h"));
    glow.emission_color[0] = glow.emission_color[1] = glow.emission_color[2] = 0.0f;
    CHECK_FALSE(feature_on({glow}, "BRDF_FEATURE_EMISSION"));
    // the lab's materials leave the openpbr model and its tables out of the kernel
    brdf::Material lambert = lobe_material(1, 0, 0, 0);
    CHECK_FALSE(feature_on({lambert}, "BRDF_FEATURE_OPENPBR"));
    lab::opencl::AssembledSource lab_source = assembled_with({lambert});
    for (const char* absent : {"brdf/openpbr_model.h", "brdf/energy_table_openpbr.h", "brdf/sheen.h", "brdf/thin_film.h", "brdf/eon_diffuse.h"}) {
        INFO(absent);
        CHECK_FALSE(contains_file(lab_source, absent));
    }
    lab::opencl::AssembledSource plain_source = assembled_with({plain});
    CHECK(contains_file(plain_source, "brdf/openpbr_model.h"));
    CHECK(contains_file(plain_source, "brdf/eon_diffuse.h"));
    for (const char* absent : {"brdf/thin_film.h", "brdf/henyey_greenstein.h", "brdf/dielectric.h", "brdf/lab_model.h"}) {
        INFO(absent);
        CHECK_FALSE(contains_file(plain_source, absent));
    }
}

TEST_CASE("switched-off features never reach the kernel source", "[features]") {
    brdf::Material gold = lobe_material(0, 1, 0, 0);
    gold.metallic = 1.0f;
    lab::opencl::AssembledSource source = assembled_with({gold});
    CHECK(contains_file(source, "brdf/ggx.h"));
    CHECK(contains_file(source, "brdf/glossy.h"));
    for (const char* absent : {"brdf/hyper_cauchy.h", "brdf/special_functions.h", "brdf/henyey_greenstein.h", "brdf/dielectric.h",
                               "brdf/diffuse.h", "brdf/dtoadq2017_model.h", "brdf/measured.h", "brdf/merl.h"}) {
        INFO(absent);
        CHECK_FALSE(contains_file(source, absent));
    }
    CHECK(source.text.find("BRDF_FEATURE_HYPER_CAUCHY") != std::string::npos);  // the define itself
    CHECK(source.text.find("hyper_cauchy_d") == std::string::npos);

    // A measured-only scene: the table lookup and its sampler, and none of the lab model.
    brdf::Material measured = brdf::default_material();
    measured.model = BRDF_MODEL_MEASURED;
    lab::opencl::AssembledSource table = assembled_with({measured});
    CHECK(contains_file(table, "brdf/measured.h"));
    CHECK(contains_file(table, "brdf/merl.h"));
    CHECK_FALSE(contains_file(table, "brdf/lab_model.h"));

    // Without switches everything is there, and the #if lines are left to the compiler.
    lab::opencl::AssembledSource full = lab::kernels::assemble_embedded_source("kernels/brdf_batch.cl");
    for (const char* present : {"brdf/hyper_cauchy.h", "brdf/henyey_greenstein.h", "brdf/dielectric.h", "brdf/dtoadq2017_model.h", "brdf/measured.h"}) {
        INFO(present);
        CHECK(contains_file(full, present));
    }
    CHECK(full.text.find("#if BRDF_FEATURE_HYPER_CAUCHY") != std::string::npos);
}

// The presets of the run (tests/bundled_presets_of_run.hpp): each preset that alone needs a feature,
// and half of the others, drawn per run; a reduced kernel each.
TEST_CASE("a kernel built with a preset's features only agrees exactly with the full build", "[features][opencl]") {
    lab::opencl::Runtime runtime("");
    lab::kernels::BrdfBatch full(runtime);
    const std::vector<brdf::Preset> presets = bundled_presets_of_run("feature build presets");
    REQUIRE(presets.size() >= 4);

    lab::validation::UniformRandom random(7);
    const int n = 2000;
    std::vector<int> index(n, 0);
    std::vector<float3> wo(n), wi(n), u(n);
    auto direction = [&random] {
        float3 u = random.next_float3();
        float z = 2.0f * u.x - 1.0f, r = std::sqrt(std::fmax(0.0f, 1.0f - z * z)), phi = 6.2831853f * u.y;
        return float3(r * std::cos(phi), r * std::sin(phi), z);
    };
    for (int k = 0; k < n; ++k) {
        wo[k] = direction();
        wi[k] = direction();
        u[k] = random.next_float3();
    }
    for (const brdf::Preset& preset : presets) {
        INFO(preset.name << ": " << brdf::feature_build_options({preset.material}));
        lab::kernels::BrdfBatch reduced(runtime, brdf::feature_build_options({preset.material}));
        full.set_materials({preset.material});
        reduced.set_materials({preset.material});
        std::vector<float3> f_full = full.eval(index, wo, wi), f_reduced = reduced.eval(index, wo, wi);
        std::vector<float> p_full = full.pdf(index, wo, wi), p_reduced = reduced.pdf(index, wo, wi);
        std::vector<brdf::BsdfSample> s_full = full.sample(index, wo, u), s_reduced = reduced.sample(index, wo, u);
        int differ = 0;
        for (int k = 0; k < n; ++k) {
            bool same = f_full[k] == f_reduced[k] && p_full[k] == p_reduced[k] && s_full[k].flags == s_reduced[k].flags &&
                        (s_full[k].flags == 0 || (s_full[k].wi == s_reduced[k].wi && s_full[k].f == s_reduced[k].f && s_full[k].pdf == s_reduced[k].pdf));
            differ += same ? 0 : 1;
        }
        CHECK(differ == 0);
    }
}
