// Fitting the lab model to measured tables (fit/, docs/fitting.md): the round trip through MERL
// files made from known lab materials (GGX and Hyper-Cauchy, isotropic, on a diffuse base), where
// the fit must recover roughness within 5 % and albedo within 2 %, and the option checks.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "analysis/lobe_data.hpp"
#include "brdf/host/merl_file.hpp"
#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "fit/fit_metric.hpp"
#include "fit/fit_optimizer.hpp"
#include "fit/fit_pairs.hpp"
#include "fit/fit_report.hpp"
#include "fit/fit_space.hpp"
#include "plots/fit_chart.hpp"

namespace fs = std::filesystem;
using brdf::float3;
using brdf::Material;

namespace {

struct RoundTripCase {
    const char* name;
    int distribution;
    float albedo[3];
    float roughness;
    float weight_glossy;  // next to weight_diffuse 1
    float fresnel;
    float hc_shape;
};

Material case_material(const RoundTripCase& c) {
    Material m = brdf::default_material();
    m.distribution = c.distribution;
    for (int k = 0; k < 3; ++k) m.albedo[k] = c.albedo[k];
    m.roughness = c.roughness;
    m.weight_diffuse = 1.0f;
    m.weight_glossy = c.weight_glossy;
    m.weight_specular = m.weight_transmission = 0.0f;
    m.fresnel = c.fresnel;
    m.metallic = 0.0f;
    m.hc_shape = c.hc_shape;
    m.energy_compensation = 1;
    return m;
}

}  // namespace

// The test's pairs and starts are fewer than the command's defaults (docs/fitting.md) to keep it
// cheap; the data are noise-free and the model holds the truth, so the tolerances are the fit's
// stated accuracy (docs/fitting.md): 5 % in roughness, 2 % in each albedo channel.
// [sweep]: 7 s of CPU, a ctest test of its own (docs/testing.md).
TEST_CASE("fit: MERL files made from known lab materials give their roughness and albedo back", "[fit][sweep]") {
    const RoundTripCase cases[] = {
        {"ggx_smooth", BRDF_DISTRIBUTION_GGX, {0.70f, 0.40f, 0.20f}, 0.30f, 0.6f, 0.04f, 2.0f},
        {"ggx_rough", BRDF_DISTRIBUTION_GGX, {0.25f, 0.50f, 0.80f}, 0.60f, 1.0f, 0.08f, 2.0f},
        {"hc_light_tails", BRDF_DISTRIBUTION_HYPER_CAUCHY, {0.50f, 0.50f, 0.30f}, 0.25f, 0.5f, 0.04f, 3.0f},
        {"hc_long_tails", BRDF_DISTRIBUTION_HYPER_CAUCHY, {0.15f, 0.30f, 0.60f}, 0.45f, 0.8f, 0.05f, 1.8f},
    };
    lab::fit::FitOptions options;
    options.starts = 2;
    options.max_evaluations = 3000;
    const lab::fit::PairGrid grid{6, 6, 20, 1};
    for (const RoundTripCase& c : cases) {
        const Material truth = case_material(c);
        const std::string path = (fs::temp_directory_path() / (std::string("dtoadq_fit_") + c.name + ".binary")).string();
        brdf::write_merl_file(path, brdf::tabulate_merl([&](float3 wo, float3 wi) { return brdf::bsdf_eval(&truth, wo, wi); }, c.name));
        const brdf::MeasuredTable table = brdf::read_merl_file(path);
        fs::remove(path);

        lab::fit::FitSpace space;
        space.distribution = c.distribution;
        const lab::fit::FitResult r = lab::fit::fit_material(lab::fit::fit_pairs(table, grid), space, options);
        const Material& m = r.material;
        // the figures for the docs: recovered parameters, error and time (timings are noisy here)
        std::printf("fit round trip %-15s roughness %.4f (%.4f)  albedo %.4f %.4f %.4f (%.2f %.2f %.2f)  hc_shape %.3f (%.2f)  "
                    "error %.2e  %d pairs  %d evaluations  %.2f s\n",
                    c.name, m.roughness, c.roughness, m.albedo[0], m.albedo[1], m.albedo[2], c.albedo[0], c.albedo[1], c.albedo[2],
                    m.hc_shape, c.hc_shape, r.error, r.pairs, r.evaluations, r.seconds);
        INFO(c.name << ": error " << r.error);
        CHECK(std::fabs(m.roughness - c.roughness) <= 0.05f * c.roughness);
        for (int k = 0; k < 3; ++k) CHECK(std::fabs(m.albedo[k] - c.albedo[k]) <= 0.02f * c.albedo[k]);
    }
}

