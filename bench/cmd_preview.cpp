// dtoadq bench preview: the preview's speed and its speed against accuracy. Prints the kernel's
// cold and warm build times, paths and rays per second, and for each light-sampling strategy the
// error (RMSE against a long reference render) reached in the same time; draws the error against
// time of every strategy (-o chart.png). Figures, not timed tests: ratios within one run.
#include <cstdio>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "report/convergence.hpp"
#include "bench/timed_runs.hpp"
#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "render/opencl_renderer.hpp"

namespace lab::cli {
namespace {

struct BenchPreviewCommand {
    RenderJobOptions job;
    double seconds = 5.0;             // per strategy
    double reference_seconds = 40.0;  // the reference render (MIS, another seed)
    std::string chart;
    std::string csv;
};

void run_bench_preview(const BenchPreviewCommand& c) {
    check_render_seconds(c.seconds);
    if (!(c.reference_seconds >= c.seconds && c.reference_seconds <= 36000.0))
        throw InputError("--reference-seconds", "", "must be at least --seconds and at most 36000");
    if (!c.chart.empty()) film::check_output_path(c.chart);
    RenderJob job = prepare_render_job(c.job);
    opencl::Runtime runtime(c.job.device);
    std::printf("bench preview: %s\ndevice %s\n\n", job.description.c_str(), runtime.device().description().c_str());
    report::RendererFactory make = [&runtime](const render::RenderInput& input) { return std::make_unique<render::OpenClRenderer>(runtime, input); };

    // Cold: a source no cache has seen (a fresh -D); warm: the very same build again.
    render::RenderInput cold_input = job.input;
    cold_input.settings.opencl.extra_build_options = "-DDTOADQ_BENCH_NONCE=" + std::to_string(std::random_device{}());
    double cold = make(cold_input)->build_seconds();
    double warm = make(cold_input)->build_seconds();
    std::printf("kernel build: cold %.3f s, warm %.3f s (PoCL kernel cache; cold/warm %.1fx)\n", cold, warm, cold / warm);

    render::RenderInput reference_input = job.input;
    reference_input.settings.light_sampling = render::LightSampling::mis;
    report::Reference reference = report::render_reference(make, reference_input, c.reference_seconds);
    const render::RenderStatistics& ref_stats = reference.half_stats;
    std::printf("throughput (MIS, %dx%d): %.3g paths/s, %.3g rays/s, %.2f rays per path\n", job.input.settings.width,
                job.input.settings.height, ref_stats.paths_per_second(), ref_stats.rays_per_second(),
                double(ref_stats.rays) / double(ref_stats.paths));
    std::printf("reference: MIS, %d spp in %.1f s; its own noise (RMSE) about %.3g\n\n", reference.samples_per_pixel, c.reference_seconds,
                reference.noise);

    std::vector<report::EqualTimeRun> runs;
    for (render::LightSampling sampling : {render::LightSampling::bsdf, render::LightSampling::lights, render::LightSampling::mis}) {
        report::EqualTimeRun run{render::light_sampling_name(sampling), job.input};
        run.input.settings.light_sampling = sampling;
        runs.push_back(std::move(run));
    }
    std::vector<report::EqualTimeResult> results = report::run_equal_time(make, runs, reference, c.seconds);
    std::printf("\nequal-time RMSE relative to MIS:");
    for (const report::EqualTimeResult& r : results) std::printf("  %s %.2fx", r.series.name.c_str(), r.final_rmse() / results.back().final_rmse());
    std::printf("\n(the RMSE includes the reference's own noise, about %.3g)\n", reference.noise);
    if (!c.chart.empty()) {
        std::vector<plots::ConvergenceSeries> series;
        for (const report::EqualTimeResult& r : results) series.push_back(r.series);
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
        "preview", "Kernel build times, paths/s and rays/s of the preview, and the equal-time error of each light-sampling strategy");
    add_preview_options(*cmd, &c->job);
    add_render_options(*cmd, &c->job);
    cmd->add_option("--seconds", c->seconds, "Render time of each strategy")->capture_default_str();
    cmd->add_option("--reference-seconds", c->reference_seconds, "Render time of the reference (MIS)")->capture_default_str();
    cmd->add_option("-o,--chart", c->chart, "Speed-against-accuracy chart (PNG): RMSE against time per strategy");
    cmd->add_option("--csv", c->csv, "The chart's data as CSV");
    cmd->callback([c] { run_bench_preview(*c); });
}

}  // namespace lab::cli
