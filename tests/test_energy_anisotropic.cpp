// Energy compensation of anisotropic GGX conductors (brdf/energy_compensation.h, the anisotropic table):
// the white furnace of an F0 = 1 conductor, lab and openpbr models, over anisotropy, roughness, theta_o
// and the azimuth phi_o of wo from the tangent, on which an anisotropic lobe's albedo depends.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "validation/albedo.hpp"
#include "validation/energy_tables.hpp"

// A named namespace keeps the using-directive to this file in its unity group (tests/CMakeLists.txt).
namespace energy_anisotropic_test {
using namespace lab::validation;

namespace {

brdf::Material white_conductor(int model, float roughness, float anisotropy, int compensation) {
    brdf::Material m = brdf::default_material(model);
    if (model == BRDF_MODEL_LAB) m.weight_diffuse = 0.0f, m.weight_glossy = 1.0f, m.weight_specular = 0.0f, m.weight_transmission = 0.0f;
    m.metallic = 1.0f;
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    m.roughness = roughness;
    m.anisotropic = anisotropy;
    m.energy_compensation = compensation;
    return m;
}

// The compensated albedo as the sampled albedo of the single-scattering lobe (visible normals, weights
// at most 1: a tight estimate and its standard error) plus what compensation adds to bsdf_eval(),
// integrated by the midpoint rule in sqrt(mu_i) and phi_i: it is smooth, and depends on phi_i. `added_scale`
// scales that part: 2 is a broken compensation that gives back twice what it should.
AlbedoEstimate furnace_albedo(const brdf::Material& m, brdf::float3 wo, double added_scale) {
    brdf::Material single = m;
    single.energy_compensation = 0;
    AlbedoEstimate a = directional_albedo(single, wo, 64, 7);
    if (!m.energy_compensation) return a;
    const double added = hemisphere_cosine_midpoint(128, 64, [&](brdf::float3 wi) {
        return double(brdf::bsdf_eval(&m, wo, wi).x - brdf::bsdf_eval(&single, wo, wi).x);
    });
    a.value.x += float(added_scale * added);
    return a;
}

struct Sweep {
    double lowest = 9.0, highest_excess = -9.0;  // lowest albedo; largest (albedo - 1) / standard error
    std::string lowest_at, highest_at;
    int outside = 0;  // points outside [0.99, 1 + 4 standard errors]
};

const float kRoughness[] = {0.2f, 0.35f, 0.5f, 0.75f, 1.0f};
const float kThetas[] = {0.0f, 30.0f, 60.0f, 75.0f, 80.0f};
const float kPhis[] = {0.0f, 30.0f, 45.0f, 60.0f, 90.0f};

Sweep furnace_sweep(int model, float anisotropy, int compensation, double added_scale) {
    Sweep s;
    for (float r : kRoughness)
        for (float theta : kThetas)
            for (float phi : kPhis) {
                AlbedoEstimate a =
                    furnace_albedo(white_conductor(model, r, anisotropy, compensation), brdf::direction_from_degrees(theta, phi), added_scale);
                double value = a.value.x, error = std::fmax(double(a.std_error.x), 1e-7);
                char at[96];
                std::snprintf(at, sizeof at, "r %.2f theta %.0f phi %.0f: %.4f +- %.5f", double(r), double(theta), double(phi), value, error);
                if (value < s.lowest) s.lowest = value, s.lowest_at = at;
                if ((value - 1.0) / error > s.highest_excess) s.highest_excess = (value - 1.0) / error, s.highest_at = at;
                if (value < 0.99 || value > 1.0 + 4.0 * error) ++s.outside;
            }
    return s;
}

// The points of the sweep outside [0.99, 1 + 4 standard errors] (of the sampled part, validation/albedo.hpp).
int check_models(std::initializer_list<float> anisotropies, int compensation, double added_scale = 1.0) {
    int outside = 0;
    for (int model : {BRDF_MODEL_LAB, BRDF_MODEL_OPENPBR})
        for (float a : anisotropies) {
            Sweep s = furnace_sweep(model, a, compensation, added_scale);
            std::printf("  %-7s anisotropy %.2f: lowest %s; largest excess %.1f standard errors (%s); %d of %zu outside\n",
                        model == BRDF_MODEL_LAB ? "lab" : "openpbr", double(a), s.lowest_at.c_str(), s.highest_excess, s.highest_at.c_str(),
                        s.outside, std::size(kRoughness) * std::size(kThetas) * std::size(kPhis));
            outside += s.outside;
        }
    return outside;
}

}  // namespace

TEST_CASE("furnace with compensation: anisotropic F0 = 1 conductors, lab and openpbr, up to anisotropy 0.5 reflect [0.99, 1 + 4 SE]",
          "[energy_compensation][furnace]") {
    std::printf("anisotropic furnace, compensated, anisotropy 0.25 and 0.5:\n");
    CHECK(check_models({0.25f, 0.5f}, 1) == 0);
}

// The strongly anisotropic lobes, whose E turns fastest with the azimuth and the ratio near grazing
// (docs/materials.md): the table's denser nodes there (brdf/energy_grid.h) are what this checks.
TEST_CASE("furnace with compensation: anisotropic F0 = 1 conductors reflect [0.99, 1 + 4 SE] up to anisotropy 1",
          "[energy_compensation][furnace][sweep]") {
    std::printf("anisotropic furnace, compensated, anisotropy 0.75, 0.9 and 1:\n");
    CHECK(check_models({0.75f, 0.9f, 1.0f}, 1) == 0);
}

TEST_CASE("anisotropic furnace: the check fails on the uncompensated lobes, and on a compensation that gives back too much",
          "[energy_compensation][furnace][sweep]") {
    std::printf("anisotropic furnace, single scattering, anisotropy 0.5:\n");
    CHECK(check_models({0.5f}, 0) > 0);
    std::printf("anisotropic furnace, twice the compensation, anisotropy 0.5:\n");
    CHECK(check_models({0.5f}, 1, 2.0) > 0);
}

TEST_CASE("anisotropic energy table: E_avg is the hemispherical average of the interpolated E(w), so f_ms reflects 1 - E(wo)",
          "[energy_compensation]") {
    // (1 / pi) int E(w) cos dw of the lookup, by the midpoint rule in mu and phi, against the stored E_avg
    double worst = 0.0;
    for (float q : {0.05f, 0.3f, 0.62f})
        for (float alpha : {0.04f, 0.25f, 0.6f, 1.3f}) {
            float ax = alpha, ay = alpha * q;
            for (bool swap : {false, true}) {
                brdf::Microfacet mf = brdf::microfacet_make(BRDF_DISTRIBUTION_GGX, swap ? ay : ax, swap ? ax : ay, 2.0f);
                const int n_mu = 2000, n_phi = 360;
                double sum = 0.0;
                for (int i = 0; i < n_mu; ++i) {
                    double mu = (i + 0.5) / n_mu, s = std::sqrt(1.0 - mu * mu);
                    for (int j = 0; j < n_phi; ++j) {
                        double phi = 2.0 * M_PI * (j + 0.5) / n_phi;
                        sum += brdf::microfacet_energy_albedo(mf, brdf::float3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(mu))) * mu;
                    }
                }
                double average = 2.0 * sum / (double(n_mu) * n_phi);
                INFO("q " << q << " alpha " << alpha << " swapped " << swap);
                CHECK(brdf::microfacet_energy_average(mf) == Approx(average).margin(1e-4));
                worst = std::fmax(worst, std::fabs(double(brdf::microfacet_energy_average(mf)) - average));
            }
        }
    std::printf("anisotropic energy table: largest |E_avg - average of E(w)| %.2g\n", worst);
}

}  // namespace energy_anisotropic_test