TEST_CASE("fit: the error is zero at the truth and grows away from it", "[fit]") {
    Material truth = case_material({"t", BRDF_DISTRIBUTION_GGX, {0.5f, 0.4f, 0.3f}, 0.4f, 0.5f, 0.04f, 2.0f});
    const brdf::MeasuredTable table =
        brdf::tabulate_merl([&](float3 wo, float3 wi) { return brdf::bsdf_eval(&truth, wo, wi); }, "truth");
    const std::vector<lab::fit::FitPair> pairs = lab::fit::fit_pairs(table, lab::fit::PairGrid{6, 6, 20, 1});
    REQUIRE(pairs.size() > 500);
    for (const lab::fit::FitPair& p : pairs) REQUIRE((p.wo.z > 0.0f && p.wi.z > 0.0f));
    CHECK(lab::fit::fit_error(truth, pairs) == 0.0);
    // an entry marked unmeasured (MERL's -1) is no pair
    brdf::MeasuredTable marked = table;
    const lab::fit::FitPair& first = pairs.front();
    marked.unmeasured.assign(MERL_ENTRY_COUNT, false);
    marked.unmeasured[std::size_t(brdf::merl_entry_index(first.ih, first.id, first.ip))] = true;
    CHECK(lab::fit::fit_pairs(marked, lab::fit::PairGrid{6, 6, 20, 1}).size() == pairs.size() - 1);
    Material rougher = truth;
    rougher.roughness = 0.42f;
    CHECK(lab::fit::fit_error(rougher, pairs) > 1e-3);
    // the space maps the truth to a vector and back
    lab::fit::FitSpace space;
    const Material back = lab::fit::material_from_parameters(space, lab::fit::parameters_from_material(space, truth));
    CHECK(lab::fit::fit_error(back, pairs) < 1e-6);
    // the breakdown's channels and bands agree with the total
    const lab::fit::ErrorBreakdown b = lab::fit::error_breakdown(rougher, pairs);
    CHECK(b.total == Approx(lab::fit::fit_error(rougher, pairs)).epsilon(1e-9));
    int counted = 0;
    for (const lab::fit::IncidenceBand& band : b.incidence) counted += band.pairs;
    CHECK(counted == int(pairs.size()));

    // a short search: every start is kept and reported, and the best is no worse than the box's
    // centre, where the first start begins
    lab::fit::FitOptions options;
    options.starts = 2;
    options.max_evaluations = 40;
    const lab::fit::FitResult r = lab::fit::fit_material(pairs, space, options);
    REQUIRE(r.starts.size() == 2);
    std::vector<double> centre;
    for (const lab::fit::FitParameter& p : lab::fit::fit_parameters(space)) centre.push_back(0.5 * (p.min + p.max));
    CHECK(r.error <= lab::fit::fit_error(lab::fit::material_from_parameters(space, centre), pairs));
    CHECK(r.evaluations <= 80);
    const nlohmann::json report = lab::fit::fit_report("t.binary", space, r, lab::fit::error_breakdown(r.material, pairs));
    CHECK(report.at("starts").size() == 2);
    CHECK(report.at("error").at("incidence").size() == 9);
    CHECK(report.at("parameters").at("roughness").get<double>() == Approx(r.material.roughness).epsilon(1e-6));
    // the fitted material as the command writes it: a preset that loads back to the same error
    brdf::Preset preset;
    preset.name = "fitted";
    preset.material = r.material;
    const std::string path = (fs::temp_directory_path() / "dtoadq_fit_preset.json").string();
    brdf::save_preset(preset, path);
    const brdf::Preset loaded = brdf::load_preset(path);
    fs::remove(path);
    CHECK(lab::fit::fit_error(loaded.material, pairs) == Approx(r.error).epsilon(1e-5));
}

