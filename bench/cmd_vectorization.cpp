// dtoadq bench vectorization: whether PoCL vectorised a scene's render kernel across work-items,
// and why not. PoCL runs a kernel's work-items in loops over the work-group and hands those loops
// to LLVM's loop vectoriser; with POCL_VECTORIZER_REMARKS=1 LLVM says, per loop, "vectorized loop
// (vectorization width: N ...)" or "loop not vectorized: REASON". The command builds the kernel
// cold (an empty PoCL cache of its own, so the remarks are printed) with those remarks captured
// from its output, launches it once (PoCL compiles the work-group function at the first
// launch), and counts the remarks by width and by reason; then whether the marches run in the
// explicit packets of the path tracer's wavefront, which no remark reports. Figures for the
// CPU-speed work, not tests.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "render/opencl_renderer.hpp"

namespace lab::cli {
namespace {

namespace fs = std::filesystem;

struct BenchVectorizationCommand {
    RenderJobOptions job;
};

// Standard output and error go to `path` while this lives: PoCL prints the remarks from its own
// code (to standard output, PoCL 3.1).
class OutputToFile {
public:
    explicit OutputToFile(const fs::path& path) {
        std::fflush(stdout);
        std::fflush(stderr);
        saved_out_ = ::dup(1);
        saved_err_ = ::dup(2);
        int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (saved_out_ < 0 || saved_err_ < 0 || fd < 0) throw std::runtime_error("bench vectorization: cannot redirect the output");
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::close(fd);
    }
    ~OutputToFile() {
        std::fflush(stdout);
        std::fflush(stderr);
        ::dup2(saved_out_, 1);
        ::dup2(saved_err_, 2);
        ::close(saved_out_);
        ::close(saved_err_);
    }

private:
    int saved_out_ = -1, saved_err_ = -1;
};

void run_bench_vectorization(const BenchVectorizationCommand& c) {
    fs::path folder = fs::temp_directory_path() / ("dtoadq-vectorization-" + std::to_string(::getpid()));
    fs::create_directories(folder);
    // PoCL reads these when its platform is first made: before the runtime below.
    ::setenv("POCL_VECTORIZER_REMARKS", "1", 1);
    ::setenv("POCL_CACHE_DIR", folder.c_str(), 1);
    RenderJobOptions options = c.job;
    if (options.scene.empty()) options.default_env = "envmaps/courtyard.exr";
    RenderJob job = prepare_render_job(options);
    fs::path log = folder / "remarks.txt";
    std::string device;
    bool packets = false;
    {
        OutputToFile capture(log);
        opencl::Runtime runtime(c.job.device);
        device = runtime.device().description();
        render::OpenClRenderer renderer(runtime, job.input);
        renderer.add_samples(1);
        packets = renderer.wavefront();
    }
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    std::string all = text.str();
    std::map<int, int> widths;
    std::map<std::string, int> reasons;
    std::regex vectorized("vectorized loop \\(vectorization width: ([0-9]+)");
    std::regex not_vectorized("loop not vectorized: ([^<\\n]*)");
    for (auto it = std::sregex_iterator(all.begin(), all.end(), vectorized); it != std::sregex_iterator(); ++it)
        ++widths[std::stoi((*it)[1].str())];
    for (auto it = std::sregex_iterator(all.begin(), all.end(), not_vectorized); it != std::sregex_iterator(); ++it)
        ++reasons[(*it)[1].str()];
    std::printf("bench vectorization: %s on %s\n\n", job.description.c_str(), device.c_str());
    if (widths.empty() && reasons.empty())
        std::printf("no vectoriser remarks were printed: the device is not PoCL, or this PoCL does not print them\n");
    for (const auto& [width, count] : widths) std::printf("%6d loops vectorized with width %d\n", count, width);
    for (const auto& [reason, count] : reasons) std::printf("%6d loops not vectorized: %s\n", count, reason.c_str());
    // the explicit lanes do not depend on the vectoriser, and it says nothing of them
    if (packets)
        std::printf("\nexplicit lanes: the marches run as packets of 8 rays per work-item in float8 (kernels/march_packets.cl,\n"
                    "SDF_LANES=8), whatever the vectoriser made of the loops above; shading runs one path per work-item\n");
    else
        std::printf("\nno explicit lanes: every march runs one ray per work-item (the wavefront is the path tracer's, on a CPU device)\n");
    fs::remove_all(folder);
}

}  // namespace

void register_bench_vectorization(CLI::App& bench) {
    auto c = std::make_shared<BenchVectorizationCommand>();
    c->job.size = "16x16";
    auto* cmd = bench.add_subcommand("vectorization", "Whether PoCL vectorised a scene's render kernel across work-items, from its vectoriser remarks");
    cmd->add_option("--scene", c->job.scene, "Scene file (default: the test model under the courtyard)");
    add_render_options(*cmd, &c->job);
    cmd->callback([c] { run_bench_vectorization(*c); });
}

}  // namespace lab::cli
