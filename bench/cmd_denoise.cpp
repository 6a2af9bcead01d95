// dtoadq bench denoise: what the display denoiser (film/denoise.hpp) buys and what it costs. For
// each environment and material on the test model, and each sample count: the RMSE of the raw and
// the denoised image against a long reference render, the ratio of the two, and the time of the
// filter against the time of one sample per pixel (the viewer's frame after an edit); a chart of
// error against time for raw and denoised (-o). Figures, not timed tests: ratios within one run.
//
// The reference has noise of its own, measured from its two halves (report::Reference::noise);
// it adds in quadrature to every error, which would pull the ratio toward 1 at high sample counts.
// The ratio is therefore also given with it taken out: sqrt(e_d^2 - n^2) / sqrt(e_r^2 - n^2).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/timed_runs.hpp"
#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "common/seconds_since.hpp"
#include "film/image_output.hpp"
#include "render/display_denoise.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "report/convergence.hpp"

namespace lab::cli {
namespace {

struct BenchDenoiseCommand {
    RenderJobOptions job;
    std::vector<std::string> envs{"envmaps/courtyard.exr", "envmaps/forest.exr"};
    std::vector<std::string> materials{"presets/clay.json", "presets/brushed_aluminium.json", "presets/glass.json"};
    std::vector<int> spps{1, 4, 16};
    int reference_spp = 1024;
    int filter_repeats = 5;
    film::DenoiseOptions filter;
    std::string chart;
    std::string csv;
};

using Clock = std::chrono::steady_clock;

// The reference's own noise taken out of an error (both are RMSEs over the same pixels).
double without_reference_noise(double error, double noise) { return std::sqrt(std::max(0.0, error * error - noise * noise)); }

std::string file_stem(const std::string& path) { return std::filesystem::path(path).stem().string(); }

struct CaseRow {
    int spp = 0;
    double raw = 0.0, denoised = 0.0, ratio = 0.0, corrected_ratio = 0.0;
    double raw_relative = 0.0, denoised_relative = 0.0;
    double render_seconds = 0.0, aov_seconds = 0.0, filter_seconds = 0.0, pass_seconds = 0.0;
};

void run_bench_denoise(const BenchDenoiseCommand& c) {
    if (c.spps.empty()) throw InputError("--spp", "", "needs at least one sample count");
    for (int spp : c.spps)
        if (spp < 1 || spp > 65536) throw InputError("--spp", std::to_string(spp), "must be in [1, 65536]");
    if (c.reference_spp < 2 * *std::max_element(c.spps.begin(), c.spps.end()) || c.reference_spp > 1 << 20)
        throw InputError("--reference-spp", std::to_string(c.reference_spp), "must be at least twice the largest --spp and at most 2^20");
    if (c.filter_repeats < 1 || c.filter_repeats > 1000) throw InputError("--filter-repeats", std::to_string(c.filter_repeats), "must be in [1, 1000]");
    if (c.filter.passes < 1 || c.filter.passes > 8) throw InputError("--passes", std::to_string(c.filter.passes), "must be in [1, 8]");
    if (!(c.filter.sigma_luminance > 0.0f)) throw InputError("--sigma-luminance", std::to_string(c.filter.sigma_luminance), "must be > 0");
    if (!(c.filter.sigma_normal >= 0.0f)) throw InputError("--sigma-normal", std::to_string(c.filter.sigma_normal), "must be >= 0");
    if (!(c.filter.sigma_depth > 0.0f)) throw InputError("--sigma-depth", std::to_string(c.filter.sigma_depth), "must be > 0");
    if (!c.chart.empty()) film::check_output_path(c.chart);

    std::optional<opencl::Runtime> runtime;
    if (c.job.device != "host") runtime.emplace(c.job.device);
    report::RendererFactory make = [&](const render::RenderInput& input) -> std::unique_ptr<render::Renderer> {
        if (runtime) return std::make_unique<render::OpenClRenderer>(*runtime, input);
        return std::make_unique<render::HostRenderer>(input);
    };
    std::printf("bench denoise: the test model at %s, reference %d spp; filter of %d passes on %s\n\n", c.job.size.c_str(), c.reference_spp,
                c.filter.passes, runtime ? runtime->device().description().c_str() : "the host");
    std::printf("%-12s %-18s %5s %10s %10s %7s %10s %9s %9s %9s %8s\n", "map", "material", "spp", "raw RMSE", "denoised", "ratio",
                "ratio w/o", "filter", "passes", "1 spp", "filter /");
    std::printf("%-12s %-18s %5s %10s %10s %7s %10s %9s %9s %9s %8s\n", "", "", "", "", "", "", "ref noise", "ms", "ms", "ms", "1 spp");

    std::vector<plots::ConvergenceSeries> series;
    std::vector<double> ratios_at_4, shares;
    for (const std::string& env : c.envs)
        for (const std::string& material : c.materials) {
            RenderJobOptions options = c.job;
            options.env = env;
            options.material = material;
            const RenderJob job = prepare_render_job(options);
            const report::Reference reference = report::render_reference_samples(make, job.input, c.reference_spp);
            const std::string name = file_stem(material) + ", " + file_stem(env);
            plots::ConvergenceSeries raw_series{name + ": raw", {}, {}}, denoised_series{name + ": denoised", {}, {}};
            // a frame: one sample of every pixel a launch, as the viewer renders, timed over eight
            const double frame = [&] {
                std::unique_ptr<render::Renderer> renderer = make(job.input);
                renderer->set_samples_per_launch(1);
                renderer->add_samples(1);  // the first launch's set-up is not a frame's
                const double before = renderer->statistics().render_seconds;
                renderer->add_samples(8);
                return (renderer->statistics().render_seconds - before) / 8.0;
            }();
            for (int spp : c.spps) {
                CaseRow row;
                row.spp = spp;
                std::unique_ptr<render::Renderer> renderer = make(job.input);
                renderer->set_samples_per_launch(std::min(spp, 16));
                renderer->add_samples(spp);
                row.render_seconds = renderer->statistics().render_seconds;
                const film::ImageRgb raw = renderer->image();
                renderer->first_hit_aovs();  // builds the AOVs' program: the time below is the pass alone
                Clock::time_point aov_start = Clock::now();
                const film::DenoiseGuide guide = render::denoise_guide(renderer->first_hit_aovs(), renderer->variance());
                row.aov_seconds = seconds_since(aov_start);
                // the filter's three steps timed apart: demodulation and its variance estimate on
                // the host, the passes where the render runs, remodulation on the host
                film::ImageRgb denoised;
                std::vector<double> filter_times, pass_times;
                const std::unique_ptr<render::DisplayFilter> filter = renderer->display_filter();
                filter->prepare();  // its program: the times below are the filter alone
                for (int i = 0; i < c.filter_repeats; ++i) {
                    Clock::time_point start = Clock::now();
                    film::AtrousBuffers buffers = film::demodulate(raw, guide);
                    Clock::time_point passes_start = Clock::now();
                    filter->passes(&buffers, c.filter, {});
                    pass_times.push_back(seconds_since(passes_start));
                    denoised = film::remodulate(buffers, guide);
                    filter_times.push_back(seconds_since(start));
                }
                row.filter_seconds = median(filter_times);
                row.pass_seconds = median(pass_times);
                row.raw = report::image_error_value(raw, reference.image, report::ErrorMetric::rmse);
                row.denoised = report::image_error_value(denoised, reference.image, report::ErrorMetric::rmse);
                row.raw_relative = report::image_error_value(raw, reference.image, report::ErrorMetric::relative_rmse);
                row.denoised_relative = report::image_error_value(denoised, reference.image, report::ErrorMetric::relative_rmse);
                row.ratio = row.denoised / row.raw;
                const double raw_clean = without_reference_noise(row.raw, reference.noise);
                row.corrected_ratio = raw_clean > 0.0 ? without_reference_noise(row.denoised, reference.noise) / raw_clean : 0.0;
                std::printf("%-12s %-18s %5d %10.4g %10.4g %6.3fx %9.3fx %9.2f %9.2f %9.2f %7.1f%%\n", file_stem(env).c_str(),
                            file_stem(material).c_str(), spp, row.raw, row.denoised, row.ratio, row.corrected_ratio, 1e3 * row.filter_seconds,
                            1e3 * row.pass_seconds, 1e3 * frame, 100.0 * row.filter_seconds / frame);
                std::fflush(stdout);
                if (spp == 4) ratios_at_4.push_back(row.corrected_ratio);
                shares.push_back(row.filter_seconds / frame);
                raw_series.seconds.push_back(row.render_seconds);
                raw_series.rmse.push_back(row.raw_relative);
                denoised_series.seconds.push_back(row.render_seconds + row.aov_seconds + row.filter_seconds);
                denoised_series.rmse.push_back(row.denoised_relative);
            }
            std::printf("%-31s reference noise (RMSE) %.3g\n", "", reference.noise);
            series.push_back(std::move(raw_series));
            series.push_back(std::move(denoised_series));
        }
    if (!ratios_at_4.empty())
        std::printf("\nat 4 spp, denoised / raw RMSE without the reference's noise: worst %.3fx, best %.3fx (target <= 0.5x)\n",
                    *std::max_element(ratios_at_4.begin(), ratios_at_4.end()), *std::min_element(ratios_at_4.begin(), ratios_at_4.end()));
    std::printf("the filter against one sample per pixel: %.1f%% to %.1f%% (target < 15%%)\n", 100.0 * *std::min_element(shares.begin(), shares.end()),
                100.0 * *std::max_element(shares.begin(), shares.end()));
    if (!c.chart.empty()) {
        plots::write_speed_accuracy_chart(series, "Display denoiser: error against time, raw and denoised (" + c.job.size + ")", c.chart, c.csv,
                                          "relative RMSE against the reference");
        std::printf("wrote %s%s\n", c.chart.c_str(), c.csv.empty() ? "" : (" and " + c.csv).c_str());
    }
}

}  // namespace

void register_bench_denoise(CLI::App& bench) {
    auto c = std::make_shared<BenchDenoiseCommand>();
    c->job.size = "256x256";  // the viewer's render size as it opens (viewer/viewer_config.hpp)
    c->job.seed = 1;
    auto* cmd = bench.add_subcommand("denoise",
                                     "The display denoiser's RMSE against raw at a few sample counts, per map and material, and its cost "
                                     "against one sample per pixel");
    add_render_options(*cmd, &c->job);
    cmd->add_option("--envs", c->envs, "Environments, each a map or constant:R,G,B")->delimiter(',')->capture_default_str();
    cmd->add_option("--materials", c->materials, "Material presets on the test model")->delimiter(',')->capture_default_str();
    cmd->add_option("--spp", c->spps, "Sample counts of the raw images")->delimiter(',')->capture_default_str();
    cmd->add_option("--reference-spp", c->reference_spp, "Samples per pixel of the reference (two halves)")->capture_default_str();
    cmd->add_option("--filter-repeats", c->filter_repeats, "Times each filter runs; its median time is given")->capture_default_str();
    cmd->add_option("--passes", c->filter.passes, "The filter's passes (widths 1, 2, 4, ...: fewer cost less and reach less far)")->capture_default_str();
    cmd->add_option("--sigma-luminance", c->filter.sigma_luminance, "The filter's luminance tolerance, in standard deviations")->capture_default_str();
    cmd->add_option("--sigma-normal", c->filter.sigma_normal, "How fast the filter's normal weight falls: exp(-sigma (1 - cos))")->capture_default_str();
    cmd->add_option("--sigma-depth", c->filter.sigma_depth, "The filter's tolerated relative depth change across the image's width")->capture_default_str();
    cmd->add_option("-o,--chart", c->chart, "Chart (PNG) of relative RMSE against time, raw and denoised");
    cmd->add_option("--csv", c->csv, "The chart's data as CSV");
    cmd->callback([c] { run_bench_denoise(*c); });
}

}  // namespace lab::cli