TEST_CASE("fit: --lobes takes the reflection lobes and names what it refuses", "[fit]") {
    lab::fit::FitSpace s;
    lab::fit::parse_lobes("diffuse,glossy,retroreflection", &s);
    CHECK((s.diffuse && s.glossy && s.retroreflection && !s.subsurface));
    CHECK_THROWS_WITH(lab::fit::parse_lobes("diffuse,specular", &s), Catch::Contains("--lobes: \"specular\" cannot be fitted"));
    CHECK_THROWS_WITH(lab::fit::parse_lobes("glosy", &s), Catch::Contains("unknown lobe \"glosy\""));
    CHECK_THROWS_WITH(lab::fit::parse_lobes("glossy,subsurface", &s), Catch::Contains("add diffuse"));
    CHECK_THROWS_WITH(lab::fit::parse_lobes("", &s), Catch::Contains("needs diffuse or glossy"));
    // every fitted parameter lies inside the parameter table's range
    s = lab::fit::FitSpace{};
    s.distribution = BRDF_DISTRIBUTION_HYPER_CAUCHY;
    s.anisotropic = true;
    for (const lab::fit::FitParameter& p : lab::fit::fit_parameters(s)) CHECK(p.min < p.max);
}

TEST_CASE("fit chart: the measured slice of a Lambert table is albedo / pi cos, and the chart is a PNG", "[fit][python]") {
    Material lambert = brdf::default_material();
    for (int k = 0; k < 3; ++k) lambert.albedo[k] = 0.5f;
    lambert.weight_diffuse = 1.0f;
    lambert.weight_glossy = lambert.weight_specular = lambert.weight_transmission = 0.0f;
    const brdf::MeasuredTable table = brdf::tabulate_merl([&](float3 wo, float3 wi) { return brdf::bsdf_eval(&lambert, wo, wi); }, "lambert");
    // the chart's measured curve: the lobe plot's slice of merl_eval, in closed form for Lambert
    const auto slice = lab::analysis::plane_slice([&table](float3 wi, float3 wo) { return brdf::merl_eval(table.rgb.data(), wo, wi); },
                                               40.0f, 0.0f, 5.0f, false);
    REQUIRE(slice.size() == 37u);
    for (const lab::analysis::PlaneSample& s : slice)
        CHECK(s.value == Approx(0.5 / M_PI * std::cos(s.angle_deg * M_PI / 180.0)).margin(1e-6));

    brdf::Preset fitted;
    fitted.name = "lambert_fit";
    fitted.material = lambert;
    lab::plots::FitChartData data;
    data.error_map = lab::fit::error_map(table, lambert, 30).error;
    const std::string png = (fs::temp_directory_path() / "dtoadq_fit_chart.png").string();
    lab::plots::write_fit_chart(table, fitted, data, png);
    std::ifstream in(png, std::ios::binary);
    char signature[4] = {};
    in.read(signature, 4);
    CHECK(std::string(signature + 1, 3) == "PNG");
    CHECK(fs::file_size(png) > 30000u);
    fs::remove(png);
    // the map is zero where the model is the table, and blank (NaN) only below the horizon
    int blank = 0;
    for (double e : data.error_map) {
        if (std::isnan(e)) ++blank;
        else CHECK(e == 0.0);
    }
    CHECK(blank > 0);
    CHECK(blank < int(data.error_map.size()) / 2);
}
