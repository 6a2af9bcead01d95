// dtoadq bench objects: what the object bounds (scene/object_tree.hpp) buy. A march step of the
// plain field evaluates every object; with the box tests it evaluates the objects near the point
// and the tests on the way down the tree. The bench renders generated scenes of N objects (on a
// grid, under a constant sky) with the box tests off and on, fits the
// cost per path as a + b N to each, and prints b(on) / b(off): how much less each added object
// costs. Then the same on/off ratio of paths/s for the bundled scenes. Figures, not timed tests:
// every ratio is measured within the one run, the two modes interleaved.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "report/convergence.hpp"
#include "bench/grid.hpp"
#include "bench/timed_runs.hpp"
#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "render/opencl_renderer.hpp"
#include "scene/load_scene.hpp"

namespace lab::cli {
namespace {

namespace fs = std::filesystem;

struct BenchObjectsCommand {
    RenderJobOptions job;
    std::vector<int> counts{1, 2, 4, 8, 16, 32, 64};
    std::vector<std::string> scenes{"scenes/shader_ball.json", "scenes/cornell_box.json", "scenes/veach_mis.json", "scenes/metaballs.json",
                                    "scenes/repetition.json", "scenes/primitives.json"};
    double seconds = 1.5;
    int repeats = 2;
};

double paths_per_second(const opencl::Runtime& runtime, render::RenderInput input, bool bounds, double seconds) {
    input.settings.object_bounds = bounds;
    render::OpenClRenderer renderer(runtime, input);
    renderer.add_samples(1);  // PoCL compiles the work-group function at the first launch: not part of the figure
    renderer.reset();
    report::render_for(renderer, seconds, [](double) {});
    return renderer.statistics().paths_per_second();
}

// Off and on, interleaved `repeats` times; the best of each (the figure least disturbed by the rest
// of the machine).
void off_on(const opencl::Runtime& runtime, const render::RenderInput& input, const BenchObjectsCommand& c, double* off, double* on) {
    *off = *on = 0.0;
    for (int r = 0; r < c.repeats; ++r) {
        *off = std::max(*off, paths_per_second(runtime, input, false, c.seconds));
        *on = std::max(*on, paths_per_second(runtime, input, true, c.seconds));
    }
}

void run_bench_objects(const BenchObjectsCommand& c) {
    check_render_seconds(c.seconds);
    check_repeats(c.repeats);
    for (int n : c.counts)
        if (n < 1 || n > 4096) throw InputError("--counts", "", "each count must be in [1, 4096]");
    opencl::Runtime runtime(c.job.device);
    render::LightSelection selection;
    render::RenderSettings settings = checked_render_settings(c.job, &selection);
    std::printf("bench objects: %s, pt with MIS, %.1f s per figure; device %s\n\n", c.job.size.c_str(), c.seconds,
                runtime.device().description().c_str());
    std::printf("%8s %16s %16s %10s %18s %18s\n", "objects", "paths/s (off)", "paths/s (on)", "on/off", "us/path (off)", "us/path (on)");
    std::vector<double> n, cost_off, cost_on;
    for (int count : c.counts) {
        render::RenderInput input;
        input.scene = grid_scene(count);
        input.environment = ibl::Environment::constant(brdf::float3(0.8f, 0.85f, 1.0f), "constant", ibl::EnvironmentOptions{});
        input.settings = settings;
        input.light_selection = selection;
        double off, on;
        off_on(runtime, input, c, &off, &on);
        n.push_back(double(count));
        cost_off.push_back(1e6 / off);
        cost_on.push_back(1e6 / on);
        std::printf("%8d %16.3g %16.3g %9.2fx %18.3f %18.3f\n", count, off, on, on / off, cost_off.back(), cost_on.back());
        std::fflush(stdout);
    }
    double b_off = least_squares_slope(n, cost_off), b_on = least_squares_slope(n, cost_on);
    std::printf("\ncost per added object: %.4f us/path without the box tests, %.4f with them: %.2f of it (target: below 1/3)\n\n", b_off,
                b_on, b_on / b_off);

    std::printf("%-28s %16s %16s %10s\n", "scene", "paths/s (off)", "paths/s (on)", "on/off");
    for (const std::string& file : c.scenes) {
        RenderJobOptions o = c.job;
        o.scene = file;
        scene::Scene scene = scene::load_scene(file);
        if (!scene.environment && scene.emitters.empty() && scene.point_lights.empty()) o.default_env = "envmaps/courtyard.exr";
        RenderJob job = prepare_render_job(o);
        double off, on;
        off_on(runtime, job.input, c, &off, &on);
        std::printf("%-28s %16.3g %16.3g %9.2fx\n", fs::path(file).filename().string().c_str(), off, on, on / off);
        std::fflush(stdout);
    }
}

}  // namespace

void register_bench_objects(CLI::App& bench) {
    auto c = std::make_shared<BenchObjectsCommand>();
    c->job.size = "96x96";
    auto* cmd = bench.add_subcommand("objects", "Paths/s with and without the object bounds, against the number of objects and per bundled scene");
    add_render_options(*cmd, &c->job);
    cmd->add_option("--counts", c->counts, "Object counts of the generated grid scenes")->capture_default_str();
    cmd->add_option("--scenes", c->scenes, "Bundled scenes to compare with the box tests off and on")->capture_default_str();
    cmd->add_option("--seconds", c->seconds, "Render time of each figure")->capture_default_str();
    cmd->add_option("--repeats", c->repeats, "Interleaved repeats; the best of each is kept")->capture_default_str();
    cmd->callback([c] { run_bench_objects(*c); });
}

}  // namespace lab::cli
