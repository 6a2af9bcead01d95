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
#include "validation/random_inputs.hpp"
#include "validation/reciprocity.hpp"
#include "validation/uniform_random.hpp"
#include "validation/sampling_efficiency.hpp"

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

// One panel's extremes: its least and greatest value and where they lie.
struct AtlasExtremes {
    std::string panel;
    double least = 0.0, greatest = 0.0;
    double least_roughness = 0.0, least_theta = 0.0, greatest_roughness = 0.0, greatest_theta = 0.0;
    double least_error = -1.0, greatest_error = -1.0;  // the standard errors of those two estimates; < 0: none (not an estimate)
};

// The entry's table: each panel's extremes, with their standard errors, roughness and angle.
Table extremes_table(const std::vector<AtlasExtremes>& extremes) {
    auto error = [](double se) { return se < 0.0 ? text_cell("-") : number_cell(se, 2); };
    auto degrees = [](double deg) { return text_cell(number_text(deg, 3) + "°"); };
    Table table;
    table.header = {"method", "least", "± standard error", "at roughness", "at θ", "greatest", "± standard error", "at roughness", "at θ"};
    for (const AtlasExtremes& x : extremes)
        table.rows.push_back({text_cell(x.panel), number_cell(x.least, 4), error(x.least_error), number_cell(x.least_roughness, 2),
                              degrees(x.least_theta), number_cell(x.greatest, 4), error(x.greatest_error), number_cell(x.greatest_roughness, 2),
                              degrees(x.greatest_theta)});
    return table;
}

constexpr int kStrata = 32;  // 1024 importance samples per estimate: a standard error of a few 1e-3

// A panel of the atlas: a white conductor of this model and distribution, compensated or not.
struct Method {
    std::string name;
    int model, distribution;
    bool compensated;
};

// The white conductors the energy and reciprocity entries compare: the lab model without and with
// energy compensation, and the 2017 model.
const std::vector<Method>& white_conductors() {
    static const std::vector<Method> methods = {{"lab, single scattering", BRDF_MODEL_LAB, BRDF_DISTRIBUTION_GGX, false},
                                         {"lab, energy compensation", BRDF_MODEL_LAB, BRDF_DISTRIBUTION_GGX, true},
                                         {"dtoadq2017", BRDF_MODEL_DTOADQ2017, BRDF_DISTRIBUTION_GGX, false}};
    return methods;
}

// The grid of the entries whose cells cost thousands of evaluations: roughness 0.05 to 0.95, and
// incident angle 0 to 80 degrees and 88.
void coarse_grid(std::vector<double>* roughness, std::vector<double>* theta) {
    for (int i = 0; i < 10; ++i) roughness->push_back(0.05 + 0.1 * i);
    for (int j = 0; j <= 8; ++j) theta->push_back(10.0 * j);
    theta->push_back(88.0);
}

// The method's panel over the grid, x (roughness) major, each cell value(material, wo, &standard
// error; < 0 for none), and its extremes.
template <typename Value>
plots::HeatmapPanel sweep(const Method& method, const std::vector<double>& roughness, const std::vector<double>& theta, Value value,
                          AtlasExtremes* e) {
    plots::HeatmapPanel panel{method.name, {}};
    *e = AtlasExtremes{};
    e->panel = method.name;
    e->least = 1e30;
    e->greatest = -1e30;
    for (double r : roughness) {
        brdf::Material m = atlas_white_conductor(method.model, float(r), method.compensated);
        m.distribution = method.distribution;
        for (double t : theta) {
            double se = -1.0;
            const double v = value(m, brdf::direction_from_degrees(float(t), 0.0f), &se);
            panel.values.push_back(v);
            if (v < e->least) e->least = v, e->least_roughness = r, e->least_theta = t, e->least_error = se;
            if (v > e->greatest) e->greatest = v, e->greatest_roughness = r, e->greatest_theta = t, e->greatest_error = se;
        }
    }
    return panel;
}

