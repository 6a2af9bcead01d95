// dtoadq render: a scene file rendered by one of the render core's integrators (`--integrator pt`:
// the path tracer with next-event estimation to every light and MIS), progressively, to a linear
// EXR with its metadata and a tone-mapped sRGB PNG. Same progress bar, --time, Ctrl-C and outputs
// as `preview`. With --frames, a sequence of renders over the scene's time (cli/render_sequence.hpp).
#include <memory>

#include "common/input_error.hpp"
#include "render/integrator.hpp"

#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "cli/render_sequence.hpp"
#include "cli/strategy_images.hpp"

namespace lab::cli {

void register_render(CLI::App& app) {
    auto job = std::make_shared<RenderJobOptions>();
    auto run = std::make_shared<RenderRunOptions>();
    auto strategies = std::make_shared<std::string>();
    auto sequence = std::make_shared<SequenceOptions>();
    run->output = "render.exr";
    auto* cmd = app.add_subcommand("render", "Render a scene file with one of the integrators (" + render::integrator_names() + ")");
    cmd->add_option("scene", job->scene, "Scene file (docs/scenes.md)")->required();
    cmd->add_option("--integrator", job->integrator, "Integrator: " + render::integrator_help())->capture_default_str();
    cmd->add_option("--mis", job->mis_heuristic, "bdpt, lt: MIS heuristic, balance or power")->capture_default_str();
    cmd->add_option("--light-sampling", job->light_sampling,
                    "How paths find lights: bsdf (BSDF sampling alone), lights (next-event estimation alone) or mis")
        ->capture_default_str();
    cmd->add_option("--material", job->material, "Material preset for the scene's \"sample\" slot, if it has one");
    add_render_options(*cmd, job.get());
    add_render_run_options(*cmd, run);
    cmd->add_option("--strategies", *strategies,
                    "bdpt, lt: also write one EXR per strategy (s, t), unweighted and MIS-weighted, with --spp samples each, and a "
                    "contact sheet, into this folder");
    add_sequence_options(*cmd, sequence);
    cmd->callback([job, run, strategies, sequence] {
        if (!sequence->frames.empty()) {
            if (!strategies->empty()) throw InputError("--strategies", "", "cannot be used with --frames");
            run_render_sequence(*job, *run, *sequence);
            return;
        }
        if (sequence->fps != 0.0 || !sequence->video.empty()) throw InputError(sequence->video.empty() ? "--fps" : "--video", "", "needs --frames A:B");
        if (!strategies->empty()) render::check_integrator_has_strategies(render::parse_integrator(job->integrator), "--strategies");
        if (!strategies->empty()) check_strategy_folder(*strategies);
        run_render_job(*job, *run);
        if (!strategies->empty()) write_strategy_images(prepare_render_job(*job), job->device, run->spp, *strategies, run->quiet);
    });
}

}  // namespace lab::cli
