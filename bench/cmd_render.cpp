// dtoadq bench render: the render core's figures per bundled scene. Paths/s and rays/s of the path
// tracer on the OpenCL device and of the same integrator built as C++ on the host's threads, as a
// ratio, with march steps per ray and distance evaluations per step (bench/march_cost.hpp); and
// on the scenes where the choice matters (the Cornell box, Veach's MIS scene) the equal-time error of next-event estimation with MIS against BSDF sampling alone (what the
// preview did before the render core) and light sampling alone, against a long reference. Then,
// on the scenes of --integrators (the Cornell box, the caustic), the equal-time error of bdpt, bdpt-cache and lt
// against pt over the same path space (pt's max depth = bdpt's max vertices - 2), against a long pt
// reference of that depth. Figures, not timed tests: every ratio is measured within the one run.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/convergence.hpp"
#include "bench/march_cost.hpp"
#include "bench/timed_runs.hpp"
#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "render/host_renderer.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"

namespace lab::cli {
namespace {

namespace fs = std::filesystem;

struct BenchRenderCommand {
    RenderJobOptions job;
    std::vector<std::string> scenes{"scenes/shader_ball.json", "scenes/cornell_box.json", "scenes/veach_mis.json",
                                    "scenes/depth_of_field.json", "scenes/metaballs.json",  "scenes/repetition.json",
                                    "scenes/primitives.json"};
    std::vector<std::string> compare{"scenes/cornell_box.json", "scenes/veach_mis.json"};
    std::vector<std::string> integrators{"scenes/cornell_box.json", "scenes/caustic.json", "scenes/shader_ball.json"};
    // bdpt-cache's runs at equal time: light paths per pixel and connections, "R:M" each; empty:
    // one run with --light-paths and --connections
    std::vector<std::string> cache_counts;
    double throughput_seconds = 2.0;
    double seconds = 4.0;
    double reference_seconds = 40.0;
    // the integrator of the --integrators references: pt, or vcm where only merging samples the
    // scene's light (scenes/caustic_mirror.json)
    std::string reference_integrator = "pt";
    std::string chart, csv;
};

// The job for one scene: a scene with no light of its own (no environment, no emitter) is lit by the
// bench's default environment, so that it measures something.
RenderJob scene_job(const RenderJobOptions& options, const std::string& file) {
    RenderJobOptions o = options;
    o.scene = file;
    scene::Scene scene = scene::load_scene(file);
    if (!scene::has_own_light(scene)) o.default_env = "envmaps/courtyard.exr";
    return prepare_render_job(o);
}

// Renders for about `seconds` and returns the statistics. One sample first, not counted: PoCL
// compiles a kernel for its work-group size at the first launch, seconds for BDPT's.
render::RenderStatistics measure(render::Renderer& renderer, double seconds) {
    renderer.add_samples(1);
    renderer.reset();
    report::render_for(renderer, seconds, [](double) {});
    return renderer.statistics();
}

// One scene at equal time: a long reference of `reference_input` (labelled `reference`), then each
// run for c.seconds; prints each run's final RMSE relative to the last run's (`baseline`) and adds
// the runs' series to the chart's.
void compare_at_equal_time(const report::RendererFactory& on_device, const BenchRenderCommand& c, const std::string& reference,
                           const render::RenderInput& reference_input, const std::vector<report::EqualTimeRun>& runs, const std::string& baseline,
                           std::vector<plots::ConvergenceSeries>* series) {
    std::printf("\n%s for %.0f s\n", reference.c_str(), c.reference_seconds);
    report::Reference ref = report::render_reference(on_device, reference_input, c.reference_seconds);
    std::printf("reference %d spp; its own noise (RMSE) about %.3g\n", ref.samples_per_pixel, ref.noise);
    std::vector<report::EqualTimeResult> results = report::run_equal_time(on_device, runs, ref, c.seconds);
    std::printf("equal-time RMSE relative to %s:", baseline.c_str());
    for (const report::EqualTimeResult& r : results) {
        std::printf("  %s %.2fx", r.series.name.c_str(), r.final_rmse() / results.back().final_rmse());
        series->push_back(r.series);
    }
    std::printf("\n");
}

// "R:M": --light-paths R and --connections M of bdpt-cache; errors name --cache-counts.
void parse_cache_counts(const std::string& text, render::RenderSettings* settings) {
    const size_t colon = text.find(':');
    try {
        size_t used = 0;
        if (colon == std::string::npos) throw std::invalid_argument(text);
        settings->bdpt.light_paths = std::stof(text.substr(0, colon), &used);
        if (used != colon) throw std::invalid_argument(text);
        settings->bdpt.connections = std::stoi(text.substr(colon + 1), &used);
        if (used != text.size() - colon - 1) throw std::invalid_argument(text);
    } catch (const std::logic_error&) {
        throw InputError("--cache-counts", "", "expected light paths per pixel and connections as R:M, got \"" + text + "\"");
    }
    render::check_render_settings(*settings);
}

void run_bench_render(const BenchRenderCommand& c) {
    render::RenderSettings checked;
    for (const std::string& counts : c.cache_counts) parse_cache_counts(counts, &checked);
    check_render_seconds(c.seconds);
    check_render_seconds(c.throughput_seconds, "--throughput-seconds");
    if (!(c.reference_seconds >= c.seconds && c.reference_seconds <= 36000.0))
        throw InputError("--reference-seconds", "", "must be at least --seconds and at most 36000");
    if (!c.chart.empty()) film::check_output_path(c.chart);
    const render::Integrator reference_integrator = render::parse_integrator(c.reference_integrator, "--reference-integrator");
    opencl::Runtime runtime(c.job.device);
    report::RendererFactory on_device = [&runtime](const render::RenderInput& input) { return std::make_unique<render::OpenClRenderer>(runtime, input); };
    std::printf("bench render: %s, pt with MIS; device %s\n\n", c.job.size.c_str(), runtime.device().description().c_str());

    std::printf("(a scene with no light of its own is lit by envmaps/courtyard.exr)\n");
    std::printf("%-28s %12s %12s %10s %10s %10s %14s %12s %12s %12s %12s %12s\n", "scene", "paths/s", "rays/s", "rays/path", "steps/ray", "evals/step",
                "host paths/s", "device/host", "bdpt paths/s", "lt paths/s", "cache paths/s", "vcm paths/s");
    for (const std::string& file : c.scenes) {
        RenderJob job = scene_job(c.job, file);
        std::unique_ptr<render::Renderer> device = on_device(job.input);
        render::RenderStatistics d = measure(*device, c.throughput_seconds);
        bench::MarchCost work = bench::measure_march_cost(runtime, job.input, 1);
        render::HostRenderer host(job.input);
        render::RenderStatistics h = measure(host, c.throughput_seconds);
        const render::Integrator kBidirectional[] = {render::Integrator::bdpt, render::Integrator::lt, render::Integrator::bdpt_cache,
                                                     render::Integrator::vcm};
        double bidirectional[4] = {0.0, 0.0, 0.0, 0.0};
        for (int i = 0; i < 4; ++i) {
            if (!render::integrator_descriptor(kBidirectional[i]).renders_environment() && job.input.environment) continue;
            render::RenderInput input = job.input;
            input.settings.integrator = kBidirectional[i];
            std::unique_ptr<render::Renderer> r = on_device(input);
            bidirectional[i] = measure(*r, c.throughput_seconds).paths_per_second();
        }
        char lt[32] = "-";  // not under an environment
        if (bidirectional[1] > 0.0) std::snprintf(lt, sizeof(lt), "%.3g", bidirectional[1]);
        std::printf("%-28s %12.3g %12.3g %10.2f %10.1f %10.2f %14.3g %11.2fx %12.3g %12s %12.3g %12.3g\n", fs::path(file).filename().string().c_str(),
                    d.paths_per_second(), d.rays_per_second(), double(d.rays) / double(d.paths), work.steps_per_ray,
                    work.evaluations_per_step, h.paths_per_second(),
                    d.paths_per_second() / h.paths_per_second(), bidirectional[0], lt, bidirectional[2], bidirectional[3]);
        std::fflush(stdout);
    }

    std::vector<plots::ConvergenceSeries> series;
    for (const std::string& file : c.compare) {
        RenderJob job = scene_job(c.job, file);
        std::string name = fs::path(file).stem().string();
        std::vector<report::EqualTimeRun> runs;
        for (render::LightSampling sampling : {render::LightSampling::bsdf, render::LightSampling::lights, render::LightSampling::mis}) {
            report::EqualTimeRun run{name + " " + render::light_sampling_name(sampling), job.input};
            run.input.settings.light_sampling = sampling;
            runs.push_back(std::move(run));
        }
        compare_at_equal_time(on_device, c, name + ": reference (MIS)", job.input, runs, "MIS", &series);
    }
    for (const std::string& file : c.integrators) {
        RenderJob job = scene_job(c.job, file);
        std::string name = fs::path(file).stem().string();
        std::vector<report::EqualTimeRun> runs;
        for (render::Integrator integrator :
             {render::Integrator::bdpt, render::Integrator::bdpt_cache, render::Integrator::vcm, render::Integrator::lt, render::Integrator::pt}) {
            if (!render::integrator_descriptor(integrator).renders_environment() && job.input.environment) continue;
            report::EqualTimeRun run{name + " " + render::integrator_name(integrator), job.input};
            run.input.settings.integrator = integrator;
            if (integrator == render::Integrator::bdpt_cache && !c.cache_counts.empty()) {
                for (const std::string& counts : c.cache_counts) {
                    report::EqualTimeRun sized = run;
                    sized.name += " " + counts;
                    parse_cache_counts(counts, &sized.input.settings);
                    runs.push_back(std::move(sized));
                }
                continue;
            }
            runs.push_back(std::move(run));
        }
        render::RenderInput reference = job.input;
        reference.settings.integrator = reference_integrator;
        compare_at_equal_time(on_device, c,
                              name + ": reference (" + c.reference_integrator + ", max depth " + std::to_string(job.input.settings.max_depth) + ")",
                              reference, runs, "pt", &series);
    }
    if (!c.chart.empty() && !series.empty()) {
        plots::write_speed_accuracy_chart(series, "Render core: RMSE against render time, by light-sampling strategy and integrator", c.chart,
                                          c.csv);
        std::printf("wrote %s%s\n", c.chart.c_str(), c.csv.empty() ? "" : (" and " + c.csv).c_str());
    }
}

}  // namespace

void register_bench_render(CLI::App& bench) {
    auto c = std::make_shared<BenchRenderCommand>();
    c->job.size = "128x128";
    auto* cmd = bench.add_subcommand(
        "render", "Paths/s and rays/s per bundled scene (pt on the device and the host build, bdpt, lt, bdpt-cache, vcm), and the equal-time error of "
        "each light-sampling strategy and of bdpt, bdpt-cache, vcm and lt against pt");
    add_render_options(*cmd, &c->job);
    cmd->add_option("--scenes", c->scenes, "Scenes to measure throughput on")->capture_default_str();
    cmd->add_option("--compare", c->compare, "Scenes to compare light-sampling strategies on at equal time")->capture_default_str();
    cmd->add_option("--integrators", c->integrators, "Scenes to compare bdpt, bdpt-cache, vcm, lt and pt on at equal time")->capture_default_str();
    cmd->add_option("--cache-counts", c->cache_counts,
                    "bdpt-cache at equal time with each of these light paths per pixel and connections, R:M (default: one run with "
                    "--light-paths and --connections)");
    cmd->add_option("--throughput-seconds", c->throughput_seconds, "Render time of each throughput figure")->capture_default_str();
    cmd->add_option("--seconds", c->seconds, "Render time of each strategy")->capture_default_str();
    cmd->add_option("--reference-seconds", c->reference_seconds, "Render time of each reference (MIS)")->capture_default_str();
    cmd->add_option("--reference-integrator", c->reference_integrator,
                    "The integrator of the --integrators references (vcm where only merging samples the light, as in scenes/caustic_mirror.json)")
        ->capture_default_str();
    cmd->add_option("-o,--chart", c->chart, "Speed-against-accuracy chart (PNG): RMSE against time per scene and strategy");
    cmd->add_option("--csv", c->csv, "The chart's data as CSV");
    cmd->callback([c] { run_bench_render(*c); });
}

}  // namespace lab::cli