AtlasEntry energy_entry(const fs::path& folder) {
    std::vector<double> roughness, theta;
    for (int i = 1; i <= 20; ++i) roughness.push_back(0.05 * i);
    for (int j = 0; j <= 17; ++j) theta.push_back(5.0 * j);
    theta.push_back(88.0);
    const std::vector<Method>& methods = white_conductors();
    AtlasEntry entry;
    std::vector<AtlasExtremes> extremes;
    entry.title = "Energy: directional albedo of a white conductor over roughness and incident angle";
    std::vector<plots::HeatmapPanel> panels;
    for (const Method& method : methods) {
        AtlasExtremes e;
        panels.push_back(sweep(method, roughness, theta,
                               [](const brdf::Material& m, brdf::float3 wo, double* se) {
                                   const validation::AlbedoEstimate a = validation::directional_albedo(m, wo, kStrata);
                                   *se = std::max({double(a.std_error.x), double(a.std_error.y), double(a.std_error.z)});
                                   return std::max({double(a.value.x), double(a.value.y), double(a.value.z)});
                               },
                               &e));
        extremes.push_back(e);
    }
    entry.image = "atlas_energy.png";
    entry.csv = "atlas_energy.csv";
    plots::write_heatmap_chart(panels, roughness, theta, "roughness", "incident angle θ (degrees)", "directional albedo (1: energy kept)", 1.0,
                               "White conductor: where energy is lost (blue) or created (red)", (folder / entry.image).string(),
                               (folder / entry.csv).string());
    const AtlasExtremes &single = extremes[0], &compensated = extremes[1], &old = extremes[2];
    char finding[512];
    std::snprintf(finding, sizeof finding,
                  "Single scattering loses up to %s of the light (roughness %.2g, θ %.0f°); energy compensation keeps the albedo within "
                  "[%.3f, %.3f] (the greatest ± %.2g, at θ %.0f°); the 2017 model ranges from %.3f to %.3f, creating energy where it exceeds 1 "
                  "(up to %.2f× at roughness %.2g, θ %.0f°).",
                  percent_text(1.0 - single.least, 3).c_str(), single.least_roughness, single.least_theta, compensated.least, compensated.greatest,
                  compensated.greatest_error, compensated.greatest_theta, old.least, old.greatest, old.greatest, old.greatest_roughness,
                  old.greatest_theta);
    entry.finding = finding;
    entry.how = "Each cell is the largest channel of the directional albedo at that roughness (GGX, isotropic, F0 = 1, albedo 1) and "
                "incident angle, estimated with the BSDF's own sampler on a stratified grid of " + std::to_string(kStrata * kStrata) +
                " samples; the table gives each extreme's standard error. The colour scale diverges at 1: blue is energy lost, red energy "
                "created.";
    entry.table = extremes_table(extremes);
    return entry;
}

// The samplers: the variance of cosine-weighted sampling over the variance of the material's own
// sampler, for the directional albedo's one-sample estimator, as log10 (0: no gain; below 0 the
// sampler is worse than cosine sampling).
AtlasEntry sampler_entry(const fs::path& folder) {
    std::vector<double> roughness, theta;
    coarse_grid(&roughness, &theta);
    constexpr long kSamples = 4000;
    constexpr double kLogCap = 6.0;
    const std::vector<Method> methods = {{"lab, GGX (visible normals)", BRDF_MODEL_LAB, BRDF_DISTRIBUTION_GGX, false},
                                         {"lab, Hyper-Cauchy, shape 3", BRDF_MODEL_LAB, BRDF_DISTRIBUTION_HYPER_CAUCHY, false},
                                         {"dtoadq2017", BRDF_MODEL_DTOADQ2017, BRDF_DISTRIBUTION_GGX, false}};
    auto efficiency = [](brdf::Material m, brdf::float3 wo) {
        m.hc_shape = 3.0f;
        return validation::sampling_efficiency(m, wo, kSamples);
    };
    AtlasEntry entry;
    std::vector<AtlasExtremes> extremes;
    entry.title = "Samplers: how much each glossy lobe's sampler beats cosine sampling, over roughness and incident angle";
    std::vector<plots::HeatmapPanel> panels;
    std::string below;
    for (const Method& method : methods) {
        AtlasExtremes e;
        int cells_below = 0;
        panels.push_back(sweep(method, roughness, theta,
                               [&](const brdf::Material& m, brdf::float3 wo, double*) {
                                   const double ratio = efficiency(m, wo).ratio;
                                   // no continuous part (NaN): no gain either way; a sampler of zero variance (a narrow lobe it
                                   // follows exactly, ratio infinite) and every ratio beyond a millionfold show at the scale's end
                                   const double v = std::isnan(ratio) ? 0.0 : std::clamp(std::log10(std::max(ratio, 1e-300)), -kLogCap, kLogCap);
                                   cells_below += v < 0.0;
                                   return v;
                               },
                               &e));
        brdf::Material least = atlas_white_conductor(method.model, float(e.least_roughness), false);
        least.distribution = method.distribution;
        const double failed = efficiency(least, brdf::direction_from_degrees(float(e.least_theta), 0.0f)).failed_fraction;
        char line[256];
        std::snprintf(line, sizeof line, "%s%s: %d of %zu cells below 1 (least %.2g× at roughness %.2g, θ %.0f°, where %.0f %% of its draws fail)",
                      below.empty() ? "" : "; ", method.name.c_str(), cells_below, roughness.size() * theta.size(), std::pow(10.0, e.least),
                      e.least_roughness, e.least_theta, 100.0 * failed);
        below += line;
        extremes.push_back(e);
    }
    entry.image = "atlas_samplers.png";
    entry.csv = "atlas_samplers.csv";
    plots::write_heatmap_chart(panels, roughness, theta, "roughness", "incident angle θ (degrees)",
                               "log10(variance with cosine sampling / with the sampler)", 0.0,
                               "Samplers against cosine sampling: where they win (red) and lose (blue)", (folder / entry.image).string(),
                               (folder / entry.csv).string());
    entry.finding = "Where the sampler loses to cosine sampling: " + below + ".";
    entry.how = "Each cell is log10 of the ratio of the variances of the directional albedo's one-sample estimator f |cos θi| / pdf, "
                "with cosine-weighted sampling and with the material's own sampler (" + std::to_string(kSamples) +
                " samples each), for a white conductor of that roughness at that incident angle, clamped to ±6 (a millionfold; a sampler "
                "that follows a narrow lobe exactly has no variance at all); the table's extremes are in log10 too. "
                "A draw that fails (a reflection below the horizon) adds 0, so a sampler that loses many of its draws "
                "at high roughness loses to cosine sampling however well it follows the lobe's peak.";
    entry.table = extremes_table(extremes);
    return entry;
}

