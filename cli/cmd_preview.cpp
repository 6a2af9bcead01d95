// dtoadq preview: the image-based-lighting path-traced preview of a material on the test model (or
// any scene) under an HDR environment: the path tracer of the render core (kernels/path_tracer.h),
// rendered progressively, written as a linear EXR with its metadata and a tone-mapped sRGB PNG.
#include <memory>

#include "cli/commands.hpp"
#include "cli/render_job.hpp"

namespace lab::cli {

void register_preview(CLI::App& app) {
    auto job = std::make_shared<RenderJobOptions>();
    job->default_env = "constant:1,1,1";  // a material shows under white light when nothing else is given
    auto run = std::make_shared<RenderRunOptions>();
    run->output = "preview.exr";
    auto* cmd = app.add_subcommand("preview", "Path-traced image-based-lighting preview of a material on the test model (or a scene)");
    add_preview_options(*cmd, job.get());
    add_render_options(*cmd, job.get());
    add_render_run_options(*cmd, run);
    cmd->callback([job, run] {
        film::ImageMetadata extra;
        extra.set("ibl_sampling", job->light_sampling);
        run_render_job(*job, *run, extra);
    });
}

}  // namespace lab::cli
