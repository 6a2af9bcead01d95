#include "cli/report_study.hpp"

#include <cmath>
#include <cstdio>
#include <memory>

#include "cli/build_info.hpp"
#include "cli/render_job.hpp"
#include "common/input_error.hpp"
#include "common/read_text_file.hpp"
#include "opencl/runtime.hpp"
#include "plots/speed_accuracy_chart.hpp"
#include "plots/tradeoff_chart.hpp"
#include "render/integrator.hpp"
#include "report/html_page.hpp"
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

// One half of a paired render: `samples` samples per pixel with seed offset `half`.
struct PairedHalf {
    film::ImageRgb image;
    render::RenderStatistics stats;
};

PairedHalf render_half(const report::RendererFactory& make, render::RenderInput input, int half, int samples) {
    input.settings.seed += uint64_t(half) * 1000003u;
    std::unique_ptr<render::Renderer> renderer = make(input);
    renderer->set_samples_per_launch(samples);
    renderer->add_samples(samples);
    return {renderer->image(), renderer->statistics()};
}

// Sphere tracing's settings on a marched scene: over-relaxation 1, 1.5 and 1.8 by the tetrahedral,
// central and analytic normals, against the conservative setting: plain steps (over-relaxation 1)
// and central differences of a quarter of the default step. Every setting renders the same samples
// (the same seeds, the same count: what the conservative setting renders in the run's time) in two
// halves, so that report::paired_relative_error tells the error the setting causes from noise.
MarchSettingsStudy march_settings_study(const report::RendererFactory& make, const StudyOptions& o, const fs::path& folder) {
    MarchSettingsStudy study;
    study.scene = fs::path(o.march_scene).filename().string();
    RenderJobOptions job_options;
    job_options.scene = o.march_scene;
    job_options.size = o.size;
    if (!scene::has_own_light(scene::load_scene(o.march_scene))) job_options.default_env = o.env;
    RenderJob job = prepare_render_job(job_options);
    render::RenderInput baseline = job.input;
    baseline.settings.over_relaxation = 1.0f;
    baseline.settings.normals = render::NormalMethod::central;
    baseline.settings.normal_step = job.input.settings.normal_step / 4.0f;
    study.baseline_description = "plain sphere tracing (over-relaxation 1) with central-difference normals of step " +
                                 report::number_text(baseline.settings.normal_step, 3);
    std::printf("report: sphere-tracing settings, %s, against %s\n", study.scene.c_str(), study.baseline_description.c_str());
    std::fflush(stdout);
    // the sample count: what the baseline renders in a quarter of the run's time, per half
    {
        std::unique_ptr<render::Renderer> probe = make(baseline);
        probe->add_samples(1);
        probe->reset();
        report::render_for(*probe, o.budget.run_seconds / 4.0, [](double) {});
        study.samples_per_pixel = std::max(1, probe->statistics().samples_per_pixel);
    }
    const PairedHalf base[2] = {render_half(make, baseline, 1, study.samples_per_pixel), render_half(make, baseline, 2, study.samples_per_pixel)};
    std::vector<plots::TradeoffPoint> points;
    for (float over_relaxation : {1.0f, 1.5f, 1.8f}) {
        for (render::NormalMethod normals : {render::NormalMethod::tetrahedral, render::NormalMethod::central, render::NormalMethod::analytic}) {
            render::RenderInput input = job.input;
            input.settings.over_relaxation = over_relaxation;
            input.settings.normals = normals;
            const PairedHalf half[2] = {render_half(make, input, 1, study.samples_per_pixel), render_half(make, input, 2, study.samples_per_pixel)};
            const report::PairedError e = report::paired_relative_error(half[0].image, half[1].image, base[0].image, base[1].image);
            MarchSetting m;
            m.name = "ω " + report::number_text(over_relaxation, 2) + ", " + render::normal_method_name(normals);
            m.seconds_per_sample = (half[0].stats.render_seconds + half[1].stats.render_seconds) / (2.0 * study.samples_per_pixel);
            m.error = e.relative;
            m.noise = e.noise;
            const double rays = double(half[0].stats.rays + half[1].stats.rays);
            m.lost_rays = rays > 0.0 ? double(half[0].stats.lost_rays + half[1].stats.lost_rays) / rays : 0.0;
            study.noise_level = std::max(study.noise_level, m.noise);
            std::printf("  %-24s %8.3g ms per sample  error %.4g (noise %.4g), lost rays %.3g\n", m.name.c_str(), 1000.0 * m.seconds_per_sample,
                        m.error, m.noise, m.lost_rays);
            std::fflush(stdout);
            points.push_back({m.name, m.seconds_per_sample, m.error});
            study.settings.push_back(std::move(m));
        }
    }
    const std::string stem = "march_" + fs::path(o.march_scene).stem().string();
    study.image = "speed_" + stem + ".png";
    study.csv = "speed_" + stem + ".csv";
    plots::write_tradeoff_chart(points, study.noise_level, study.scene + ": sphere-tracing settings", "relative error against the conservative setting",
                                (folder / study.image).string(), (folder / study.csv).string());
    return study;
}

}  // namespace

StudyResults run_speed_accuracy_study(const StudyOptions& o, const fs::path& folder, std::string* device) {
    opencl::Runtime runtime(o.device);
    *device = runtime.device().description();
    report::RendererFactory make = [&runtime](const render::RenderInput& input) {
        return std::make_unique<render::OpenClRenderer>(runtime, input);
    };
    StudyResults results;
    std::vector<StudyComparison>& comparisons = results.comparisons;
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
    if (!o.march_scene.empty()) results.march = march_settings_study(make, o, folder);
    return results;
}

}  // namespace lab::cli
