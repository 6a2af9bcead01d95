// dtoadq bench breakdown: where the path tracer's time goes, per scene. (1) March work: rays per
// path, march steps per ray, distance functions evaluated per step (bench/march_cost.hpp). (2) Parts:
// paths/s with the random numbers, the environment's importance sampling or the BSDF replaced by a
// nearly free stand-in (bench/kernels/part_standins.h), against the default build, interleaved in one
// run; 1 - default/stand-in is the part's share of the time, as far as the stand-in keeps the
// paths alike (its rays per path are printed next to it); and the environment's part done twice,
// on the very same paths: default/twice - 1 bounds its share from above (the second lookups are not
// prefetched as the path's own are, docs/render.md). (3) The wavefront's
// launches (a CPU device): each kind's share of the time and microseconds per sample, the host
// waiting for every launch (bench/wavefront_launch_timer.hpp). (4) Work-group size:
// paths/s per local size against the default 64. Figures, not timed tests: every ratio is measured
// within the run.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "report/convergence.hpp"
#include "bench/march_cost.hpp"
#include "bench/part_build.hpp"
#include "bench/timed_runs.hpp"
#include "bench/wavefront_launch_timer.hpp"
#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"

namespace lab::cli {
namespace {

namespace fs = std::filesystem;

struct BenchBreakdownCommand {
    RenderJobOptions job;
    std::vector<std::string> scenes{"scenes/shader_ball.json", "scenes/cornell_box.json", "scenes/repetition.json", "scenes/primitives.json"};
    std::vector<int> local_sizes{8, 16, 32, 128, 256};
    double seconds = 1.5;
    int repeats = 2;
    int count_samples = 2;
};

struct Speed {
    double paths_per_second = 0.0, rays_per_path = 0.0;
};

// PoCL compiles a kernel's work-group function at its first launch of each shape, into its cache:
// one launch of each number of samples in flight that a render's launches reach (1, 2, ... as many
// as the wavefront holds, at most 8 to keep a tiny image's warm-up short), then the film cleared, so
// that no figure pays for a compile. A single warm-up sample left the larger launches' compiles in
// the figure (a stand-in at 0.02x).
void warm_up_launch_shapes(render::OpenClRenderer& renderer) {
    for (int n = 1; n <= std::min(renderer.samples_in_flight(), 8); ++n) {
        renderer.set_samples_per_launch(n);
        renderer.add_samples(n);
    }
    renderer.set_samples_per_launch(1);
    renderer.reset();
}

Speed measure_speed(const opencl::Runtime& runtime, render::RenderInput input, double seconds) {
    render::OpenClRenderer renderer(runtime, input);
    warm_up_launch_shapes(renderer);
    report::render_for(renderer, seconds, [](double) {});
    render::RenderStatistics s = renderer.statistics();
    return Speed{s.paths_per_second(), s.paths ? double(s.rays) / double(s.paths) : 0.0};
}

// The default build and each variant in turn, `repeats` times; the best paths/s of each (the
// figure least disturbed by the rest of the machine).
std::vector<Speed> interleaved(const opencl::Runtime& runtime, const std::vector<render::RenderInput>& variants, const BenchBreakdownCommand& c) {
    std::vector<Speed> best(variants.size());
    for (int r = 0; r < c.repeats; ++r)
        for (size_t v = 0; v < variants.size(); ++v) {
            Speed s = measure_speed(runtime, variants[v], c.seconds);
            if (s.paths_per_second > best[v].paths_per_second) best[v] = s;
        }
    return best;
}

// The wavefront's launches over a render of `seconds`, each kind's share and time per sample.
void print_launch_times(const opencl::Runtime& runtime, const render::RenderInput& input, double seconds) {
    render::OpenClRenderer renderer(runtime, input);
    if (!renderer.wavefront()) {
        std::printf("  launches: no wavefront on this device (one work-item per path)\n");
        return;
    }
    warm_up_launch_shapes(renderer);
    bench::WavefrontLaunchTimer timer;
    renderer.observe_wavefront_launches(&timer);
    report::render_for(renderer, seconds, [](double) {});
    renderer.observe_wavefront_launches(nullptr);
    const bench::WavefrontLaunchTimes& t = timer.times();
    const int samples = renderer.statistics().samples_per_pixel;
    const double total = t.total();
    if (samples <= 0 || !(total > 0.0)) return;
    std::printf("  launches, share of the time and us per sample (%d samples, the host waiting for each):\n", samples);
    const std::pair<const char*, const bench::WavefrontLaunchTimes::Kind*> kinds[] = {
        {"camera steps", &t.camera_steps}, {"camera rays' packets", &t.camera_marches}, {"scatter steps", &t.scatter_steps},
        {"rays' and shadow rays' packets", &t.marches}, {"last steps", &t.last_steps}, {"resolves", &t.resolves}};
    for (const auto& [name, kind] : kinds)
        if (kind->launches > 0)
            std::printf("    %-31s %5.1f %%  %8.1f us  (%d launches)\n", name, 100.0 * kind->seconds / total, 1e6 * kind->seconds / samples,
                        kind->launches);
}

void run_bench_breakdown(const BenchBreakdownCommand& c) {
    check_render_seconds(c.seconds);
    check_repeats(c.repeats);
    for (int l : c.local_sizes)
        if (l < 1 || l > 4096) throw InputError("--local-sizes", "", "each size must be in [1, 4096]");
    opencl::Runtime runtime(c.job.device);
    std::printf("bench breakdown: %s, pt with MIS, %.1f s per figure, best of %d; device %s\n", c.job.size.c_str(), c.seconds, c.repeats,
                runtime.device().description().c_str());
    std::printf("(a scene with no light of its own is lit by envmaps/courtyard.exr)\n");
    for (const std::string& file : c.scenes) {
        RenderJobOptions o = c.job;
        o.scene = file;
        scene::Scene scene = scene::load_scene(file);
        if (!scene.environment && scene.emitters.empty() && scene.point_lights.empty()) o.default_env = "envmaps/courtyard.exr";
        RenderJob job = prepare_render_job(o);
        std::printf("\n%s\n", fs::path(file).filename().string().c_str());
        bench::MarchCost w = bench::measure_march_cost(runtime, job.input, c.count_samples);
        std::printf("  rays/path %.2f, march steps/ray %.1f, distance evaluations/step %.2f%s\n", w.rays_per_path, w.steps_per_ray,
                    w.evaluations_per_step, w.same_film ? "" : " (the counting build's film differs: figures doubtful)");

        const std::vector<std::string> parts{"RNG", "ENVIRONMENT", "BSDF"};
        std::vector<render::RenderInput> variants{job.input};
        for (const std::string& part : parts) {
            variants.push_back(job.input);
            bench::use_part_build(variants.back().settings.opencl, "BENCH_STANDIN_" + part);
        }
        variants.push_back(job.input);
        bench::use_part_build(variants.back().settings.opencl, "BENCH_TWICE_ENVIRONMENT");
        std::vector<Speed> s = interleaved(runtime, variants, c);
        std::printf("  default: %.3g paths/s, %.2f rays/path\n", s[0].paths_per_second, s[0].rays_per_path);
        // the share from rays/s: a stand-in that changes the path length (the grey Lambert BSDF) changes paths/s for that too
        for (size_t i = 0; i < 3; ++i) {
            double rays = s[i + 1].paths_per_second * s[i + 1].rays_per_path, default_rays = s[0].paths_per_second * s[0].rays_per_path;
            std::printf("  stand-in %-12s %.3g paths/s (%.2fx), %.2f rays/path, rays/s %.2fx: share of the time about %.0f %%\n", parts[i].c_str(),
                        s[i + 1].paths_per_second, s[i + 1].paths_per_second / s[0].paths_per_second, s[i + 1].rays_per_path,
                        rays / default_rays, 100.0 * (1.0 - default_rays / rays));
        }
        const Speed& twice = s[parts.size() + 1];
        std::printf("  environment twice    %.3g paths/s (%.2fx), %.2f rays/path: share of the time at most about %.0f %%\n", twice.paths_per_second,
                    twice.paths_per_second / s[0].paths_per_second, twice.rays_per_path,
                    100.0 * (s[0].paths_per_second / twice.paths_per_second - 1.0));
        print_launch_times(runtime, job.input, c.seconds);

        std::vector<render::RenderInput> sizes{job.input};
        for (int l : c.local_sizes) {
            sizes.push_back(job.input);
            sizes.back().settings.opencl.local_size = l;
        }
        std::vector<Speed> t = interleaved(runtime, sizes, c);
        std::printf("  work-group size, paths/s against 64:");
        for (size_t i = 0; i < c.local_sizes.size(); ++i) std::printf("  %d: %.2fx", c.local_sizes[i], t[i + 1].paths_per_second / t[0].paths_per_second);
        std::printf("\n");
        std::fflush(stdout);
    }
}

}  // namespace

void register_bench_breakdown(CLI::App& bench) {
    auto c = std::make_shared<BenchBreakdownCommand>();
    c->job.size = "96x96";
    auto* cmd = bench.add_subcommand("breakdown", "Where the path tracer's time goes: march steps per ray, evaluations per step, the share of "
                                                  "random numbers, environment sampling and BSDF, the wavefront's launches, and the work-group size");
    add_render_options(*cmd, &c->job);
    cmd->add_option("--scenes", c->scenes, "Scenes to break down")->capture_default_str();
    cmd->add_option("--local-sizes", c->local_sizes, "Work-group sizes to compare with the default 64")->capture_default_str();
    cmd->add_option("--seconds", c->seconds, "Render time of each figure")->capture_default_str();
    cmd->add_option("--repeats", c->repeats, "Interleaved repeats; the best of each is kept")->capture_default_str();
    cmd->callback([c] { run_bench_breakdown(*c); });
}

}  // namespace lab::cli
