// dtoadq bench compare --to OLD_BINARY: paths/s of this build against another build of dtoadq on the
// same scenes in one run, as a ratio. Each build renders each scene with `render --time` as a
// child process, the two interleaved and repeated, and the paths/s come from what every render
// writes into its EXR (dtoadq:spp and dtoadq:seconds, which every build with the render core
// writes), so the other build needs no new option to be measured. The median of the repeats is
// reported, and the median of each repeat's own ratio with its range.
// Then the same for `bench objects`' grids of N objects (bench/grid.hpp), written as scene
// files for both builds: the cost per path of one more object in each build, fitted over N, and
// their ratio.
// Figures, not timed tests.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bench/grid.hpp"
#include "bench/timed_runs.hpp"
#include "cli/commands.hpp"
#include "common/input_error.hpp"
#include "film/image_metadata.hpp"
#include "film/image_output.hpp"
#include "scene/load_scene.hpp"

namespace lab::cli {
namespace {

namespace fs = std::filesystem;

struct BenchCompareCommand {
    std::string other;
    std::vector<std::string> scenes{"scenes/shader_ball.json", "tools/bench_scenes/sphere.json", "scenes/cornell_box.json",
                                    "scenes/repetition.json", "scenes/primitives.json"};
    std::string size = "128x128";
    double seconds = 3.0;
    int repeats = 3;
    std::vector<std::string> extra;  // more arguments for both builds' render
    std::vector<int> object_counts{1, 2, 4, 8, 16, 32, 64};
    bool objects = true;
};

// Runs `argv` with standard output and error sent to /dev/null; its exit status, or -1.
int run_quietly(const std::vector<std::string>& argv) {
    pid_t pid = ::fork();
    if (pid < 0) return -1;
    if (pid == 0) {
        std::FILE* null = std::fopen("/dev/null", "w");
        if (null) {
            ::dup2(::fileno(null), 1);
            ::dup2(::fileno(null), 2);
        }
        std::vector<char*> args;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        ::execv(args[0], args.data());
        ::_exit(127);
    }
    int status = 0;
    if (::waitpid(pid, &status, 0) < 0) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int metadata_int(const film::ImageMetadata& m, const std::string& key, const std::string& file) {
    const film::MetadataValue* v = m.find(key);
    if (!v) throw InputError(file, "dtoadq:" + key, "missing: not a render of dtoadq");
    if (const int* i = std::get_if<int>(v)) return *i;
    return std::stoi(film::metadata_text(*v));
}

// paths/s of one `render --time` of `exe`, from its EXR's metadata.
double render_paths_per_second(const std::string& exe, const BenchCompareCommand& c, const std::string& scene, const fs::path& out,
                               double seconds) {
    std::vector<std::string> argv = {exe, "render", scene, "--size", c.size, "--time", std::to_string(seconds), "--quiet", "-o", out.string()};
    // lit like the other benches: a scene with no light of its own under envmaps/courtyard.exr
    scene::Scene loaded = scene::load_scene(scene);
    if (!scene::has_own_light(loaded)) argv.insert(argv.end(), {"--env", "envmaps/courtyard.exr"});
    argv.insert(argv.end(), c.extra.begin(), c.extra.end());
    fs::remove(out);
    int status = run_quietly(argv);
    if (status != 0) throw InputError(exe, "", "render " + scene + " failed (exit status " + std::to_string(status) + ")");
    film::ImageMetadata m;
    film::ImageRgb image = film::read_image(out.string(), &m);
    int spp = metadata_int(m, "spp", out.string());
    const film::MetadataValue* rendered = m.find("seconds");
    double s = rendered && std::holds_alternative<float>(*rendered) ? double(std::get<float>(*rendered)) : 0.0;
    if (!(s > 0.0)) throw InputError(out.string(), "dtoadq:seconds", "missing or not positive");
    return double(spp) * double(image.width) * double(image.height) / s;
}

void run_bench_compare(const BenchCompareCommand& c) {
    if (::access(c.other.c_str(), X_OK) != 0) throw InputError(c.other, "", "is not an executable file");
    check_render_seconds(c.seconds);
    check_repeats(c.repeats);
    for (int n : c.object_counts)
        if (n < 1 || n > 4096) throw InputError("--object-counts", "", "each count must be in [1, 4096]");
    std::string self = fs::read_symlink("/proc/self/exe").string();
    fs::path folder = fs::temp_directory_path() / ("dtoadq-bench-compare-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    std::printf("bench compare: this build (%s) against %s; %s, render --time %.1f s, median of %d, interleaved\n", self.c_str(),
                c.other.c_str(), c.size.c_str(), c.seconds, c.repeats);
    std::printf("paired: the median of each repeat's ratio (the two renders of a repeat one after the other, in alternating\n"
                "order), with the least and greatest of them: the spread is this machine's noise\n\n");
    std::printf("%-28s %16s %16s %10s %10s %15s\n", "scene", "paths/s (this)", "paths/s (other)", "this/other", "paired", "(range)");
    // both builds' median paths/s of one scene file, printed as a row: {this build's, the other's}
    auto both = [&](const std::string& scene, const std::string& name) {
        // PoCL compiles a kernel's work-group function at its first launch of each shape (the
        // global size's class among them), into its cache, so that no figure may pay for it: two
        // renders of each build first. In the first, a cold compile takes the whole time of its
        // first launch, and the launches stay at one sample; in the second, they double (up to
        // some 0.125 s each) to their largest shapes, compiling those. One render of 0.01 s leaves the
        // larger launches' compiles in the first repeat (a grid of 64 objects at 0.62x, one repeat at
        // 0.05x); so does one render of 0.5 s after a change of the kernels.
        const double warm_up = std::min(c.seconds, 0.5);
        for (int w = 0; w < 2; ++w) {
            render_paths_per_second(c.other, c, scene, folder / "other.exr", warm_up);
            render_paths_per_second(self, c, scene, folder / "this.exr", warm_up);
        }
        std::vector<double> mine, theirs, paired;
        for (int r = 0; r < c.repeats; ++r) {
            // alternating which build goes first, so that a drift of the machine's speed within a
            // repeat favours neither
            if (r % 2 == 0) theirs.push_back(render_paths_per_second(c.other, c, scene, folder / "other.exr", c.seconds));
            mine.push_back(render_paths_per_second(self, c, scene, folder / "this.exr", c.seconds));
            if (r % 2 == 1) theirs.push_back(render_paths_per_second(c.other, c, scene, folder / "other.exr", c.seconds));
            paired.push_back(mine.back() / theirs.back());
        }
        const std::pair<double, double> medians{median(mine), median(theirs)};
        const auto [least, greatest] = std::minmax_element(paired.begin(), paired.end());
        std::printf("%-28s %16.3g %16.3g %9.2fx %9.2fx %6.2f-%.2fx\n", name.c_str(), medians.first, medians.second, medians.first / medians.second,
                    median(paired), *least, *greatest);
        std::fflush(stdout);
        return medians;
    };
    for (const std::string& scene : c.scenes) both(scene, fs::path(scene).filename().string());
    if (c.objects && c.object_counts.size() >= 2) {
        std::printf("\n");
        std::vector<double> n, mine, theirs;  // us/path
        for (int count : c.object_counts) {
            fs::path file = folder / ("grid_" + std::to_string(count) + ".json");
            std::ofstream(file) << grid_scene_json(count).dump(1);
            const auto [this_build, other_build] = both(file.string(), "grid of " + std::to_string(count) + " objects");
            n.push_back(double(count));
            mine.push_back(1e6 / this_build);
            theirs.push_back(1e6 / other_build);
        }
        double slope_mine = least_squares_slope(n, mine), slope_theirs = least_squares_slope(n, theirs);
        std::printf("\ncost per added object: %.4f us/path in this build, %.4f in the other: %.2f of it\n", slope_mine, slope_theirs,
                    slope_mine / slope_theirs);
    }
    fs::remove_all(folder);
}

}  // namespace

void register_bench_compare(CLI::App& bench) {
    auto c = std::make_shared<BenchCompareCommand>();
    auto* cmd = bench.add_subcommand("compare", "Paths/s of this build against another dtoadq binary on the same scenes, as a ratio");
    cmd->add_option("--to", c->other, "The other dtoadq binary (an older build)")->required();
    cmd->add_option("--scenes", c->scenes, "Scene files to render")->capture_default_str();
    cmd->add_option("--size", c->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--seconds", c->seconds, "Render time of each figure")->capture_default_str();
    cmd->add_option("--repeats", c->repeats, "Renders per build and scene (the median is reported)")->capture_default_str();
    cmd->add_option("--object-counts", c->object_counts, "Object counts of the generated grid scenes (bench objects')")->capture_default_str();
    cmd->add_flag("!--no-objects", c->objects, "Leave out the grids and the cost per added object");
    cmd->add_option("--render-args", c->extra, "More arguments for both builds' render (e.g. --device host)")->allow_extra_args(false);
    cmd->callback([c] { run_bench_compare(*c); });
}

}  // namespace lab::cli
