// dtoadq bench render: the render core's figures per bundled scene. Paths/s and rays/s of the path
// tracer on the OpenCL device and of the same integrator built as C++ on the host's threads, as a
// ratio, with march steps per ray and distance evaluations per step (bench/march_cost.hpp); and
// on the scenes where the choice matters (the Cornell box, Veach's MIS scene) the equal-time error of next-event estimation with MIS against BSDF sampling alone (what the
// preview did before the render core) and light sampling alone, against a long reference. Then,
// on the scenes of --integrators (the Cornell box, the caustic), the equal-time error of bdpt, bdpt-cache and lt
// against pt over the same path space (pt's max depth = bdpt's max vertices - 2), against a long pt
// reference of that depth. Figures, not timed tests: every ratio is measured within the one run.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iterator>
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
    // --matrix: every integrator on every scene of `matrix_scenes` (empty: every scene in scenes/),
    // under its own lights (where it has any) and under `matrix_env`, and nothing else
    bool matrix = false;
    std::vector<std::string> matrix_scenes;
    std::string matrix_env = "envmaps/courtyard.exr";
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

// The scenes of --matrix: the given ones, else every scene file in scenes/, sorted.
std::vector<std::string> matrix_scene_files(const BenchRenderCommand& c) {
    if (!c.matrix_scenes.empty()) return c.matrix_scenes;
    std::vector<std::string> files;
    if (!fs::is_directory("scenes")) throw InputError("--matrix-scenes", "", "no scenes/ folder here: run from the repository root or name the scenes");
    for (const fs::directory_entry& e : fs::directory_iterator("scenes"))
        if (e.path().extension() == ".json") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

// "out.png" and "cornell_box own" -> "out-cornell_box-own.png": one chart per scene and lighting.
std::string matrix_output(const std::string& path, const std::string& label) {
    if (path.empty()) return path;
    fs::path p(path);
    std::string tag = label;
    std::replace(tag.begin(), tag.end(), ' ', '-');
    return (p.parent_path() / (p.stem().string() + "-" + tag + p.extension().string())).string();
}

// --matrix: pt, lt, bdpt, bdpt-cache and vcm at equal time on every scene, under its own lights and
// under --matrix-env (which lt cannot render: it is left out there), each against a long reference
// of --reference-integrator with another seed. A row per scene and lighting: each integrator's
// RMSE relative to pt's and its paths/s; a chart of RMSE against time per scene and lighting.
void run_matrix(const report::RendererFactory& on_device, const BenchRenderCommand& c, render::Integrator reference_integrator) {
    constexpr render::Integrator kIntegrators[] = {render::Integrator::pt, render::Integrator::lt, render::Integrator::bdpt,
                                               render::Integrator::bdpt_cache, render::Integrator::vcm};
    constexpr int kCount = int(std::size(kIntegrators));
    struct Row {
        std::string label;
        double reference_noise = 0.0;
        double rmse[kCount] = {}, paths_per_second[kCount] = {};
    };
    std::vector<Row> rows;
    for (const std::string& file : matrix_scene_files(c)) {
        const scene::Scene scene = scene::load_scene(file);
        for (int lighting = 0; lighting < 2; ++lighting) {
            if (lighting == 0 && !scene::has_own_light(scene)) continue;
            RenderJobOptions o = c.job;
            o.scene = file;
            if (lighting == 1) o.env = c.matrix_env;
            RenderJob job = prepare_render_job(o);
            Row row;
            row.label = fs::path(file).stem().string() + (lighting == 0 ? " own" : " " + fs::path(c.matrix_env).stem().string());
            std::vector<report::EqualTimeRun> runs;
            std::vector<int> slots;
            for (int i = 0; i < kCount; ++i) {
                if (!render::integrator_descriptor(kIntegrators[i]).renders_environment() && job.input.environment) continue;
                report::EqualTimeRun run{row.label + " " + render::integrator_name(kIntegrators[i]), job.input};
                run.input.settings.integrator = kIntegrators[i];
                runs.push_back(std::move(run));
                slots.push_back(i);
            }
            render::RenderInput reference_input = job.input;
            reference_input.settings.integrator = reference_integrator;
            std::printf("\n%s: reference (%s) for %.0f s\n", row.label.c_str(), c.reference_integrator.c_str(), c.reference_seconds);
            report::Reference ref = report::render_reference(on_device, reference_input, c.reference_seconds);
            row.reference_noise = ref.noise;
            std::printf("reference %d spp; its own noise (RMSE) about %.3g\n", ref.samples_per_pixel, ref.noise);
            std::vector<report::EqualTimeResult> results = report::run_equal_time(on_device, runs, ref, c.seconds);
            std::vector<plots::ConvergenceSeries> series;
            for (size_t k = 0; k < results.size(); ++k) {
                row.rmse[slots[k]] = results[k].final_rmse();
                row.paths_per_second[slots[k]] = results[k].stats.paths_per_second();
                series.push_back(results[k].series);
            }
            if (!c.chart.empty())
                plots::write_speed_accuracy_chart(series, row.label + ": RMSE against render time per integrator", matrix_output(c.chart, row.label),
                                                  matrix_output(c.csv, row.label));
            rows.push_back(row);
            std::fflush(stdout);
        }
    }
    std::printf("\nequal time, %.1f s each: RMSE relative to pt's (paths/s); bdpt / best of pt and lt; reference %s, %.0f s\n", c.seconds,
                c.reference_integrator.c_str(), c.reference_seconds);
    std::printf("| scene, lights | pt RMSE | lt | bdpt | bdpt-cache | vcm | bdpt / best(pt, lt) | reference noise |\n|---|---|---|---|---|---|---|---|\n");
    for (const Row& row : rows) {
        std::printf("| %s | %.3g (%.3g) |", row.label.c_str(), row.rmse[0], row.paths_per_second[0]);
        for (int i = 1; i < kCount; ++i) {
            if (row.rmse[i] > 0.0) std::printf(" %.2f (%.3g) |", row.rmse[i] / row.rmse[0], row.paths_per_second[i]);
            else std::printf(" - |");
        }
        const double best = row.rmse[1] > 0.0 ? std::min(row.rmse[0], row.rmse[1]) : row.rmse[0];
        std::printf(" %.2f | %.3g |\n", row.rmse[2] / best, row.reference_noise);
    }
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
    if (c.matrix) {
        std::printf("bench render --matrix: %s, max depth %d; device %s\n", c.job.size.c_str(), c.job.max_depth, runtime.device().description().c_str());
        run_matrix(on_device, c, reference_integrator);
        return;
    }
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
    cmd->add_flag("--matrix", c->matrix,
                  "Instead of the above: pt, lt, bdpt, bdpt-cache and vcm at equal time (--seconds) on every scene of --matrix-scenes, under its own "
                  "lights and under --matrix-env, against a --reference-integrator reference; a table, and a chart per scene and lighting (-o "
                  "out.png writes out-SCENE-LIGHTS.png)");
    cmd->add_option("--matrix-scenes", c->matrix_scenes, "The scenes of --matrix (default: every scene in scenes/)");
    cmd->add_option("--matrix-env", c->matrix_env, "The environment of --matrix's second lighting (the scene's lights stay)")->capture_default_str();
    cmd->add_option("-o,--chart", c->chart, "Speed-against-accuracy chart (PNG): RMSE against time per scene and strategy");
    cmd->add_option("--csv", c->csv, "The chart's data as CSV");
    cmd->callback([c] { run_bench_render(*c); });
}

}  // namespace lab::cli