// Reciprocity: the largest relative difference between f(wo, wi) and f(wi, wo) over random wi in the
// upper hemisphere, as log10, on a scale that diverges at the validation's tolerance (1e-4).
AtlasEntry reciprocity_entry(const fs::path& folder) {
    std::vector<double> roughness, theta;
    coarse_grid(&roughness, &theta);
    constexpr int kPairs = 2000;
    constexpr double kTolerance = 1e-4;  // validation::ValidationOptions::reciprocity_tolerance
    constexpr double kFloor = 1e-9;      // below float's resolution: shown as equal
    const std::vector<Method>& methods = white_conductors();
    AtlasEntry entry;
    std::vector<AtlasExtremes> extremes;
    entry.title = "Reciprocity: the largest relative difference between f(wo, wi) and f(wi, wo), over roughness and angle";
    std::vector<plots::HeatmapPanel> panels;
    std::string over;
    for (const Method& method : methods) {
        AtlasExtremes e;
        int cells_over = 0;
        panels.push_back(sweep(method, roughness, theta,
                               [&](const brdf::Material& m, brdf::float3 wo, double*) {
                                   validation::UniformRandom rng(1);
                                   double worst = 0.0;
                                   for (int k = 0; k < kPairs; ++k) {
                                       const brdf::float3 wi = validation::uniform_hemisphere_direction(rng);
                                       worst = std::max(worst, validation::relative_difference(brdf::bsdf_eval(&m, wo, wi), brdf::bsdf_eval(&m, wi, wo)));
                                   }
                                   cells_over += worst > kTolerance;
                                   return std::log10(std::max(worst, kFloor));
                               },
                               &e));
        char line[200];
        std::snprintf(line, sizeof line, "%s%s: %d of %zu cells above it (largest %.2g at roughness %.2g, θ %.0f°)", over.empty() ? "" : "; ",
                      method.name.c_str(), cells_over, roughness.size() * theta.size(), std::pow(10.0, e.greatest), e.greatest_roughness,
                      e.greatest_theta);
        over += line;
        extremes.push_back(e);
    }
    entry.image = "atlas_reciprocity.png";
    entry.csv = "atlas_reciprocity.csv";
    plots::write_heatmap_chart(panels, roughness, theta, "roughness", "incident angle θ (degrees)", "log10(largest relative difference)",
                               std::log10(kTolerance), "Reciprocity: within the tolerance 1e-4 (blue) or beyond it (red)",
                               (folder / entry.image).string(), (folder / entry.csv).string());
    entry.finding = "Against the validation's tolerance of 1e-4: " + over + ".";
    entry.how = "Each cell is log10 of the largest relative difference, over the channels and " + std::to_string(kPairs) +
                " directions wi drawn uniformly over the upper hemisphere, between f(wo, wi) and f(wi, wo) for a white conductor of that "
                "roughness with wo at that angle; differences below 1e-9 show as 1e-9. The scale diverges at the tolerance; the table's "
                "extremes are in log10 too.";
    entry.table = extremes_table(extremes);
    return entry;
}

}  // namespace

std::vector<AtlasEntry> write_stability_atlas(const fs::path& folder) {
    return {energy_entry(folder), sampler_entry(folder), reciprocity_entry(folder)};
}

}  // namespace lab::report
