// The sections of `dtoadq report`'s page (report/html_page.hpp) from what the report computed:
// the previews' and the scene's render statistics, the lobes, the albedo curves, the validation
// results and the time each stage took. Each section writes the CSV its tables link to.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "analysis/albedo_curve.hpp"
#include "analysis/lobe_data.hpp"
#include "report/stability_atlas.hpp"
#include "cli/report_study.hpp"
#include "brdf/host/preset.hpp"
#include "render/renderer.hpp"
#include "report/html_page.hpp"
#include "validation/report.hpp"

namespace lab::cli {

struct ReportRender {
    std::string name;   // the preset, or the scene file
    std::string image;  // its PNG, relative to the report folder
    render::RenderStatistics stats;
};

struct ReportPreviews {
    std::string environment;  // file name
    std::string size;         // WxH
    int spp = 0;
    std::string sheet;        // the contact sheet's PNG; empty when no preview was rendered
    std::vector<std::pair<brdf::Preset, ReportRender>> renders;
};

struct ReportLobes {
    std::string group;   // its title
    float theta_in_deg = 0.0f;
    std::string image;
    std::vector<analysis::LobeData> lobes;  // one per material of the group
};

struct ReportScene {
    std::string integrator;
    std::string size;
    ReportRender render;
};

// Every section writes its CSV into `folder` (names ending in .csv, listed in the section's tables).
report::Section previews_section(const ReportPreviews& previews, const std::filesystem::path& folder);
report::Section lobes_section(const std::vector<ReportLobes>& lobes, const std::filesystem::path& folder);
report::Section albedo_section(const std::vector<brdf::Preset>& presets, const std::vector<std::vector<analysis::AlbedoPoint>>& curves,
                               const analysis::AlbedoCurveOptions& options, const std::string& image, const std::string& csv);
report::Section validation_section(const std::vector<validation::MaterialValidation>& results, const validation::ValidationOptions& options,
                                   const std::filesystem::path& folder);
// The scene renders, a figure each; writes scene.csv (one row per render).
report::Section scene_section(const std::vector<ReportScene>& scenes, const std::filesystem::path& folder);
// The speed-against-accuracy study: a chart per preset or scene, with the runs' figures; writes their tables' CSV.
report::Section speed_section(const StudyResults& study, const StudyBudget& budget, const std::string& size, const std::filesystem::path& folder);
// The stability atlas: an entry per chart, its finding first; writes its tables' CSV.
report::Section atlas_section(const std::vector<report::AtlasEntry>& entries, const std::filesystem::path& folder);
// The device the renders ran on, the build, the date, and the seconds each stage took.
report::Section machine_section(const std::string& device, const std::vector<std::pair<std::string, double>>& stage_seconds,
                                const std::filesystem::path& folder);

}  // namespace lab::cli
