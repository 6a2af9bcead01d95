#include "report/stability_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "brdf/brdf.hpp"
#include "brdf/host/angles.hpp"
#include "brdf/host/parameters.hpp"
#include "plots/heatmap_chart.hpp"
#include "report/html_page.hpp"
#include "validation/albedo.hpp"

namespace lab::report {

namespace fs = std::filesystem;

brdf::Material atlas_white_conductor(int model, float roughness, bool compensated) {
    brdf::Material m = brdf::default_material();
    m.model = model;
    for (float& a : m.albedo) a = 1.0f;
    m.metallic = 1.0f;
    m.roughness = roughness;
    m.weight_diffuse = 0.0f;
    m.weight_glossy = 1.0f;
    m.weight_specular = 0.0f;
    m.weight_transmission = 0.0f;
    m.distribution = BRDF_DISTRIBUTION_GGX;
    m.energy_compensation = compensated ? 1 : 0;
    return m;
}

namespace {

constexpr int kStrata = 32;  // 1024 importance samples per estimate: a standard error of a few 1e-3

std::string percent(double fraction) { return number_text(100.0 * fraction, 3) + " %"; }

AtlasEntry energy_entry(const fs::path& folder) {
    std::vector<double> roughness, theta;
    for (int i = 1; i <= 20; ++i) roughness.push_back(0.05 * i);
    for (int j = 0; j <= 17; ++j) theta.push_back(5.0 * j);
    theta.push_back(88.0);
    struct Method {
        std::string name;
        int model;
        bool compensated;
    };
    const std::vector<Method> methods = {{"lab, single scattering", BRDF_MODEL_LAB, false},
                                         {"lab, energy compensation", BRDF_MODEL_LAB, true},
                                         {"dtoadq2017", BRDF_MODEL_DTOADQ2017, false}};
    AtlasEntry entry;
    entry.title = "Energy: directional albedo of a white conductor over roughness and incident angle";
    std::vector<plots::HeatmapPanel> panels;
    for (const Method& method : methods) {
        plots::HeatmapPanel panel{method.name, {}};
        AtlasExtremes e;
        e.panel = method.name;
        e.least = 1e30;
        e.greatest = -1e30;
        for (double r : roughness) {
            const brdf::Material m = atlas_white_conductor(method.model, float(r), method.compensated);
            for (double t : theta) {
                const brdf::float3 wo = brdf::direction_from_degrees(float(t), 0.0f);
                const validation::AlbedoEstimate a = validation::directional_albedo(m, wo, kStrata);
                const double value = std::max({double(a.value.x), double(a.value.y), double(a.value.z)});
                const double se = std::max({double(a.std_error.x), double(a.std_error.y), double(a.std_error.z)});
                panel.values.push_back(value);
                if (value < e.least) e.least = value, e.least_roughness = r, e.least_theta = t, e.least_error = se;
                if (value > e.greatest) e.greatest = value, e.greatest_roughness = r, e.greatest_theta = t, e.greatest_error = se;
            }
        }
        panels.push_back(std::move(panel));
        entry.extremes.push_back(e);
    }
    entry.image = "atlas_energy.png";
    entry.csv = "atlas_energy.csv";
    plots::write_heatmap_chart(panels, roughness, theta, "roughness", "incident angle θ (degrees)", "directional albedo (1: energy kept)", 1.0,
                               "White conductor: where energy is lost (blue) or created (red)", (folder / entry.image).string(),
                               (folder / entry.csv).string());
    const AtlasExtremes &single = entry.extremes[0], &compensated = entry.extremes[1], &old = entry.extremes[2];
    char finding[512];
    std::snprintf(finding, sizeof finding,
                  "Single scattering loses up to %s of the light (roughness %.2g, θ %.0f°); energy compensation keeps the albedo within "
                  "[%.3f, %.3f] (the greatest ± %.2g, at θ %.0f°); the 2017 model ranges from %.3f to %.3f, creating energy where it exceeds 1 "
                  "(up to %.2f× at roughness %.2g, θ %.0f°).",
                  percent(1.0 - single.least).c_str(), single.least_roughness, single.least_theta, compensated.least, compensated.greatest,
                  compensated.greatest_error, compensated.greatest_theta, old.least, old.greatest, old.greatest, old.greatest_roughness,
                  old.greatest_theta);
    entry.finding = finding;
    entry.how = "Each cell is the largest channel of the directional albedo at that roughness (GGX, isotropic, F0 = 1, albedo 1) and "
                "incident angle, estimated with the BSDF's own sampler on a stratified grid of " + std::to_string(kStrata * kStrata) +
                " samples; the table gives each extreme's standard error. The colour scale diverges at 1: blue is energy lost, red energy created.";
    return entry;
}

}  // namespace

std::vector<AtlasEntry> write_stability_atlas(const fs::path& folder) { return {energy_entry(folder)}; }

}  // namespace lab::report
