// dtoadq report: the lab's main job on a folder of presets — overlaid lobe plots per group of
// materials, the albedo chart of all of them, the validation table, and a path-traced preview of
// each on the test model under an HDR environment — written to one folder, with index.html, the
// page that shows them with their captions and numbers (cli/report_page.hpp).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/render_job.hpp"
#include "cli/report_groups.hpp"
#include "report/atlas_geometry.hpp"
#include "report/stability_atlas.hpp"
#include "cli/report_page.hpp"
#include "cli/report_strategies.hpp"
#include "cli/report_study.hpp"
#include "scene/load_scene.hpp"
#include "common/input_error.hpp"
#include "opencl/runtime.hpp"
#include "render/interrupt.hpp"
#include "render/opencl_renderer.hpp"
#include "analysis/albedo_curve.hpp"
#include "analysis/lobe_data.hpp"
#include "plots/albedo_chart.hpp"
#include "plots/lobe_plot.hpp"
#include "plots/output_file.hpp"
#include "plots/preview_sheet.hpp"
#include "report/html_page.hpp"
#include "validation/report.hpp"

namespace fs = std::filesystem;

namespace lab::cli {
namespace {

struct ReportOptions {
    std::string out = "lab-report";
    std::string presets = "presets";
    std::vector<float> thetas{30.0f, 60.0f};
    long chi_square_samples = 1000000;
    bool preview = true;
    std::string env = "envmaps/courtyard.exr";
    std::string preview_size = "256x256";
    int preview_spp = 64;
    std::string scene = "scenes/cornell_box.json";  // rendered by BDPT on the render core
    std::string scene_integrator = "bdpt";
    int scene_spp = 32;
    std::string studio_scene = "scenes/studio.json";  // the look-dev studio's area lights, by the path tracer
    std::string studio_integrator = "pt";
    std::string device;
    // the speed-against-accuracy study (cli/report_study.hpp)
    bool study = true;
    bool full = false;  // --full: the full budget; else the quick one
    double study_seconds = 0.0, study_reference_seconds = 0.0;  // > 0: instead of the budget's
    std::string study_size = "128x128";
    std::vector<std::string> study_presets{"presets/glossy_plastic.json", "presets/brushed_aluminium.json"};
    std::vector<std::string> study_scenes{"scenes/cornell_box.json", "scenes/caustic.json"};
    std::string study_march_scene = "scenes/metaballs.json";  // empty: no sphere-tracing settings
    std::string atlas_scene = "scenes/metaballs.json";        // the stability atlas's sphere-tracing entries march it
    // the atlas's integrator entry (cli/report_strategies.hpp): a caustic and a glossy scene
    bool strategies = true;
    std::vector<std::string> strategy_scenes{"scenes/caustic.json", "scenes/veach_mis.json"};
};

// What an interrupted report says it finished.
struct ReportProgress {
    std::vector<std::string> finished;  // stages and presets done, in order
    std::string partial;                // the stage Ctrl-C cut short, if any
};

// Renders `spp` samples per pixel into `exr` (and the PNG beside it), and notes in `progress` what
// it finished, or what Ctrl-C cut short (written with the samples it holds; its EXR's metadata
// says how many). False when Ctrl-C came before the first sample: nothing was written.
bool render_report_image(render::Renderer& renderer, const RenderJob& job, int spp, const fs::path& exr, const std::string& what,
                         ReportProgress* progress, render::RenderStatistics* written_stats) {
    render::RenderLimits limits;
    limits.samples = spp;
    limits.quiet = true;
    render::ProgressiveOutcome outcome = render::render_progressively(renderer, limits);
    render::RenderStatistics stats = renderer.statistics();
    if (!outcome.failure.empty() && stats.samples_per_pixel == 0) render::fail_after_writing(outcome, 0, "");
    if (stats.samples_per_pixel == 0) return false;
    render::write_render_images(exr.string(), renderer.image(), film::ToneMap::Aces, 0.0f, job_metadata(job, renderer, stats));
    if (!outcome.failure.empty()) render::fail_after_writing(outcome, stats.samples_per_pixel, exr.string());
    render::print_render_statistics(stats, true);  // only the warnings
    *written_stats = stats;
    if (outcome.interrupted)
        progress->partial = what + " (" + std::to_string(stats.samples_per_pixel) + " of " + std::to_string(spp) + " samples per pixel, written)";
    else
        progress->finished.push_back(what);
    return true;
}

// One preview per preset, each its own kernel (a preset's kernel holds only the lobes it uses).
// Ctrl-C ends the preview being rendered, and no further preset is started.
ReportPreviews write_previews(const ReportOptions& o, const std::vector<brdf::Preset>& presets, const fs::path& out, ReportProgress* progress,
                              std::string* device) {
    ReportPreviews previews;
    previews.environment = fs::path(o.env).filename().string();
    previews.size = o.preview_size;
    previews.spp = o.preview_spp;
    std::vector<plots::SheetImage> sheet;
    opencl::Runtime runtime(o.device);
    for (const brdf::Preset& p : presets) {
        if (render::interrupt_requested()) break;
        RenderJobOptions job_options;
        job_options.material = p.source;
        job_options.env = o.env;
        job_options.size = o.preview_size;
        RenderJob job = prepare_render_job(job_options);
        std::string name = "preview_" + fs::path(p.source).stem().string();
        std::printf("report: preview of %s -> %s.png\n", p.name.c_str(), (out / name).c_str());
        std::fflush(stdout);
        render::OpenClRenderer renderer(runtime, job.input);
        *device = renderer.device_description();
        ReportRender render{p.name, name + ".png", {}};
        if (!render_report_image(renderer, job, o.preview_spp, out / (name + ".exr"), "the preview of " + p.name, progress, &render.stats)) break;
        previews.renders.emplace_back(p, render);
        sheet.push_back({p.name, (out / (name + ".png")).string()});
    }
    if (sheet.empty()) return previews;
    std::printf("report: preview sheet -> %s\n", (out / "previews.png").c_str());
    plots::write_preview_sheet(sheet, "Presets on the test model under " + fs::path(o.env).filename().string() + ", " +
                                          std::to_string(o.preview_spp) + " spp", (out / "previews.png").string());
    previews.sheet = "previews.png";
    return previews;
}

// A scene (--scene by --scene-integrator, --studio-scene by --studio-integrator) rendered at the
// previews' size with --scene-spp, written as scene_<stem>.exr/.png.
std::optional<ReportScene> write_scene_render(const ReportOptions& o, const std::string& file, const std::string& integrator, const fs::path& out,
                                              ReportProgress* progress, std::string* device) {
    RenderJobOptions job_options;
    job_options.scene = file;
    job_options.size = o.preview_size;
    job_options.integrator = integrator;
    RenderJob job = prepare_render_job(job_options);
    std::string name = "scene_" + fs::path(file).stem().string();
    std::printf("report: render of %s -> %s.png\n", file.c_str(), (out / name).c_str());
    std::fflush(stdout);
    std::optional<opencl::Runtime> runtime;
    std::unique_ptr<render::Renderer> renderer = make_renderer(job, o.device, &runtime);
    *device = renderer->device_description();
    ReportScene scene{integrator, o.preview_size, {fs::path(file).filename().string(), name + ".png", {}}};
    if (!render_report_image(*renderer, job, o.scene_spp, out / (name + ".exr"), "the render of " + fs::path(file).filename().string(), progress,
                             &scene.render.stats))
        return std::nullopt;
    return scene;
}

// Ctrl-C: one line saying what was finished, and the interrupted exit status. What was written
// stays; the page and the validation table are written only by a report that ran to its end.
void stop_if_interrupted(const ReportProgress& progress, const std::vector<brdf::Preset>& presets) {
    if (!render::interrupt_requested()) return;
    std::string finished;
    for (const std::string& f : progress.finished) finished += (finished.empty() ? "" : ", ") + f;
    std::fprintf(stderr, "dtoadq: report interrupted; finished: %s%s%s (%zu presets in all)\n",
                 finished.empty() ? "nothing" : finished.c_str(), progress.partial.empty() ? "" : "; cut short: ",
                 progress.partial.c_str(), presets.size());
    throw CLI::RuntimeError(render::kInterruptedExitStatus);
}

// The seconds per stage of the last report written into the folder (its timings.csv); empty when
// there is none or it cannot be read.
std::map<std::string, double> last_report_timings(const fs::path& csv) {
    std::map<std::string, double> seconds;
    std::ifstream in(csv);
    std::string line;
    if (!std::getline(in, line) || line != "stage,seconds") return {};
    while (std::getline(in, line)) {
        const size_t comma = line.rfind(',');
        if (comma == std::string::npos) return {};
        try {
            seconds[line.substr(0, comma)] = std::stod(line.substr(comma + 1));
        } catch (const std::exception&) {
            return {};
        }
    }
    return seconds;
}

void run_report(const ReportOptions& o) {
    render::InterruptScope interrupt_scope;  // Ctrl-C anywhere in the report: finish the step, say what was done
    ReportProgress progress;
    std::vector<brdf::Preset> presets = load_preset_folder(o.presets, "--presets");
    int width = 0, height = 0;
    render::parse_image_size(o.preview_size, "--preview-size", &width, &height);
    if (o.preview_spp < 1 || o.preview_spp > 1 << 20) throw InputError("--preview-spp", "", "must be in [1, 1048576]");
    if (o.preview && !fs::exists(o.env) && o.env.rfind("constant:", 0) != 0)
        throw InputError(o.env, "", "no such file (--env; run from the repository root, or pass --env)");
    if (o.preview && !o.scene.empty() && !fs::exists(o.scene))
        throw InputError(o.scene, "", "no such file (--scene; run from the repository root, or pass --scene)");
    if (o.preview && !o.studio_scene.empty() && !fs::exists(o.studio_scene))
        throw InputError(o.studio_scene, "", "no such file (--studio-scene; run from the repository root, or pass --studio-scene)");
    if (o.scene_spp < 1 || o.scene_spp > 1 << 20) throw InputError("--scene-spp", "", "must be in [1, 1048576]");
    if (o.study) {
        // 0: the budget's; else in (0, 3600] (NaN is refused)
        for (auto [seconds, option] : {std::pair{o.study_seconds, "--study-seconds"}, std::pair{o.study_reference_seconds, "--study-reference-seconds"}})
            if (seconds != 0.0 && !(seconds > 0.0 && seconds <= 3600.0)) throw InputError(option, "", "must be more than 0 and at most 3600");
        render::parse_image_size(o.study_size, "--study-size", &width, &height);
        for (const std::string& f : o.study_presets)
            if (!fs::exists(f)) throw InputError(f, "", "no such file (--study-presets; run from the repository root, or pass --study-presets)");
        for (const std::string& f : o.study_scenes)
            if (!fs::exists(f)) throw InputError(f, "", "no such file (--study-scenes; run from the repository root, or pass --study-scenes)");
        if (!o.study_march_scene.empty() && !fs::exists(o.study_march_scene))
            throw InputError(o.study_march_scene, "", "no such file (--study-march-scene; run from the repository root, or pass --study-march-scene)");
    }
    if (!fs::exists(o.atlas_scene))
        throw InputError(o.atlas_scene, "", "no such file (--atlas-scene; run from the repository root, or pass --atlas-scene)");
    for (const std::string& f : o.strategies ? o.strategy_scenes : std::vector<std::string>{}) {
        if (!fs::exists(f)) throw InputError(f, "", "no such file (--strategy-scenes; run from the repository root, or pass --strategy-scenes)");
        if (!scene::has_own_light(scene::load_scene(f)))
            throw InputError(f, "--strategy-scenes", "has no light of its own: the strategy atlas renders a scene under its own lights");
    }
    std::error_code ec;
    fs::create_directories(o.out, ec);
    if (ec || !fs::is_directory(o.out)) throw InputError(o.out, "-o", "cannot create the report folder");
    const fs::path out(o.out);
    // the stages, each announced with the time left as this folder's last report took it, and timed for the page
    std::vector<std::string> stages{"lobe plots", "albedo chart"};
    if (o.preview) stages.push_back("previews");
    if (o.preview && !o.scene.empty()) stages.push_back("scene render");
    if (o.preview && !o.studio_scene.empty()) stages.push_back("studio render");
    if (o.study) stages.push_back("speed against accuracy");
    stages.push_back("stability atlas");
    stages.push_back("validation");
    const std::map<std::string, double> last_seconds = last_report_timings(out / "timings.csv");
    std::vector<std::pair<std::string, double>> stage_seconds;
    auto stage_start = std::chrono::steady_clock::now();
    auto begin_stage = [&](const std::string& stage) {
        const size_t k = size_t(std::find(stages.begin(), stages.end(), stage) - stages.begin());
        double left = 0.0;
        bool known = true;
        for (size_t i = k; i < stages.size(); ++i) {
            auto it = last_seconds.find(stages[i]);
            known = known && it != last_seconds.end();
            if (known) left += it->second;
        }
        std::printf("report: stage %zu of %zu, %s", k + 1, stages.size(), stage.c_str());
        if (known) std::printf(" (about %.0f s left, as the last report in %s took)", left, o.out.c_str());
        std::printf("\n");
        std::fflush(stdout);
        stage_start = std::chrono::steady_clock::now();
    };
    auto end_stage = [&](const std::string& stage) {
        stage_seconds.emplace_back(stage, std::chrono::duration<double>(std::chrono::steady_clock::now() - stage_start).count());
    };

    std::vector<ReportLobes> lobes;
    begin_stage("lobe plots");
    for (const PresetGroup& group : group_presets(presets)) {
        for (float theta : o.thetas) {
            std::string name = "lobes_" + group.id + "_theta" + std::to_string(int(theta)) + ".png";
            std::printf("report: lobes of %s at %g degrees -> %s\n", group.title.c_str(), theta, (out / name).c_str());
            std::fflush(stdout);
            plots::write_lobe_plot(group.presets, theta, 0.0f, (out / name).string(), "");
            ReportLobes l{group.title, theta, name, {}};
            for (const brdf::Preset& p : group.presets) l.lobes.push_back(analysis::compute_lobe(p, theta, 0.0f, {}));
            lobes.push_back(std::move(l));
            stop_if_interrupted(progress, presets);
        }
    }
    progress.finished.push_back("the lobe plots");
    end_stage("lobe plots");
    begin_stage("albedo chart");
    std::printf("report: directional albedo of %zu presets -> %s\n", presets.size(), (out / "albedo.png").c_str());
    std::fflush(stdout);
    const analysis::AlbedoCurveOptions albedo_options;
    std::vector<std::vector<analysis::AlbedoPoint>> albedo_curves;
    for (const brdf::Preset& p : presets) albedo_curves.push_back(analysis::albedo_curve(p.material, albedo_options));
    plots::write_albedo_chart(presets, albedo_curves, (out / "albedo.png").string(), (out / "albedo.csv").string(), albedo_options);
    progress.finished.push_back("the albedo chart");
    end_stage("albedo chart");
    stop_if_interrupted(progress, presets);

    std::string device;
    ReportPreviews previews;
    std::vector<ReportScene> scenes;
    if (o.preview) {
        begin_stage("previews");
        previews = write_previews(o, presets, out, &progress, &device);
        end_stage("previews");
        stop_if_interrupted(progress, presets);
        if (!o.scene.empty()) {
            begin_stage("scene render");
            if (std::optional<ReportScene> scene = write_scene_render(o, o.scene, o.scene_integrator, out, &progress, &device)) scenes.push_back(*scene);
            end_stage("scene render");
            stop_if_interrupted(progress, presets);
        }
        if (!o.studio_scene.empty()) {
            begin_stage("studio render");
            if (std::optional<ReportScene> scene = write_scene_render(o, o.studio_scene, o.studio_integrator, out, &progress, &device))
                scenes.push_back(*scene);
            end_stage("studio render");
            stop_if_interrupted(progress, presets);
        }
    }

    StudyResults study;
    StudyBudget budget = study_budget(o.full ? "full" : "quick");
    if (o.study_seconds > 0.0) budget.run_seconds = o.study_seconds;
    if (o.study_reference_seconds > 0.0) budget.reference_seconds = o.study_reference_seconds;
    if (o.study) {
        begin_stage("speed against accuracy");
        StudyOptions study_options{budget, o.study_size, o.env, o.study_presets, o.study_scenes, o.study_march_scene, o.device};
        study = run_speed_accuracy_study(study_options, out, &device);
        progress.finished.push_back("the speed-against-accuracy study");
        end_stage("speed against accuracy");
        stop_if_interrupted(progress, presets);
    }

    begin_stage("stability atlas");
    std::printf("report: stability atlas -> %s\n", (out / "atlas_energy.png").c_str());
    std::fflush(stdout);
    // the BRDF entries run on one thread and wait on Python for their charts, the geometry entries
    // march on every core: side by side they take little more than the longer of the two
    std::future<std::vector<report::AtlasEntry>> geometry = std::async(std::launch::async, [&] { return report::write_geometry_atlas(out, o.atlas_scene); });
    std::vector<report::AtlasEntry> atlas = report::write_stability_atlas(out);
    for (report::AtlasEntry& e : geometry.get()) atlas.push_back(std::move(e));
    if (o.strategies) {
        StrategyAtlasOptions strategy_options;
        strategy_options.scenes = o.strategy_scenes;
        strategy_options.spp = o.full ? 128 : 16;
        strategy_options.device = o.device;
        atlas.push_back(strategy_atlas_entry(write_strategy_atlas(strategy_options, out, &device)));
    }
    progress.finished.push_back("the stability atlas");
    end_stage("stability atlas");
    stop_if_interrupted(progress, presets);

    validation::ValidationOptions options;
    options.chi_square_samples = o.chi_square_samples;
    std::vector<validation::MaterialValidation> results;
    begin_stage("validation");
    for (const brdf::Preset& p : presets) {
        std::printf("report: validating %s\n", p.name.c_str());
        std::fflush(stdout);
        results.push_back(validation::validate_material(p, options));
        progress.finished.push_back("the validation of " + p.name);
        stop_if_interrupted(progress, presets);
    }
    end_stage("validation");
    std::ostringstream table;
    validation::print_validation_table(table, results);
    std::printf("\n%s\n", table.str().c_str());
    plots::open_output((out / "validation.txt").string(), "-o") << table.str();

    report::Page page;
    page.title = "DTOADQ lab report";
    page.subtitle = std::to_string(presets.size()) + " material presets from " + o.presets + ".";
    if (o.preview) page.sections.push_back(previews_section(previews, out));
    page.sections.push_back(lobes_section(lobes, out));
    page.sections.push_back(albedo_section(presets, albedo_curves, albedo_options, "albedo.png", "albedo.csv"));
    page.sections.push_back(validation_section(results, options, out));
    if (!scenes.empty()) page.sections.push_back(scene_section(scenes, out));
    if (o.study) page.sections.push_back(speed_section(study, budget, o.study_size, out));
    page.sections.push_back(atlas_section(atlas, out));
    page.sections.push_back(machine_section(device, stage_seconds, out));
    report::write_page(page, (out / "index.html").string());
    std::printf("report: wrote %s\n", (out / "index.html").c_str());

    // a lab-model preset failing a physical check is a defect; the 2017 model is expected to fail
    int unexpected = 0;
    for (const validation::MaterialValidation& r : results)
        if (!r.passed() && r.model != BRDF_MODEL_DTOADQ2017) ++unexpected;
    if (unexpected > 0) {
        std::fprintf(stderr, "dtoadq: error: %d lab-model preset(s) failed a physical check (see %s)\n", unexpected,
                     (out / "index.html").c_str());
        throw CLI::RuntimeError(1);
    }
}

}  // namespace

void register_report(CLI::App& app) {
    auto options = std::make_shared<ReportOptions>();
    auto* cmd = app.add_subcommand("report", "Lobe plots, albedo chart, validation and previews of every preset, written to one folder with index.html, the page that shows them");
    cmd->add_option("-o,--output", options->out, "Folder to write the report into")->capture_default_str();
    cmd->add_option("--presets", options->presets, "Folder of material presets (JSON)")->capture_default_str();
    cmd->add_option("--theta-in", options->thetas, "Incident angles of the lobe plots, degrees")->capture_default_str();
    cmd->add_option("--samples", options->chi_square_samples, "Samples per chi-square test")->capture_default_str();
    cmd->add_option("--env", options->env, "Environment of the previews: .exr/.hdr or constant:R,G,B")->capture_default_str();
    cmd->add_option("--preview-size", options->preview_size, "Preview image size WxH")->capture_default_str();
    cmd->add_option("--preview-spp", options->preview_spp, "Preview samples per pixel")->capture_default_str();
    cmd->add_option("--scene", options->scene, "Scene rendered after the previews (empty: none)")->capture_default_str();
    cmd->add_option("--scene-integrator", options->scene_integrator, "Integrator of the scene render: bdpt, pt or lt")->capture_default_str();
    cmd->add_option("--scene-spp", options->scene_spp, "Samples per pixel of the scene renders (--scene and --studio-scene)")->capture_default_str();
    cmd->add_option("--studio-scene", options->studio_scene, "Look-dev studio rendered after --scene: area lights, no environment (empty: none)")
        ->capture_default_str();
    cmd->add_option("--studio-integrator", options->studio_integrator, "Integrator of the studio render: pt, bdpt or lt")->capture_default_str();
    cmd->add_flag("!--no-preview", options->preview, "Skip the path-traced previews and the scene render");
    auto* quick = cmd->add_flag("--quick", "The speed-against-accuracy study's quick budget: 2 s per run, 16 s references (the default)");
    auto* full = cmd->add_flag("--full", options->full, "The study's full budget: 10 s per run, 160 s references");
    quick->excludes(full);
    cmd->add_flag("!--no-study", options->study, "Skip the speed-against-accuracy study");
    cmd->add_option("--study-seconds", options->study_seconds, "Seconds per run of the study, instead of the budget's");
    cmd->add_option("--study-reference-seconds", options->study_reference_seconds, "Seconds per reference of the study, instead of the budget's");
    cmd->add_option("--study-size", options->study_size, "Image size of the study's renders")->capture_default_str();
    cmd->add_option("--study-presets", options->study_presets, "Presets whose preview's light sampling the study compares")->capture_default_str();
    cmd->add_option("--study-scenes", options->study_scenes, "Scenes whose integrators the study compares")->capture_default_str();
    cmd->add_option("--strategy-scenes", options->strategy_scenes,
                    "Scenes whose BDPT strategies the stability atlas maps, each under its own lights")
        ->capture_default_str();
    cmd->add_flag("!--no-strategies", options->strategies, "Leave the stability atlas's map of BDPT's strategies out");
    cmd->add_option("--study-march-scene", options->study_march_scene, "Scene whose sphere-tracing settings the study compares (empty: none)")
        ->capture_default_str();
    cmd->add_option("--atlas-scene", options->atlas_scene, "Scene of the stability atlas's sphere-tracing entries, beside a displaced sphere")
        ->capture_default_str();
    cmd->add_option("--device", options->device, "OpenCL device of the previews (dtoadq devices lists them)");
    cmd->callback([options] { run_report(*options); });
}

}  // namespace lab::cli
