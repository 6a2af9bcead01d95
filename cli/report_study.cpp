#include "cli/report_study.hpp"

#include <cstdio>
#include <memory>

#include "cli/build_info.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "common/read_text_file.hpp"
#include "opencl/runtime.hpp"
#include "plots/speed_accuracy_chart.hpp"
#include "render/integrator.hpp"
#include "render/opencl_renderer.hpp"
#include "report/reference_cache.hpp"
#include "scene/load_scene.hpp"

namespace lab::cli {

namespace fs = std::filesystem;

StudyBudget study_budget(const std::string& name) {
    // quick: the main job's, a minute or two in all; full: references of some ten times the samples
    if (name == "quick") return {name, 2.0, 16.0};
    if (name == "full") return {name, 10.0, 160.0};
    throw InputError("--budget", "", "must be quick or full, not '" + name + "'");
}

namespace {

// The key a cached reference is kept under: what it renders (its files' content: the scene or
// preset, and the environment's image), how, for how long, and by which build.
std::string reference_key(const std::vector<std::string>& files, const render::RenderInput& input, double seconds) {
    std::string key;
    for (const std::string& file : files)
        key += fs::path(file).filename().string() + " " + report::text_digest(read_text_file(file, uintmax_t(1) << 30, "input")) + ", ";
    char settings[160];
    std::snprintf(settings, sizeof settings, "%dx%d, max depth %d, seed %llu, %g s", input.settings.width, input.settings.height,
                  input.settings.max_depth, static_cast<unsigned long long>(input.settings.seed), seconds);
    return key + settings + ", dtoadq " + kBuildCommit;
}

StudyComparison compare(const report::RendererFactory& make, const StudyOptions& o, const fs::path& folder, const std::string& stem,
                        const std::string& subject, const std::vector<std::string>& files, const render::RenderInput& reference_input,
                        const std::vector<report::EqualTimeRun>& runs) {
    StudyComparison c;
    c.subject = subject;
    const std::string exr = (folder / "references" / (stem + ".exr")).string();
    std::printf("report: speed against accuracy, %s: reference (%g s) -> %s\n", stem.c_str(), o.budget.reference_seconds, exr.c_str());
    std::fflush(stdout);
    report::Reference reference =
        report::cached_reference(exr, reference_key(files, reference_input, o.budget.reference_seconds), make, reference_input,
                                 o.budget.reference_seconds, &c.reference_reused);
    c.reference_spp = reference.samples_per_pixel;
    c.reference_relative_noise = reference.relative_noise;
    c.results = report::run_equal_time(make, runs, reference, o.budget.run_seconds, report::ErrorMetric::relative_rmse);
    c.image = "speed_" + stem + ".png";
    c.csv = "speed_" + stem + ".csv";
    std::vector<plots::ConvergenceSeries> series;
    for (const report::EqualTimeResult& r : c.results) series.push_back(r.series);
    plots::write_speed_accuracy_chart(series, subject, (folder / c.image).string(), (folder / c.csv).string(),
                                      "relative RMSE against the reference");
    return c;
}

}  // namespace

std::vector<StudyComparison> run_speed_accuracy_study(const StudyOptions& o, const fs::path& folder, std::string* device) {
    opencl::Runtime runtime(o.device);
    *device = runtime.device().description();
    report::RendererFactory make = [&runtime](const render::RenderInput& input) {
        return std::make_unique<render::OpenClRenderer>(runtime, input);
    };
    std::vector<StudyComparison> comparisons;
    for (const std::string& preset : o.presets) {
        RenderJobOptions job_options;
        job_options.material = preset;
        job_options.env = o.env;
        job_options.size = o.size;
        RenderJob job = prepare_render_job(job_options);
        std::vector<report::EqualTimeRun> runs;
        for (render::LightSampling sampling : {render::LightSampling::bsdf, render::LightSampling::lights, render::LightSampling::mis}) {
            report::EqualTimeRun run{render::light_sampling_name(sampling), job.input};
            run.input.settings.light_sampling = sampling;
            runs.push_back(std::move(run));
        }
        std::vector<std::string> files{preset};
        if (fs::is_regular_file(o.env)) files.push_back(o.env);
        StudyComparison c = compare(make, o, folder, "preview_" + fs::path(preset).stem().string(),
                                    job.material_name + " on the test model under " + job.environment_name, files, job.input, runs);
        c.varies = "the preview's light sampling: the BSDF's sampler alone, the environment's alone, and both with MIS";
        c.baseline = "mis";
        c.reference_description = "MIS";
        comparisons.push_back(std::move(c));
    }
    for (const std::string& scene_file : o.scenes) {
        RenderJobOptions job_options;
        job_options.scene = scene_file;
        job_options.size = o.size;
        const scene::Scene scene = scene::load_scene(scene_file);
        if (!scene::has_own_light(scene)) job_options.default_env = o.env;
        RenderJob job = prepare_render_job(job_options);
        std::vector<report::EqualTimeRun> runs;
        for (render::Integrator integrator : {render::Integrator::bdpt, render::Integrator::lt, render::Integrator::pt}) {
            if (!render::integrator_descriptor(integrator).renders_environment() && job.input.environment) continue;
            report::EqualTimeRun run{render::integrator_name(integrator), job.input};
            run.input.settings.integrator = integrator;
            runs.push_back(std::move(run));
        }
        std::vector<std::string> files{scene_file};
        const std::string env = scene.environment ? scene.environment->file : job_options.default_env;
        if (!env.empty() && fs::is_regular_file(env)) files.push_back(env);
        StudyComparison c = compare(make, o, folder, "scene_" + fs::path(scene_file).stem().string(), fs::path(scene_file).filename().string(),
                                    files, job.input, runs);
        c.varies = "the integrator: bidirectional path tracing (every strategy, MIS), light tracing, and the path tracer";
        c.baseline = "pt";
        c.reference_description = "the path tracer with MIS, max depth " + std::to_string(job.input.settings.max_depth);
        comparisons.push_back(std::move(c));
    }
    return comparisons;
}

}  // namespace lab::cli
