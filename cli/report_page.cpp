#include "cli/report_page.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "brdf/host/parameters.hpp"
#include "cli/build_info.hpp"
#include "common/luminance.hpp"

namespace lab::cli {

namespace fs = std::filesystem;
using report::Cell;
using report::CellKind;
using report::number_cell;
using report::text_cell;

namespace {

Cell verdict(bool passed) { return {passed ? "PASS" : "FAIL", passed ? CellKind::pass : CellKind::fail}; }

float luminance_of(const brdf::float3& c) { return luminance(c.x, c.y, c.z); }

// Writes the table's CSV as `name` in `folder` and links it from the table.
report::Table with_csv(report::Table table, const fs::path& folder, const std::string& name) {
    report::write_csv(table, (folder / name).string());
    table.csv = name;
    return table;
}

std::string degrees(float deg) { return report::number_text(deg, 3) + "°"; }

std::vector<Cell> render_row(const ReportRender& r) {
    const render::RenderStatistics& s = r.stats;
    const double rays_per_path = s.paths > 0 ? double(s.rays) / double(s.paths) : 0.0;
    return {text_cell(r.name), number_cell(s.samples_per_pixel), number_cell(s.render_seconds, 3), number_cell(s.paths_per_second(), 3), number_cell(rays_per_path, 3),
            number_cell(double(s.nonfinite_samples))};
}

const std::vector<std::string> kRenderHeader = {"what", "samples/pixel", "seconds", "paths/s", "rays/path", "non-finite paths"};

// The albedo point nearest `theta_deg`.
const analysis::AlbedoPoint& point_near(const std::vector<analysis::AlbedoPoint>& curve, float theta_deg) {
    return *std::min_element(curve.begin(), curve.end(), [theta_deg](const analysis::AlbedoPoint& a, const analysis::AlbedoPoint& b) {
        return std::fabs(a.theta_deg - theta_deg) < std::fabs(b.theta_deg - theta_deg);
    });
}

}  // namespace

report::Section previews_section(const ReportPreviews& previews, const fs::path& folder) {
    report::Section s{"presets", "Presets on the test model",
                      "Every preset path-traced on the test model (a shader ball on a ground plane) under " + previews.environment + ": " +
                      std::to_string(previews.spp) + " samples per pixel at " + previews.size +
                      ", the path tracer with multiple importance sampling of the BSDF and the environment, ACES tone map. Each render's EXR "
                      "(linear radiance, with its settings in the metadata) lies beside its PNG.", {}};
    if (previews.sheet.empty()) return s;
    report::Table table;
    table.header = kRenderHeader;
    table.header.insert(table.header.begin() + 1, "model");
    for (const auto& [preset, render] : previews.renders) {
        std::vector<Cell> row = render_row(render);
        row.insert(row.begin() + 1, text_cell(brdf::model_name(preset.material.model)));
        table.rows.push_back(std::move(row));
    }
    s.figures.push_back({previews.sheet, "contact sheet of the preset previews",
                         "The presets side by side, each titled with its name. The table gives each render's samples per pixel, the seconds "
                         "its samples took on the device (kernel builds excluded), paths per second, rays marched per path, and the paths "
                         "left out for a non-finite value (0 expected).",
                         with_csv(std::move(table), folder, "previews.csv")});
    for (const auto& [preset, render] : previews.renders) {
        report::Figure f;
        f.image = render.image;
        f.alt = "preview of " + preset.name;
        f.caption = preset.name + (preset.description.empty() ? "" : ": " + preset.description);
        f.numbers.header = {"parameter", "value"};
        const brdf::Material& m = preset.material;
        f.numbers.rows = {{text_cell("model"), text_cell(brdf::model_name(m.model))},
                          {text_cell("albedo (RGB)"), text_cell(report::number_text(m.albedo[0], 3) + ", " + report::number_text(m.albedo[1], 3) + ", " +
                                                      report::number_text(m.albedo[2], 3))},
                          {text_cell("roughness"), number_cell(m.roughness, 3)},
                          {text_cell("metallic"), number_cell(m.metallic, 3)},
                          {text_cell("anisotropic"), number_cell(m.anisotropic, 3)},
                          {text_cell("transmission weight"), number_cell(m.weight_transmission, 3)}};
        s.figures.push_back(std::move(f));
    }
    return s;
}

report::Section lobes_section(const std::vector<ReportLobes>& lobes, const fs::path& folder) {
    report::Section s{"lobes", "Lobes",
                      "The BSDF of each group of presets for one incident direction: the luminance of f(wi, wo) |cos θo| in the plane of "
                      "incidence (polar plot; positive angles towards the mirror side, below 90° under the surface for materials that "
                      "transmit) and over the sphere of outgoing directions (3D). The radius is logarithmic when the materials' peaks differ "
                      "by more than 20×. Delta lobes (smooth mirrors and glass) cannot be drawn as functions: the tables give their weight, "
                      "the share of the incident light each carries.", {}};
    for (const ReportLobes& l : lobes) {
        report::Table table;
        table.header = {"material", "peak of f |cos θo|", "at angle", "delta lobes", "their weight (luminance)"};
        for (const analysis::LobeData& d : l.lobes) {
            auto peak = std::max_element(d.plane.begin(), d.plane.end(),
                                         [](const analysis::PlaneSample& a, const analysis::PlaneSample& b) { return a.value < b.value; });
            double delta_weight = 0.0;
            for (const analysis::DeltaLobe& delta : d.deltas) delta_weight += luminance_of(delta.weight);
            const bool has_peak = peak != d.plane.end() && peak->value > 0.0f;  // not a material of delta lobes only
            table.rows.push_back({text_cell(d.material), has_peak ? number_cell(peak->value, 4) : text_cell("none"),
                                  has_peak ? text_cell(degrees(peak->angle_deg)) : text_cell("-"), number_cell(double(d.deltas.size())),
                                  number_cell(delta_weight, 4)});
        }
        const std::string stem = fs::path(l.image).stem().string();
        s.figures.push_back({l.image, "lobes of " + l.group + " at " + degrees(l.theta_in_deg),
                             l.group + ", incident at θi = " + degrees(l.theta_in_deg) +
                                 ", φi = 0°. The table gives each material's peak in the plane of incidence (sampled every 0.25°) and "
                                 "where it lies.",
                             with_csv(std::move(table), folder, stem + ".csv")});
    }
    return s;
}

report::Section albedo_section(const std::vector<brdf::Preset>& presets, const std::vector<std::vector<analysis::AlbedoPoint>>& curves,
                               const analysis::AlbedoCurveOptions& options, const std::string& image, const std::string& csv) {
    report::Section s{"albedo", "Directional albedo", "", {}};
    const std::vector<float> angles{0.0f, 30.0f, 60.0f, 80.0f};
    report::Table table;
    table.header = {"material"};
    for (float a : angles) table.header.push_back("albedo at " + degrees(a));
    table.header.push_back("largest standard error");
    for (size_t i = 0; i < presets.size(); ++i) {
        std::vector<Cell> row{text_cell(presets[i].name)};
        double se = 0.0;
        for (float a : angles) {
            const analysis::AlbedoPoint& p = point_near(curves[i], a);
            const brdf::float3& v = p.estimate.value;
            row.push_back(number_cell((v.x + v.y + v.z) / 3.0, 4));
            se = std::max({se, double(p.estimate.std_error.x), double(p.estimate.std_error.y), double(p.estimate.std_error.z)});
        }
        row.push_back(number_cell(se, 2));
        table.rows.push_back(std::move(row));
    }
    table.csv = csv;  // every angle and channel, with standard errors
    s.figures.push_back({image, "directional albedo of every preset against the incident angle",
                         "The share of light from one incident direction that the material reflects or transmits, per channel, against the "
                         "incident angle (" + std::to_string(options.angles) + " angles, φi = " + degrees(options.phi_deg) +
                             "), each estimated with the BSDF's own sampler on a stratified grid of " + std::to_string(options.strata) + "² "
                             "samples. Above 1 a material creates energy. The table gives the mean of RGB at four angles; the CSV holds every "
                             "angle and channel with its standard error.",
                         std::move(table)});
    return s;
}

report::Section validation_section(const std::vector<validation::MaterialValidation>& results, const validation::ValidationOptions& options,
                                   const fs::path& folder) {
    report::Section s{"validation", "Validation",
                      "The physical checks of every preset. The 2017 model (dtoadq2017) is expected to fail them: it is kept to show where "
                      "the write-up's formulas break; a lab-model preset that fails is a defect, and the report exits with an error.", {}};
    report::Table table;
    table.header = {"material", "model", "chi-square directions", "smallest p", "level per direction", "sampler", "reciprocity error",
                    "tolerance", "reciprocity", "largest albedo", "at θ", "at φ", "energy", "result"};
    for (const validation::MaterialValidation& v : results) {
        table.rows.push_back({text_cell(v.name), text_cell(brdf::model_name(v.model)), number_cell(v.chi_square_tests),
                              v.continuous ? number_cell(v.smallest_p_value, 3) : text_cell("delta only"), number_cell(v.alpha, 3),
                              verdict(v.chi_square_passed()), number_cell(v.reciprocity_error, 2), number_cell(v.reciprocity_tolerance, 2),
                              verdict(v.reciprocity_passed()), number_cell(v.albedo.albedo, 5), text_cell(degrees(v.albedo.theta_deg)),
                              text_cell(degrees(v.albedo.phi_deg)), verdict(v.energy_passed()), verdict(v.passed())});
    }
    s.figures.push_back({"", "",
                         "Sampler: a chi-square test of the importance sampler's histogram against its pdf at several incident "
                         "directions (" + std::to_string(options.chi_square_samples) + " samples each), at a family-wise level of " +
                             report::number_text(options.significance, 2) +
                             " (Šidák). Reciprocity: the largest relative difference between f(wi, wo) and f(wo, wi) over " +
                             std::to_string(options.reciprocity_pairs) +
                             " random pairs. Energy: the white furnace, the largest directional albedo over incident directions, which "
                             "may not exceed 1 by more than its estimate's noise.",
                         with_csv(std::move(table), folder, "validation.csv")});
    return s;
}

report::Section scene_section(const std::vector<ReportScene>& scenes, const fs::path& folder) {
    report::Section s{"scene", "Scene renders", "", {}};
    report::Table all;
    all.header = kRenderHeader;
    for (const ReportScene& scene : scenes) all.rows.push_back(render_row(scene.render));
    all = with_csv(std::move(all), folder, "scene.csv");
    for (const ReportScene& scene : scenes) {
        report::Table table = all;
        table.rows = {render_row(scene.render)};
        s.figures.push_back({scene.render.image, "render of " + scene.render.name,
                             scene.render.name + " rendered by " + scene.integrator + " at " + scene.size + ", " +
                                 std::to_string(scene.render.stats.samples_per_pixel) +
                                 " samples per pixel, ACES tone map; its EXR lies beside the PNG. Seconds are the device's time for the "
                                 "samples (the kernel build excluded).",
                             table});
    }
    return s;
}

report::Section speed_section(const StudyResults& study, const StudyBudget& budget, const std::string& size, const fs::path& folder) {
    report::Section s{"speed", "Speed against accuracy",
                      "Each method renders for the same time on this machine, in this run, and its image is compared with a reference after "
                      "every launch: the relative RMSE (each channel's RMSE over the reference's mean, averaged) against render time, on "
                      "log-log axes, with a line of slope −1/2 (the Monte Carlo rate: the error of an unbiased method falls as 1/√time) "
                      "for comparison. A method that is better at equal time lies lower; one whose line flattens above the others is "
                      "limited by the reference's own noise or is biased. Budget '" + budget.name + "': " + report::number_text(budget.run_seconds, 3) +
                      " s per run, references of " + report::number_text(budget.reference_seconds, 3) + " s, at " + size +
                      " (report --full renders longer references and runs). The references are kept in references/ and reused by the "
                      "next report with the same inputs, settings, budget and build.", {}};
    for (const StudyComparison& c : study.comparisons) {
        report::Table table;
        table.header = {"run", "samples/pixel", "paths/s", "relative RMSE", "relative RMSE × √seconds", "against " + c.baseline + " at equal time"};
        double baseline_error = 0.0;
        for (const report::EqualTimeResult& r : c.results)
            if (r.series.name == c.baseline) baseline_error = r.final_rmse();
        for (const report::EqualTimeResult& r : c.results) {
            const double t = r.series.seconds.empty() ? 0.0 : r.series.seconds.back();
            table.rows.push_back({text_cell(r.series.name), number_cell(r.stats.samples_per_pixel), number_cell(r.stats.paths_per_second(), 3),
                                  number_cell(r.final_rmse(), 3), number_cell(r.final_rmse() * std::sqrt(t), 3),
                                  baseline_error > 0.0 ? text_cell(report::number_text(r.final_rmse() / baseline_error, 3) + "×") : text_cell("-")});
        }
        const std::string stem = fs::path(c.image).stem().string();
        s.figures.push_back({c.image, "relative RMSE against render time for " + c.subject,
                             c.subject + ": " + c.varies + ". The reference is " + c.reference_description + ", " +
                                 std::to_string(c.reference_spp) + " samples per pixel" + (c.reference_reused ? " (reused)" : "") +
                                 "; its own relative noise, about " + report::number_text(c.reference_relative_noise, 2) +
                                 ", is the floor under every line. The chart's points are in " + c.csv + ".",
                             with_csv(std::move(table), folder, stem + "_table.csv")});
    }
    if (study.march) {
        const MarchSettingsStudy& m = *study.march;
        report::Table table;
        table.header = {"setting", "ms per sample", "error it causes", "noise level", "lost rays"};
        for (const MarchSetting& setting : m.settings)
            table.rows.push_back({text_cell(setting.name), number_cell(1000.0 * setting.seconds_per_sample, 3), number_cell(setting.error, 3),
                                  number_cell(setting.noise, 3), number_cell(setting.lost_rays, 2)});
        const std::string stem = fs::path(m.image).stem().string();
        s.figures.push_back({m.image, "time per sample against the error of each sphere-tracing setting on " + m.scene,
                             m.scene + ": each sphere-tracing setting (ω the over-relaxation, and the normal estimator; analytic falls "
                             "back to tetrahedral where the field has no analytic gradient, as in a blend) against the conservative one, " +
                                 m.baseline_description + ". Every setting renders the same samples, " + std::to_string(m.samples_per_pixel) +
                                 " per pixel in each of two halves drawn with two seeds; the error a setting causes is estimated from the "
                                 "product of its two halves' differences from the conservative setting's, whose expectation is the squared "
                                 "error whatever the noise (relative: over the image's mean, per channel, averaged). Errors inside the grey "
                                 "band, twice the estimate's standard error, cannot be told from noise at this budget. Lost rays: the share "
                                 "of marches that ran out of steps. The chart's points are in " + m.csv + ".",
                             with_csv(std::move(table), folder, stem + "_table.csv")});
    }
    return s;
}

report::Section atlas_section(const std::vector<report::AtlasEntry>& entries, const fs::path& folder) {
    report::Section s{"atlas", "Stability atlas",
                      "Where each method fails: every entry charts one quantity over the parameters where methods break down, "
                      "with its finding in the first line of the caption.", {}};
    for (const report::AtlasEntry& e : entries) {
        const std::string stem = fs::path(e.image).stem().string();
        s.figures.push_back({e.image, e.title, e.finding + " " + e.how + " The chart's numbers are in " + e.csv + ".",
                             with_csv(e.table, folder, stem + "_table.csv")});
    }
    return s;
}

report::Section machine_section(const std::string& device, const std::vector<std::pair<std::string, double>>& stage_seconds,
                                const fs::path& folder) {
    report::Section s{"machine", "Machine and versions", "", {}};
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char date[64];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now));
    report::Table about;
    about.header = {"what", "value"};
    about.rows = {{text_cell("device of the renders"), text_cell(device.empty() ? "none (no render in this report)" : device)},
                  {text_cell("dtoadq commit"), text_cell(kBuildCommit)},
                  {text_cell("compiler"), text_cell(kBuildCompiler)},
                  {text_cell("report written"), text_cell(date)}};
    s.figures.push_back({"", "", "What the figures above were measured on.", with_csv(std::move(about), folder, "machine.csv")});
    report::Table times;
    times.header = {"stage", "seconds"};
    double total = 0.0;
    for (const auto& [stage, seconds] : stage_seconds) {
        times.rows.push_back({text_cell(stage), number_cell(seconds, 3)});
        total += seconds;
    }
    times.rows.push_back({text_cell("all"), number_cell(total, 3)});
    s.figures.push_back({"", "", "The wall-clock seconds each stage of the report took, kernel builds included.",
                         with_csv(std::move(times), folder, "timings.csv")});
    return s;
}

}  // namespace lab::cli
