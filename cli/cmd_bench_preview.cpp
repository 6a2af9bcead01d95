// dtoadq bench preview: the preview's speed and its speed against accuracy. Prints the kernel's
// cold and warm build times, paths and rays per second, and for each environment-sampling strategy
// the error (RMSE against a long reference render) reached in the same time; draws the error
// against time of every strategy (-o chart.png). Figures, not timed tests: ratios within one run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/preview_job.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "film/image_stats.hpp"
#include "ibl/preview_renderer.hpp"
#include "opencl/runtime.hpp"
#include "plots/speed_accuracy_chart.hpp"

namespace lab::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct BenchPreviewCommand {
    PreviewJobOptions job;
    double seconds = 5.0;             // per strategy
    double reference_seconds = 40.0;  // the reference render (MIS, another seed)
    std::string chart;
    std::string csv;
};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Renders for `seconds` in launches short enough to chart; calls `checkpoint` after each launch.
template <typename Checkpoint>
void render_for(ibl::PreviewRenderer& renderer, double seconds, Checkpoint checkpoint) {
    Clock::time_point start = Clock::now();
    while (seconds_since(start) < seconds) {
        Clock::time_point launch = Clock::now();
        renderer.add_samples(renderer.samples_per_launch());
        double took = seconds_since(launch);
        checkpoint(seconds_since(start));
        // double the launch while it is short, but keep ~20 points per series
        if (took < seconds / 40.0) renderer.set_samples_per_launch(renderer.samples_per_launch() * 2);
    }
}

void run_bench_preview(const BenchPreviewCommand& c) {
    if (!(c.seconds > 0.0 && c.seconds <= 3600.0)) throw InputError("--seconds", "", "must be more than 0 and at most 3600");
    if (!(c.reference_seconds >= c.seconds && c.reference_seconds <= 36000.0))
        throw InputError("--reference-seconds", "", "must be at least --seconds and at most 36000");
    if (!c.chart.empty()) film::check_output_path(c.chart);
    PreviewJob job = prepare_preview_job(c.job);
    opencl::Runtime runtime(c.job.device);
    std::printf("bench preview: %s\ndevice %s\n\n", job.description.c_str(), runtime.device().description().c_str());

    // Cold: a source no cache has seen (a fresh -D); warm: the very same build again.
    std::random_device entropy;
    ibl::PreviewSettings cold_settings = job.settings;
    cold_settings.extra_build_options = "-DDTOADQ_BENCH_NONCE=" + std::to_string(entropy());
    double cold = ibl::PreviewRenderer(runtime, job.scene, job.environment, cold_settings).build_seconds();
    double warm = ibl::PreviewRenderer(runtime, job.scene, job.environment, cold_settings).build_seconds();
    std::printf("kernel build: cold %.3f s, warm %.3f s (PoCL kernel cache; cold/warm %.1fx)\n", cold, warm, cold / warm);

    // Reference: MIS, its own seed, long; its own noise estimated from its two halves.
    ibl::PreviewSettings reference_settings = job.settings;
    reference_settings.sampling = ibl::IblSampling::mis;
    reference_settings.seed = job.settings.seed + 1000003;
    ibl::PreviewRenderer half_a(runtime, job.scene, job.environment, reference_settings);
    reference_settings.seed += 1;
    ibl::PreviewRenderer half_b(runtime, job.scene, job.environment, reference_settings);
    render_for(half_a, c.reference_seconds / 2, [](double) {});
    render_for(half_b, c.reference_seconds / 2, [](double) {});
    film::ImageRgb a = half_a.image(), b = half_b.image(), reference(a.width, a.height);
    for (size_t k = 0; k < a.rgb.size(); ++k) reference.rgb[k] = 0.5f * (a.rgb[k] + b.rgb[k]);
    // RMSE(a, b) = sqrt(2) sigma_half, and the mean of the halves has sigma_half / sqrt(2).
    double reference_noise = film::image_error(a, b).rmse_mean / 2.0;
    ibl::PreviewStatistics ref_stats = half_a.statistics();
    std::printf("throughput (MIS, %dx%d): %.3g paths/s, %.3g rays/s, %.2f rays per path\n", job.settings.width, job.settings.height,
                ref_stats.paths_per_second(), ref_stats.rays_per_second(), double(ref_stats.rays) / double(ref_stats.paths));
    std::printf("reference: MIS, %d spp in %.1f s; its own noise (RMSE) about %.3g\n\n",
                half_a.statistics().samples_per_pixel + half_b.statistics().samples_per_pixel, c.reference_seconds, reference_noise);

    std::vector<plots::ConvergenceSeries> series;
    std::printf("equal time, %.1f s each:\n  %-8s %8s %12s %12s %14s\n", c.seconds, "strategy", "spp", "paths/s", "RMSE", "RMSE x sqrt(t)");
    double mis_rmse = 0.0;
    std::vector<std::pair<std::string, double>> finals;
    for (ibl::IblSampling sampling : {ibl::IblSampling::brdf, ibl::IblSampling::env, ibl::IblSampling::mis}) {
        ibl::PreviewSettings settings = job.settings;
        settings.sampling = sampling;
        ibl::PreviewRenderer renderer(runtime, job.scene, job.environment, settings);
        plots::ConvergenceSeries s;
        s.name = ibl::ibl_sampling_name(sampling);
        render_for(renderer, c.seconds, [&](double t) {
            s.seconds.push_back(t);
            s.rmse.push_back(film::image_error(renderer.image(), reference).rmse_mean);
        });
        ibl::PreviewStatistics stats = renderer.statistics();
        double rmse = s.rmse.back();
        std::printf("  %-8s %8d %12.3g %12.4g %14.4g\n", s.name.c_str(), stats.samples_per_pixel, stats.paths_per_second(), rmse,
                    rmse * std::sqrt(s.seconds.back()));
        if (sampling == ibl::IblSampling::mis) mis_rmse = rmse;
        finals.push_back({s.name, rmse});
        series.push_back(std::move(s));
    }
    std::printf("\nequal-time RMSE relative to MIS:");
    for (const auto& [name, rmse] : finals) std::printf("  %s %.2fx", name.c_str(), rmse / mis_rmse);
    std::printf("\n(the RMSE includes the reference's own noise, about %.3g)\n", reference_noise);
    if (!c.chart.empty()) {
        plots::write_speed_accuracy_chart(series, "Preview: RMSE against render time (" + job.material_name + ", " + job.environment_name + ")",
                                          c.chart, c.csv);
        std::printf("wrote %s%s\n", c.chart.c_str(), c.csv.empty() ? "" : (" and " + c.csv).c_str());
    }
}

}  // namespace

void register_bench_preview(CLI::App& bench) {
    auto c = std::make_shared<BenchPreviewCommand>();
    c->job.size = "128x128";
    c->job.env = "envmaps/courtyard.exr";
    auto* cmd = bench.add_subcommand(
        "preview", "Kernel build times, paths/s and rays/s of the preview, and the equal-time error of each environment-sampling strategy");
    add_preview_job_options(*cmd, &c->job);
    cmd->add_option("--seconds", c->seconds, "Render time of each strategy")->capture_default_str();
    cmd->add_option("--reference-seconds", c->reference_seconds, "Render time of the reference (MIS)")->capture_default_str();
    cmd->add_option("-o,--chart", c->chart, "Speed-against-accuracy chart (PNG): RMSE against time per strategy");
    cmd->add_option("--csv", c->csv, "The chart's data as CSV");
    cmd->callback([c] { run_bench_preview(*c); });
}

}  // namespace lab::cli
