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

report::AtlasEntry strategy_atlas_entry(const StrategyAtlas& atlas) {
    using report::text_cell;
    auto number = [](double v) { return report::number_cell(v, 3); };
    auto percent = [](double f) { return report::number_text(100.0 * f, 2) + " %"; };
    report::AtlasEntry e;
    e.title = "each scene's BDPT image beside the map of which strategies carry its light";
    e.image = atlas.image;
    e.csv = atlas.csv;
    e.table.header = {"scene", "strategies", "share of the light", "lit pixels where under 10 %", "strongest strategy (s, t)", "its share"};
    for (const StrategyAtlasScene& scene : atlas.scenes) {
        const report::StrategyShares& shares = scene.shares;
        for (int g = 0; g < report::kStrategyGroups; ++g) {
            const report::StrategyLight* strongest = nullptr;
            for (const report::StrategyLight& s : shares.strategies)
                if (int(report::strategy_group(s.s, s.t)) == g && (!strongest || s.share > strongest->share)) strongest = &s;
            e.table.rows.push_back({text_cell(scene.scene), text_cell(report::strategy_group_name(report::StrategyGroup(g))), number(shares.light[size_t(g)]),
                                    number(shares.minor_pixels[size_t(g)]),
                                    text_cell(strongest ? "(" + std::to_string(strongest->s) + ", " + std::to_string(strongest->t) + ")" : "-"),
                                    strongest ? number(strongest->share) : text_cell("-")});
        }
        const size_t pt = size_t(report::StrategyGroup::path_tracer), lt = size_t(report::StrategyGroup::light_tracer),
                     connection = size_t(report::StrategyGroup::connection);
        e.finding += "On " + scene.scene + " the path tracer's strategies carry " + percent(shares.light[pt]) + " of the light, light tracing's " +
                     percent(shares.light[lt]) + " and connections " + percent(shares.light[connection]) + "; the path tracer's carry under a tenth in " +
                     percent(shares.minor_pixels[pt]) + " of the lit pixels, light tracing's in " + percent(shares.minor_pixels[lt]) + ".";
        if (&scene != &atlas.scenes.back()) e.finding += " ";
    }
    const StrategyAtlasOptions& o = atlas.options;
    e.how = "Where each integrator fails: BDPT (max depth " + std::to_string(o.max_depth) + ", " + o.size + ") renders each of its strategies alone, " +
            std::to_string(o.spp) + " samples per pixel each, weighted by its MIS weight with the balance heuristic, which is the strategy's sampling "
            "density over the sum of every strategy's for the same path; the weighted renders sum to the BDPT image. Each pixel of a map shows the "
            "share of its luminance that each group carries, and so the share of the sampling density it has there: red, light tracing's strategies "
            "(t = 1, what lt renders); green, connections of two subpaths of two or more vertices, which only BDPT makes; blue, the path tracer's "
            "(s ≤ 1, what pt renders). Where a group carries under a tenth, the others sample that light at least nine times as densely: that is "
            "where its integrator alone fails. Unlit pixels (under 1 % of the image's mean) are black.";
    return e;
}

}  // namespace lab::cli
