// Lobe plots and albedo charts: the data against closed forms, the CSV tables, and real PNGs.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/child_process.hpp"
#include "analysis/albedo_curve.hpp"
#include "analysis/lobe_data.hpp"
#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "plots/albedo_chart.hpp"
#include "plots/lobe_plot.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

// default_material() is a pure Lambert lobe of albedo 0.8
brdf::Preset lambert() {
    brdf::Preset p;
    p.name = "lambert, white-ish";  // a comma, so the CSV has to quote it
    p.material = brdf::default_material();
    return p;
}

brdf::Preset smooth_glass() {
    brdf::Preset p;
    p.name = "glass";
    p.material = brdf::default_material();
    p.material.albedo[0] = p.material.albedo[1] = p.material.albedo[2] = 1.0f;
    p.material.roughness = 0.0f;
    p.material.weight_diffuse = 0.0f;
    p.material.weight_transmission = 1.0f;
    p.material.ior = 1.5f;
    return p;
}

// Unpolarised Fresnel reflectance of a dielectric from outside, written out here as the reference.
double fresnel_reference(double cos_i, double eta) {
    double sin_t = std::sqrt(1.0 - cos_i * cos_i) / eta;
    double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

std::vector<std::string> lines_of(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

bool is_png(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[8] = {};
    in.read(magic, 8);
    return in && std::string(magic, 8) == "\x89PNG\r\n\x1a\n";
}

struct ScratchFolder {
    lab::TempFolder folder{"test"};
    fs::path operator/(const std::string& name) const { return folder.path() / name; }
};

}  // namespace

TEST_CASE("a Lambert lobe is albedo / pi over the whole upper hemisphere", "[plots]") {
    lab::analysis::LobeData d = lab::analysis::compute_lobe(lambert(), 30.0f, 0.0f, {2.0f, 0.5f});
    CHECK_FALSE(d.transmits);
    CHECK(d.deltas.empty());
    CHECK(d.theta_count == 46);  // 0, 2, ..., 90
    CHECK(d.phi_count == 90);    // 0, 4, ..., 356
    REQUIRE(d.grid.size() == 46u * 90u);
    const double f = 0.8 / kPi;
    for (const lab::analysis::LobeSample& s : d.grid) {
        if (s.theta_deg >= 90.0f) continue;  // the horizon itself is a boundary case of the BSDF
        INFO("theta " << s.theta_deg << " phi " << s.phi_deg);
        REQUIRE(s.f.x == Approx(f).epsilon(1e-5));
        REQUIRE(s.f.z == Approx(f).epsilon(1e-5));
        REQUIRE(s.pdf == Approx(std::cos(s.theta_deg * kPi / 180.0) / kPi).margin(1e-6));
    }
    // the slice: luminance of a grey f times |cos|, over -90..90 only
    REQUIRE(d.plane.size() == 361u);
    CHECK(d.plane.front().angle_deg == -90.0f);
    CHECK(d.plane.back().angle_deg == 90.0f);
    for (const lab::analysis::PlaneSample& s : d.plane)
        if (std::fabs(s.angle_deg) < 90.0f) REQUIRE(s.value == Approx(f * std::cos(s.angle_deg * kPi / 180.0)).margin(1e-6));
}

TEST_CASE("the plane-of-incidence slice follows the grid's directions", "[plots]") {
    brdf::Preset gold = brdf::load_preset("presets/gold.json");
    lab::analysis::LobeData d = lab::analysis::compute_lobe(gold, 30.0f, 0.0f, {1.0f, 0.5f});
    // slice angle +30 is the mirror direction (theta 30, phi 180); -30 is the incident side (phi 0)
    auto grid_value = [&](int theta, int phi) {
        const lab::analysis::LobeSample& s = d.grid[size_t(theta) * size_t(d.phi_count) + size_t(phi / 2)];
        REQUIRE(s.theta_deg == float(theta));
        REQUIRE(s.phi_deg == float(phi));
        return 0.2126 * s.f.x + 0.7152 * s.f.y + 0.0722 * s.f.z;
    };
    auto slice_value = [&](float angle) {
        for (const lab::analysis::PlaneSample& s : d.plane)
            if (s.angle_deg == angle) return double(s.value);
        FAIL("no slice sample at " << angle);
        return 0.0;
    };
    const double c30 = std::cos(30.0 * kPi / 180.0);
    CHECK(slice_value(30.0f) == Approx(grid_value(30, 180) * c30).epsilon(1e-4));
    CHECK(slice_value(-30.0f) == Approx(grid_value(30, 0) * c30).epsilon(1e-4));
    CHECK(slice_value(60.0f) == Approx(grid_value(60, 180) * 0.5).epsilon(1e-4));
    // and a glossy conductor peaks near the mirror direction
    const lab::analysis::PlaneSample* peak = &d.plane.front();
    for (const lab::analysis::PlaneSample& s : d.plane)
        if (s.value > peak->value) peak = &s;
    CHECK(peak->angle_deg > 25.0f);
    CHECK(peak->angle_deg < 45.0f);
}

TEST_CASE("the grid follows `brdf eval`: the incident direction is the BSDF's first argument", "[plots]") {
    brdf::Preset glass = brdf::load_preset("presets/frosted_glass.json");
    lab::analysis::LobeData d = lab::analysis::compute_lobe(glass, 60.0f, 0.0f, {2.0f, 0.5f});
    REQUIRE(d.transmits);
    const double to_rad = kPi / 180.0;
    brdf::float3 wi(float(std::sin(60.0 * to_rad)), 0.0f, float(std::cos(60.0 * to_rad)));
    int checked = 0;
    for (const lab::analysis::LobeSample& s : d.grid) {
        if (s.phi_deg != 180.0f || (s.theta_deg != 20.0f && s.theta_deg != 150.0f)) continue;
        double t = s.theta_deg * to_rad, p = s.phi_deg * to_rad;
        brdf::float3 wo(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
        INFO("theta_o " << s.theta_deg);
        CHECK(s.f.y == Approx(brdf::bsdf_eval(&glass.material, wi, wo).y).epsilon(1e-4));
        CHECK(s.pdf == Approx(brdf::bsdf_pdf(&glass.material, wi, wo)).epsilon(1e-4));
        // the other order gives another density, so the check above does tell them apart
        CHECK(std::fabs(s.pdf - brdf::bsdf_pdf(&glass.material, wo, wi)) > 1e-3 * s.pdf);
        ++checked;
    }
    CHECK(checked == 2);
}

TEST_CASE("smooth glass has two delta lobes: Fresnel reflection and Snell refraction", "[plots]") {
    for (float theta_in : {0.0f, 45.0f, 80.0f}) {
        INFO("theta_in " << theta_in);
        lab::analysis::LobeData d = lab::analysis::compute_lobe(smooth_glass(), theta_in, 20.0f, {2.0f, 0.5f});
        CHECK(d.transmits);
        CHECK(d.grid.size() == 91u * 90u);  // the lower hemisphere too
        CHECK(d.plane.size() == 721u);
        for (const lab::analysis::LobeSample& s : d.grid) REQUIRE(s.f.y == 0.0f);  // a delta-only BSDF is zero everywhere
        REQUIRE(d.deltas.size() == 2u);
        const lab::analysis::DeltaLobe& reflection = d.deltas[0].transmission ? d.deltas[1] : d.deltas[0];
        const lab::analysis::DeltaLobe& refraction = d.deltas[0].transmission ? d.deltas[0] : d.deltas[1];
        REQUIRE(refraction.transmission);
        REQUIRE_FALSE(reflection.transmission);
        double fr = fresnel_reference(std::cos(theta_in * kPi / 180.0), 1.5);
        CHECK(reflection.weight.y == Approx(fr).margin(2e-3));
        CHECK(refraction.weight.y == Approx(1.0 - fr).margin(2e-3));
        CHECK(reflection.weight.y + refraction.weight.y == Approx(1.0).margin(1e-4));
        CHECK(reflection.theta_deg == Approx(theta_in).margin(1e-3));
        CHECK(reflection.plane_angle_deg == Approx(theta_in).margin(1e-3));
        double theta_t = std::asin(std::sin(theta_in * kPi / 180.0) / 1.5) * 180.0 / kPi;
        CHECK(refraction.theta_deg == Approx(180.0 - theta_t).margin(1e-3));
        CHECK(refraction.plane_angle_deg == Approx(180.0 - theta_t).margin(1e-3));
        CHECK(reflection.in_plane);
        CHECK(refraction.in_plane);
        if (theta_in > 0.0f) CHECK(reflection.phi_deg == Approx(200.0).margin(1e-3));
    }
}

TEST_CASE("delta lobes sharing a direction add up: a mirror lobe beside Lambert", "[plots]") {
    brdf::Material m = brdf::default_material();
    m.weight_diffuse = 0.5f;
    m.weight_specular = 0.5f;
    m.fresnel = 0.04f;
    std::vector<lab::analysis::DeltaLobe> deltas = lab::analysis::find_delta_lobes(m, 0.0f, 0.0f);
    REQUIRE(deltas.size() == 1u);
    CHECK_FALSE(deltas[0].transmission);
    CHECK(deltas[0].weight.x == Approx(0.5 * 0.04).margin(2e-4));  // lobe weight x Schlick at normal incidence
    CHECK(deltas[0].theta_deg == Approx(0.0).margin(1e-3));
}

TEST_CASE("the lobe CSV has one row per material and grid direction", "[plots]") {
    ScratchFolder scratch;
    fs::path csv = scratch / "lobe.csv";
    lab::plots::write_lobe_csv({lambert(), smooth_glass()}, 40.0f, 0.0f, csv.string(), 3.0f);
    std::vector<std::string> lines = lines_of(csv);
    REQUIRE(lines.size() == 1u + 31u * 60u + 61u * 60u);  // Lambert to 90 degrees, glass to 180
    CHECK(lines[0] == "material,theta_o,phi_o,f_r,f_g,f_b,pdf");
    std::ostringstream first;
    first << "\"lambert, white-ish\",0,0,";
    CHECK(lines[1].rfind(first.str(), 0) == 0);
    std::istringstream row(lines[1].substr(first.str().size()));
    double f_r, pdf;
    char comma;
    row >> f_r >> comma;
    row.ignore(1000, ',');
    row.ignore(1000, ',');
    row >> pdf;
    CHECK(f_r == Approx(0.8 / kPi).epsilon(1e-6));
    CHECK(pdf == Approx(1.0 / kPi).epsilon(1e-6));
    CHECK(lines.back().rfind("glass,180,354,0,0,0,0", 0) == 0);
}

TEST_CASE("CSV numbers: a float's 7 digits, and non-finite values as Python reads them", "[plots]") {
    CHECK(lab::plots::csv_number(0.1f) == "0.1");
    CHECK(lab::plots::csv_number(1.0 / 3.0) == "0.3333333");
    CHECK(lab::plots::csv_number(std::nan("")) == "nan");
    CHECK(lab::plots::csv_number(INFINITY) == "inf");
    CHECK(lab::plots::csv_number(-INFINITY) == "-inf");
}

TEST_CASE("a bad lobe resolution or output path is refused before any work", "[plots]") {
    CHECK_THROWS_AS(lab::analysis::compute_lobe(lambert(), 10.0f, 0.0f, {7.0f, 0.5f}), std::invalid_argument);
    try {
        lab::plots::write_lobe_plot({lambert()}, 10.0f, 0.0f, "/nonexistent-folder/lobe.png", "");
        FAIL("no error for an unwritable path");
    } catch (const lab::InputError& e) {
        CHECK(std::string(e.what()) == "/nonexistent-folder/lobe.png: cannot write: folder /nonexistent-folder does not exist");
    }
    ScratchFolder scratch;
    CHECK_THROWS_AS(lab::plots::write_albedo_chart({lambert()}, scratch.folder.path().string(), ""), lab::InputError);
}

TEST_CASE("the Python with matplotlib is the first candidate that imports it", "[plots]") {
    CHECK(lab::plots::find_matplotlib_python({"/nonexistent/python3", "/usr/bin/python3"}) == "/usr/bin/python3");
    try {
        lab::plots::find_matplotlib_python({"/nonexistent/python3", "/bin/false"});
        FAIL("found matplotlib in no Python at all");
    } catch (const std::runtime_error& e) {
        CHECK(std::string(e.what()).rfind("matplotlib not found: install python3-matplotlib", 0) == 0);
    }
}

TEST_CASE("albedo curves: Lambert is its albedo at every angle, smooth glass is 1", "[plots]") {
    lab::analysis::AlbedoCurveOptions options;
    options.angles = 10;
    options.strata = 16;
    std::vector<lab::analysis::AlbedoPoint> curve = lab::analysis::albedo_curve(lambert().material, options);
    REQUIRE(curve.size() == 10u);
    CHECK(curve.front().theta_deg == 0.0f);
    CHECK(curve[1].theta_deg == 10.0f);
    CHECK(curve.back().theta_deg == 90.0f);
    for (const lab::analysis::AlbedoPoint& p : curve) CHECK(p.estimate.value.x == Approx(0.8).epsilon(1e-5));
    for (const lab::analysis::AlbedoPoint& p : lab::analysis::albedo_curve(smooth_glass().material, options))
        if (p.theta_deg < 90.0f) CHECK(p.estimate.value.y == Approx(1.0).epsilon(1e-5));
}

TEST_CASE("lobe plots and albedo charts are written as PNG with their CSV", "[plots][python]") {
    ScratchFolder scratch;
    std::vector<brdf::Preset> presets = {lambert(), brdf::load_preset("presets/frosted_glass.json"), smooth_glass()};
    lab::plots::LobePlotOptions lobe_options;
    lobe_options.csv_theta_step_deg = 5.0f;
    lab::plots::write_lobe_plot(presets, 45.0f, 0.0f, (scratch / "lobe.png").string(), (scratch / "lobe.csv").string(), lobe_options);
    CHECK(is_png(scratch / "lobe.png"));
    CHECK(fs::file_size(scratch / "lobe.png") > 50000u);
    CHECK(lines_of(scratch / "lobe.csv").size() == 1u + 19u * 36u + 2u * 37u * 36u);

    lab::analysis::AlbedoCurveOptions albedo_options;
    albedo_options.angles = 7;
    albedo_options.strata = 8;
    lab::plots::write_albedo_chart(presets, (scratch / "albedo.png").string(), (scratch / "albedo.csv").string(), albedo_options);
    CHECK(is_png(scratch / "albedo.png"));
    CHECK(fs::file_size(scratch / "albedo.png") > 30000u);
    std::vector<std::string> rows = lines_of(scratch / "albedo.csv");
    REQUIRE(rows.size() == 1u + 3u * 7u);
    CHECK(rows[0] == "material,theta,a_r,a_g,a_b,se_r,se_g,se_b");
    CHECK(rows[1] == "\"lambert, white-ish\",0,0.8,0.8,0.8,0,0,0");
}
