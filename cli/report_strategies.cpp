#include "cli/report_strategies.hpp"

#include <cstdio>
#include <optional>

#include "cli/strategy_images.hpp"
#include "film/image_output.hpp"
#include "plots/preview_sheet.hpp"
#include "report/html_page.hpp"

namespace lab::cli {

namespace fs = std::filesystem;

StrategyAtlas write_strategy_atlas(const StrategyAtlasOptions& options, const fs::path& folder, std::string* device) {
    StrategyAtlas atlas;
    atlas.options = options;
    atlas.image = "atlas_strategies.png";
    atlas.csv = "atlas_strategies.csv";
    std::optional<opencl::Runtime> runtime;
    std::vector<plots::SheetImage> sheet;
    report::Table csv;
    csv.header = {"scene", "s", "t", "group", "share of the light"};
    for (const std::string& file : options.scenes) {
        RenderJobOptions job_options;
        job_options.scene = file;
        job_options.size = options.size;
        job_options.integrator = "bdpt";
        job_options.mis_heuristic = "balance";  // the weights are the densities' shares (report/strategy_shares.hpp)
        job_options.max_depth = options.max_depth;
        job_options.device = options.device;
        const RenderJob job = prepare_render_job(job_options);
        std::printf("report: BDPT's strategies one by one on %s\n", file.c_str());
        std::fflush(stdout);
        std::vector<report::WeightedStrategy> strategies;
        render_strategies(job, options.device, options.spp, false, &runtime,
                          [&](const StrategyImage& one) { strategies.push_back({one.s, one.t, one.image}); });
        StrategyAtlasScene scene{fs::path(file).filename().string(), "", report::strategy_shares(strategies)};
        const std::string stem = "atlas_strategies_" + fs::path(file).stem().string();
        film::write_png((folder / (stem + "_image.png")).string(), scene.shares.image, film::ToneMap::Aces, 0.0f, film::ImageMetadata{});
        film::write_png((folder / (stem + "_groups.png")).string(), scene.shares.groups, film::ToneMap::Clamp, 0.0f, film::ImageMetadata{});
        sheet.push_back({scene.scene + ": BDPT, " + std::to_string(strategies.size()) + " strategies", (folder / (stem + "_image.png")).string()});
        sheet.push_back({scene.scene + ": which strategies carry it", (folder / (stem + "_groups.png")).string()});
        for (const report::StrategyLight& s : scene.shares.strategies)
            csv.rows.push_back({{scene.scene}, {std::to_string(s.s)}, {std::to_string(s.t)}, {report::strategy_group_name(report::strategy_group(s.s, s.t))},
                                {report::number_text(s.share, 4)}});
        atlas.scenes.push_back(std::move(scene));
    }
    if (runtime) *device = runtime->device().description();
    plots::write_preview_sheet(sheet, "BDPT's strategies: red light tracing's (t = 1), green connections (s, t ≥ 2), blue the path tracer's (s ≤ 1)",
                               (folder / atlas.image).string());
    report::write_csv(csv, (folder / atlas.csv).string());
    return atlas;
}

}  // namespace lab::cli
