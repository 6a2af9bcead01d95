// Chi-square goodness-of-fit of the default model's sampler against its pdf (the Mitsuba 3 test):
// every lobe and mixture, anisotropy with a turned tangent, both distributions, transmission from
// both sides, delta lobes mixed with continuous ones. Sidak-corrected over all the tests here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "tests/chi_square_suite.hpp"
#include "tests/lobe_material.hpp"
#include "tests/points_of_run.hpp"
#include "validation/chi_square.hpp"

using lab::validation::ChiSquareOptions;
using lab::validation::ChiSquareResult;

namespace {

struct Setting {
    const char* group;
    const char* name;
    brdf::Material material;
    bool inside;  // incident directions from below the surface (z < 0)
};

brdf::Material lobes(float diffuse, float glossy, float specular, float transmission) {
    brdf::Material m = lobe_material(diffuse, glossy, specular, transmission);
    m.albedo[0] = 0.8f;
    m.albedo[1] = 0.6f;
    m.albedo[2] = 0.4f;
    return m;
}

brdf::Material hyper_cauchy(brdf::Material m, float shape) {
    m.distribution = BRDF_DISTRIBUTION_HYPER_CAUCHY;
    m.hc_shape = shape;
    return m;
}

std::vector<Setting> settings() {
    std::vector<Setting> s;
    auto add = [&](const char* group, const char* name, brdf::Material m, bool inside = false) {
        s.push_back({group, name, m, inside});
    };
    const float deg = brdf::kDegrees;
    brdf::Material m;

    add("diffuse", "Lambert", lobes(1, 0, 0, 0));
    m = lobes(1, 0, 0, 0), m.retroreflection = 1.0f, m.roughness = 0.8f;
    add("diffuse", "Disney retro-reflective diffuse", m);
    m = lobes(1, 0, 0, 0), m.subsurface = 1.0f, m.subsurface_asymmetry = -0.6f, m.retroreflection = 0.5f;
    add("diffuse", "Henyey-Greenstein subsurface", m);

    m = lobes(0.7f, 0.3f, 0, 0), m.roughness = 0.4f, m.fresnel = 0.04f;
    add("glossy", "GGX coat over diffuse", m);
    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 0.25f;
    add("glossy", "GGX rough metal 0.25", m);
    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 1.0f;
    add("glossy", "GGX rough metal 1.0", m);
    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 0.45f, m.anisotropic = 0.8f, m.tangent_rotation = 30 * deg;
    add("glossy", "GGX anisotropic 0.8, tangent 30 deg", m);
    m = lobes(0.4f, 0.6f, 0, 0), m.roughness = 0.6f, m.anisotropic = 1.0f, m.tangent_rotation = -70 * deg;
    add("glossy", "GGX anisotropic 1, tangent -70 deg, over diffuse", m);
    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 0.15f, m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    add("glossy", "GGX conductor F0 = 1, roughness 0.15", m);

    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 0.4f;
    add("hyper_cauchy", "Hyper-Cauchy 1.6 metal", hyper_cauchy(m, 1.6f));
    m = lobes(0.5f, 0.5f, 0, 0), m.roughness = 0.3f;
    add("hyper_cauchy", "Hyper-Cauchy 2 over diffuse", hyper_cauchy(m, 2.0f));
    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 0.5f, m.anisotropic = 0.6f, m.tangent_rotation = 45 * deg;
    add("hyper_cauchy", "Hyper-Cauchy 3 anisotropic 0.6, tangent 45 deg", hyper_cauchy(m, 3.0f));
    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 0.35f;
    add("hyper_cauchy", "Hyper-Cauchy 5 metal", hyper_cauchy(m, 5.0f));
    m = lobes(0, 1, 0, 0), m.metallic = 1.0f, m.roughness = 0.25f;
    add("hyper_cauchy", "Hyper-Cauchy 8 metal", hyper_cauchy(m, 8.0f));

    m = lobes(0, 0, 0, 1), m.roughness = 0.3f, m.ior = 1.5f;
    add("transmission", "rough glass GGX, ior 1.5, from outside", m);
    m = lobes(0, 0, 0, 1), m.roughness = 0.45f, m.ior = 1.33f;
    add("transmission", "rough water GGX, ior 1.33, from inside", m, true);
    m = lobes(0, 0, 0, 1), m.roughness = 0.4f, m.ior = 1.5f, m.anisotropic = 0.7f, m.tangent_rotation = 20 * deg;
    add("transmission", "rough glass GGX anisotropic 0.7, from outside", m);
    m = lobes(0, 0, 0, 1), m.roughness = 0.4f, m.ior = 2.4f;
    add("transmission", "rough diamond Hyper-Cauchy 2.5, from outside", hyper_cauchy(m, 2.5f));
    m = lobes(0, 0, 0, 1), m.roughness = 0.35f, m.ior = 1.5f;
    add("transmission", "rough glass Hyper-Cauchy 1.8, from inside", hyper_cauchy(m, 1.8f), true);

    m = lobes(0.3f, 0, 0, 0.7f), m.roughness = 0.0f, m.ior = 1.5f;
    add("delta", "smooth glass + diffuse, from outside", m);
    add("delta", "smooth glass + diffuse, from inside", m, true);
    m = lobes(0.5f, 0.3f, 0.2f, 0), m.roughness = 0.4f;
    add("delta", "diffuse + glossy + mirror", m);
    m = lobes(0.5f, 0.2f, 0, 0.3f), m.metallic = 1.0f, m.roughness = 0.35f;
    add("delta", "metal: diffuse weight to glossy, transmission to mirror", m);
    m = lobes(0.3f, 0.3f, 0.2f, 0.4f), m.metallic = 0.5f, m.roughness = 0.45f, m.ior = 1.7f;
    add("delta", "half metal, all lobes, Hyper-Cauchy 1.8, from outside", hyper_cauchy(m, 1.8f));
    add("delta", "half metal, all lobes, Hyper-Cauchy 1.8, from inside", hyper_cauchy(m, 1.8f), true);
    return s;
}

// Five incident directions, from near-normal to grazing, at azimuths away from the tangent.
const float kThetas[5] = {0.0f, 28.0f, 52.0f, 71.0f, 86.0f};
const float kPhis[5] = {0.0f, 40.0f, 200.0f, 115.0f, 300.0f};

int total_tests() { return int(settings().size()) * 5; }

// A group's every setting, at `directions` of the five incident directions drawn per run
// (tests/points_of_run.hpp; 5: all of them). The Sidak level stays that of the whole suite's
// kChiSquareSuiteTests, so each test's power is the stated one.
void run_group(const std::string& group, int directions = 5) {
    const std::vector<Setting> all = settings();
    double smallest = 1.0;
    std::string smallest_at;
    int runs = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        const Setting& s = all[i];
        if (group != s.group) continue;
        for (int d : sweep_points_of_run(std::string("chi-square directions: ") + s.name, 5, directions)) {
            float theta = s.inside ? 180.0f - kThetas[d] : kThetas[d];
            brdf::float3 wo = brdf::direction_from_degrees(theta, kPhis[d]);
            ChiSquareOptions options = chi_square_suite_options();
            options.seed = 1000 * i + d + 1;  // independent tests, as Sidak assumes
            ChiSquareResult r = lab::validation::chi_square_bsdf(s.material, wo, options);
            ++runs;
            INFO(s.name << ", theta " << theta << " phi " << kPhis[d] << ": " << lab::validation::describe(r));
            CHECK(r.passed);
            if (r.p_value < smallest) {
                smallest = r.p_value;
                smallest_at = std::string(s.name) + ", theta " + std::to_string(theta);
            }
        }
    }
    REQUIRE(runs > 0);
    std::printf("chi-square [%s]: %d tests (Sidak over %d), smallest p-value %.4g (%s)\n", group.c_str(), runs,
                total_tests(), smallest, smallest_at.c_str());
}

}  // namespace

TEST_CASE("chi-square suite covers at least 20 settings x 5 directions", "[chi_square]") {
    CHECK(settings().size() >= 20);
    CHECK(total_tests() == kChiSquareSuiteTests);  // the Sidak level the power checks use
}

TEST_CASE("chi-square: diffuse lobes", "[chi_square][sweep]") { run_group("diffuse"); }
TEST_CASE("chi-square: GGX glossy lobes, isotropic and anisotropic", "[chi_square][sweep]") { run_group("glossy"); }
TEST_CASE("chi-square: Hyper-Cauchy glossy lobes, shapes 1.6 to 8", "[chi_square][sweep]") { run_group("hyper_cauchy", 2); }
TEST_CASE("chi-square: rough transmission from both sides", "[chi_square][sweep]") { run_group("transmission", 2); }
TEST_CASE("chi-square: mixtures with delta lobes", "[chi_square][sweep]") { run_group("delta", 2); }
