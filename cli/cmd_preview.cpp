// dtoadq preview: the image-based-lighting path-traced preview of a material on the test model (or
// any scene) under an HDR environment, rendered progressively on OpenCL, written as a linear EXR
// with its metadata and a tone-mapped sRGB PNG.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "brdf/host/preset.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/preview_job.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "film/tone_map.hpp"
#include "ibl/environment.hpp"
#include "ibl/preview_renderer.hpp"
#include "ibl/preview_scene.hpp"
#include "opencl/runtime.hpp"

namespace lab::cli {
namespace {


struct PreviewCommand {
    PreviewJobOptions job;
    int spp = 64;
    bool spp_given = false;
    double time_seconds = 0.0;
    std::string output = "preview.exr";
    std::string tone_map = "aces";
    float exposure = 0.0f;
    bool quiet = false;
};

void run_preview(const PreviewCommand& c) {
    // Everything that can be wrong with the input is found before the first sample.
    film::check_output_path(c.output);
    if (is_exr_path(c.output)) film::check_output_path(png_beside(c.output));
    film::ToneMap tone_map = film::parse_tone_map(c.tone_map);
    if (!(c.time_seconds >= 0.0) || c.time_seconds > 1e6) throw InputError("--time", "", "must be in [0, 1e6] seconds");
    if (c.spp < 1 || c.spp > 1 << 24) throw InputError("--spp", "", "must be in [1, 16777216]");
    if (!(c.exposure >= -64.0f && c.exposure <= 64.0f)) throw InputError("--exposure", "", "must be a number of stops in [-64, 64]");
    PreviewJob job = prepare_preview_job(c.job);
    opencl::Runtime runtime(c.job.device);
    ibl::PreviewRenderer renderer(runtime, job.scene, job.environment, job.settings);
    if (!c.quiet)
        std::printf("%s on %s: kernel built in %.2f s\n", job.description.c_str(), runtime.device().description().c_str(),
                    renderer.build_seconds());
    std::fflush(stdout);
    for (const std::string& w : job.warnings) std::fprintf(stderr, "dtoadq: note: %s\n", w.c_str());

    RenderLimits limits;
    limits.samples = c.spp;
    limits.samples_given = c.spp_given;
    limits.seconds = c.time_seconds;
    limits.quiet = c.quiet;
    bool interrupted = render_progressively(renderer, limits);
    ibl::PreviewStatistics stats = renderer.statistics();
    film::ImageMetadata metadata = preview_metadata(job, stats, runtime.device().description());
    metadata.set("tonemap", c.tone_map);
    metadata.set("exposure", c.exposure);
    write_preview_images(c.output, renderer.image(), tone_map, c.exposure, metadata);
    std::printf("wrote %s%s\n", c.output.c_str(), is_exr_path(c.output) ? (" and " + png_beside(c.output)).c_str() : "");
    print_preview_statistics(stats, c.quiet);
    if (interrupted) {
        std::fprintf(stderr, "dtoadq: interrupted after %d samples per pixel; the image so far was written\n", stats.samples_per_pixel);
        throw CLI::RuntimeError(kInterruptedExitStatus);
    }
}

}  // namespace

void register_preview(CLI::App& app) {
    auto c = std::make_shared<PreviewCommand>();
    auto* cmd = app.add_subcommand("preview", "Path-traced image-based-lighting preview of a material on the test model (or a scene)");
    add_preview_job_options(*cmd, &c->job);
    cmd->add_option("--spp", c->spp, "Samples per pixel (with --time: at most this many)")->capture_default_str()
        ->each([c](const std::string&) { c->spp_given = true; });
    cmd->add_option("--time", c->time_seconds, "Render until this many seconds have passed, instead of a sample count");
    cmd->add_option("-o,--output", c->output, "Output .exr (linear, with a tone-mapped .png beside it) or .png")->capture_default_str();
    cmd->add_option("--tonemap", c->tone_map, "Tone map of the PNG: aces, reinhard or clamp")->capture_default_str();
    cmd->add_option("--exposure", c->exposure, "Exposure of the PNG in stops")->capture_default_str();
    cmd->add_flag("--quiet", c->quiet, "No progress bar or statistics");
    cmd->callback([c] { run_preview(*c); });
}

}  // namespace lab::cli
