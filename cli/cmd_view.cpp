// dtoadq view: the live viewer (viewer/, docs/viewer.md). This file turns the options into a
// render job (cli/render_job, as `preview` does), checks everything a script asks for before the
// window opens, and hands the viewer its renderer factory.
#include <algorithm>
#include <cstdio>
#include <iterator>
#include <memory>
#include <mutex>
#include <optional>

#include "brdf/host/preset.hpp"
#include "cli/commands.hpp"
#include "cli/render_job.hpp"
#include "cli/turntable.hpp"
#include "common/input_error.hpp"
#include "scene/look_dev_references.hpp"
#include "scene/test_model.hpp"
#include "viewer/app.hpp"
#include "viewer/material_edit.hpp"
#include "render/aov_layers.hpp"
#include "render/progressive.hpp"
#include "viewer/material_export.hpp"
#include "viewer/scene_export.hpp"
#include "viewer/view_modes.hpp"
#include "viewer/window_layout.hpp"

namespace lab::cli {

namespace {

struct ViewOptions {
    RenderJobOptions job;
    std::string compare, slot, screenshot, save_preset, export_to, tone_map = "aces", window, display = "render", denoise = "on";
    std::vector<std::string> sets, moves, inspect, env_loads, reference_loads, resizes, open_sections, view_modes;
    long max_render_pixels = 512 * 512;
    TurntableOptions turntable;
    int frames = 0, min_spp = 1, max_spp = 1 << 16;
    double chunk_ms = 33.0;
    float exposure = 0.0f;
    float error_threshold = 0.05f;
    std::string save_exr, save_layers;
    bool stats = false, split = false, print_layout = false;
};

int find_slot(const scene::Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name) return int(i);
    return -1;
}

// --window and --resize: a size the window can take (the panel and a sliver of render beside it).
void parse_window_size(const std::string& text, const std::string& option, int* width, int* height) {
    render::parse_image_size(text, option, width, height);
    if (*width < viewer::kSmallestWindowWidth || *height < viewer::kSmallestWindowHeight)
        throw InputError(option, "", text + " is smaller than the panel and a render beside it (" + std::to_string(viewer::kSmallestWindowWidth) +
                                         "x" + std::to_string(viewer::kSmallestWindowHeight) + " at least)");
}

const char* const kSectionNames[] = {"Material", "Checks", "Lobe", "Environment", "Presets", "Inspector", "Help", "all"};

void run_view(const ViewOptions& o) {
    if (o.turntable.frames != 0) {  // headless: no window
        TurntableOptions t = o.turntable;
        t.tone_map = o.tone_map;
        t.exposure = o.exposure;
        render_turntable(o.job, t);
        return;
    }
    film::ToneMap tone_map = film::parse_tone_map(o.tone_map);
    if (o.frames < 0 || o.frames > 10000000) throw InputError("--frames", "", "must be in [0, 10000000]");
    if (o.min_spp < 1 || o.min_spp > o.max_spp) throw InputError("--min-spp", "", "must be in [1, --max-spp]");
    if (o.max_spp < 1 || o.max_spp > 1 << 24) throw InputError("--max-spp", "", "must be in [1, 16777216]");
    if (!(o.chunk_ms >= 1.0 && o.chunk_ms <= 10000.0)) throw InputError("--chunk-ms", "", "must be in [1, 10000] ms");
    if (!(o.exposure >= -64.0f && o.exposure <= 64.0f)) throw InputError("--exposure", "", "must be a number of stops in [-64, 64]");
    std::vector<viewer::ScriptedSet> sets;
    for (const std::string& s : o.sets) sets.push_back(viewer::parse_scripted_set(s));
    if (!sets.empty() && o.frames == 0) throw InputError("--set", "", "needs --frames (a scripted run)");
    if (!o.screenshot.empty()) render::check_render_output(o.screenshot);
    std::string export_scene, export_name;
    std::string export_material;
    if (viewer::is_material_file_target(o.export_to))
        export_material = o.export_to;
    else if (!o.export_to.empty())
        viewer::parse_export_target(o.export_to, &export_scene, &export_name);

    auto job = std::make_shared<RenderJob>(prepare_render_job(o.job));  // a bad preset, scene or environment stops here
    const scene::Scene& scene = job->input.scene;
    viewer::ViewerConfig config;
    config.edited_slot = find_slot(scene, o.slot.empty() ? scene::kSampleMaterialSlot : o.slot);
    if (config.edited_slot < 0) {
        if (!o.slot.empty()) throw InputError(scene.file, "materials", "no material \"" + o.slot + "\" (--slot)");
        config.edited_slot = 0;
    }
    config.preset.name = o.job.material.empty() ? scene.materials[size_t(config.edited_slot)].name : job->material_name;
    config.preset.source = o.job.material.empty() ? scene.file : o.job.material;
    for (const scene::MaterialSlot& slot : scene.materials) config.initial.materials.push_back(slot.material);
    config.preset.material = config.initial.materials[size_t(config.edited_slot)];
    config.initial.camera = scene.camera;
    config.scene = scene;
    config.base_scene = job->base_scene;
    config.references = scene::parse_look_dev_references(job->references, "--references");  // --shadow-catcher's included
    if (job->input.environment) {
        config.initial.env_rotation_degrees = job->input.environment->rotation_degrees();
        config.initial.env_exposure_stops = job->input.environment->exposure_stops();
    }
    config.initial.background_opacity = job->input.settings.background_opacity;
    config.initial.background_blur_degrees = job->input.settings.background_blur_degrees;
    config.compare = o.compare.empty() ? config.preset : brdf::load_preset(o.compare);
    // Every scripted change is tried once now, so a bad key or value stops before the window opens.
    brdf::Preset trial = config.preset;
    for (const viewer::ScriptedSet& s : sets) trial = viewer::with_parameter(trial, s.key, s.value, "--set");

    config.width = job->input.settings.width;
    config.height = job->input.settings.height;
    config.initial.width = config.width;
    config.initial.height = config.height;
    if (!o.window.empty()) parse_window_size(o.window, "--window", &config.window_width, &config.window_height);
    config.sizing = viewer::parse_display_sizing(o.display);
    if (o.max_render_pixels < 64 || o.max_render_pixels > 16384L * 16384L)
        throw InputError("--max-render-pixels", "", "must be in [64, 268435456]");
    config.max_render_pixels = o.max_render_pixels;
    for (const std::string& text : o.resizes) {
        viewer::ScriptedSet resize = viewer::parse_scripted_set("window=" + text);  // WxH@FRAME
        if (o.frames == 0) throw InputError("--resize", "", "needs --frames (a scripted run)");
        int w = 0, h = 0;
        parse_window_size(resize.value, "--resize", &w, &h);
        config.resizes.push_back(resize);
    }
    for (const std::string& name : o.open_sections) {
        if (std::find(std::begin(kSectionNames), std::end(kSectionNames), name) == std::end(kSectionNames))
            throw InputError("--open", "", "unknown section \"" + name + "\" (Material, Checks, Lobe, Environment, Presets, Inspector, Help, all)");
        config.open_sections.push_back(name);
    }
    config.title = "dtoadq view: " + job->description;
    config.max_samples = o.max_spp;
    config.chunk_seconds = o.chunk_ms * 1e-3;
    config.tone_map = tone_map;
    config.display_exposure = o.exposure;
    config.denoise = parse_on_off(o.denoise, "--denoise");
    config.frames = o.frames;
    config.sets = sets;
    for (const std::string& text : o.moves) {
        viewer::ScriptedSet move = viewer::parse_scripted_set(text);
        if (o.frames == 0) throw InputError("--move", "", "needs --frames (a scripted run)");
        viewer::ViewState trial_state = config.initial;
        viewer::apply_move(&trial_state, move.key, move.value);  // a bad key or value stops before the window opens
        config.moves.push_back(move);
    }
    config.min_samples = o.min_spp;
    for (const std::string& text : o.env_loads) {
        viewer::ScriptedSet load = viewer::parse_scripted_set("env=" + text);  // PATH@FRAME
        if (o.frames == 0) throw InputError("--load-env", "", "needs --frames (a scripted run)");
        config.env_loads.push_back(load);
    }
    for (const std::string& text : o.reference_loads) {
        viewer::ScriptedSet load = viewer::parse_scripted_set("references=" + text);  // LIST@FRAME
        if (o.frames == 0) throw InputError("--load-references", "", "needs --frames (a scripted run)");
        scene::parse_look_dev_references(load.value, "--load-references");
        config.reference_loads.push_back(load);
    }
    for (const std::string& text : o.view_modes) {
        viewer::ScriptedSet mode = viewer::parse_scripted_set("view=" + text);  // NAME@FRAME
        viewer::parse_view_mode(mode.value, "--view-mode");
        if (o.frames == 0 && mode.frame > 0) throw InputError("--view-mode", "", "NAME@FRAME needs --frames (a scripted run)");
        config.view_modes.push_back(mode);
    }
    if (!(o.error_threshold > 0.0f && o.error_threshold <= 1e6f))
        throw InputError("--error-threshold", "", "must be a relative standard error above 0, at most 1e6");
    config.relative_error_threshold = o.error_threshold;
    if (!o.save_exr.empty()) {
        if (o.frames == 0) throw InputError("--save-exr", "", "needs --frames (a scripted run; the panel's \"save EXR\" saves by hand)");
        config.save_exr = o.save_exr;
        config.save_layers = render::parse_aov_selection(o.save_layers, o.save_exr, "--save-layers");
        if (!render::is_exr_path(o.save_exr)) throw InputError("--save-exr", "", o.save_exr + " is not an .exr");
    } else if (!o.save_layers.empty()) {
        throw InputError("--save-layers", "", "needs --save-exr");
    }
    for (const std::string& text : o.inspect) {
        int x = -1, y = -1;
        char tail = 0;
        if (std::sscanf(text.c_str(), "%d,%d%c", &x, &y, &tail) != 2 || x < 0 || y < 0 || x >= config.width || y >= config.height)
            throw InputError("--inspect", "", "expected X,Y inside the " + std::to_string(config.width) + "x" + std::to_string(config.height) +
                                                  " image, got \"" + text + "\"");
        config.inspect.push_back({x, y});
    }
    config.screenshot = o.screenshot;
    config.save_preset = o.save_preset;
    config.export_scene = export_scene;
    config.export_material = export_material;
    config.export_name = export_name;
    config.stats = o.stats;
    config.print_layout = o.print_layout;
    config.split = o.split;
    // Renderers are made on render workers' threads (the kernel build never holds up the window),
    // each with an OpenCL runtime of its own, kept until the viewer ends (the split view and a new
    // map run a second renderer beside the first).
    struct Runtimes {
        std::mutex mutex;
        std::vector<std::unique_ptr<std::optional<opencl::Runtime>>> list;
        // One at a time: PoCL's first platform query is not safe from two threads at once.
        std::unique_ptr<render::Renderer> make(const RenderJob& job, const std::string& device) {
            std::lock_guard<std::mutex> lock(mutex);
            auto runtime = std::make_unique<std::optional<opencl::Runtime>>();
            std::unique_ptr<render::Renderer> renderer = make_renderer(job, device, runtime.get());
            list.push_back(std::move(runtime));
            return renderer;
        }
    };
    auto runtimes = std::make_shared<Runtimes>();
    const std::string device = o.job.device;
    config.make_renderer = [job, device, runtimes] { return runtimes->make(*job, device); };
    const RenderJobOptions job_options = o.job;
    config.factory_for = [job_options, device, runtimes](const std::string& env,
                                                         const scene::LookDevReferences& references) -> viewer::RenderWorker::RendererFactory {
        const std::string words = scene::look_dev_references_text(references);
        return [job_options, env, words, device, runtimes] {
            RenderJobOptions options = job_options;
            if (!env.empty()) {
                options.env = env;
                options.env_rotation = options.env_exposure = 0.0f;  // the viewer's own values are applied next
            }
            options.references = words;
            options.shadow_catcher = false;  // the words hold it
            RenderJob job = prepare_render_job(options);  // throws for a missing or bad map
            return runtimes->make(job, device);
        };
    };
    int status = viewer::run_viewer(config);
    if (status != 0) throw CLI::RuntimeError(status);
}

}  // namespace

void register_view(CLI::App& app) {
    auto o = std::make_shared<ViewOptions>();
    o->job.default_env = "constant:1,1,1";
    o->job.size = "384x384";
    auto* cmd = app.add_subcommand("view", "Live viewer: tune a material on the test model (or a scene) under an environment");
    cmd->add_option("scene", o->job.scene, "Scene file (docs/scenes.md); default: the built-in test model");
    cmd->add_option("--material", o->job.material, "Material preset for the edited slot (the scene's \"sample\")");
    cmd->add_option("--compare", o->compare, "Material B of the lobe panel's A/B overlay (default: the edited material as loaded)");
    cmd->add_option("--slot", o->slot, "The scene material the panel edits (default: \"sample\", else the first)");
    cmd->add_option("--ground", o->job.ground, "Ground plane of the test model: on or off")->capture_default_str();
    add_render_options(*cmd, &o->job);
    cmd->add_option("--frames", o->frames, "Headless: close after N frames (and once the image shows every --set)");
    cmd->add_option("--min-spp", o->min_spp, "Headless: and once the image has at least this many samples per pixel")->capture_default_str();
    cmd->add_option("--set", o->sets, "Headless: KEY=VALUE@FRAME, a material parameter changed at a frame (repeatable)");
    cmd->add_option("--move", o->moves,
                    "Headless: KEY=VALUE@FRAME, a camera or environment change at a frame: orbit=DX,DY (pixels of drag), "
                    "env_rotation=DEG, env_exposure=STOPS, background_blur=DEG, background_opacity=A (repeatable)");
    cmd->add_option("--screenshot", o->screenshot, "Headless: the window as a PNG at the last frame");
    cmd->add_option("--save-preset", o->save_preset, "Write the edited material as a preset on exit");
    cmd->add_option("--export-to", o->export_to, "SCENE.json:NAME: write the material into the scene on exit (add or replace NAME); or FILE.mtlx|.gltf|.xml|.pbrt: export it for MaterialX, glTF, Mitsuba 3 or pbrt-v4 on exit (docs/interchange.md)");
    cmd->add_option("--load-env", o->env_loads, "Headless: PATH@FRAME, load an environment map at a frame as the panel does (errors are shown, not fatal)");
    cmd->add_option("--load-references", o->reference_loads,
                    "Headless: LIST@FRAME, the look-dev references switched at a frame as the environment panel does (none, all, or chrome,grey,chart,catcher)");
    cmd->add_option("--view-mode", o->view_modes,
                    "NAME@FRAME: the view menu's choice from a frame on (NAME alone: from the start; repeatable): image, albedo, normal, "
                    "depth, slot, samples, variance, false-colour, relative-error, gamut");
    cmd->add_option("--error-threshold", o->error_threshold,
                    "The relative-error view's threshold: pixels whose standard error over their mean luminance is above it are marked")
        ->capture_default_str();
    cmd->add_option("--save-exr", o->save_exr, "Headless: the frame shown at the end as an EXR (and a PNG beside it), with --save-layers");
    cmd->add_option("--save-layers", o->save_layers,
                    "The --save-exr file's AOV layers, as --aov lists them: albedo, normal, depth, slot, variance, samples");
    cmd->add_option("--inspect", o->inspect, "Headless: X,Y, a pixel whose inspector lines are printed at the end (repeatable)");
    cmd->add_option("--denoise", o->denoise,
                    "on: the image shown is denoised while it accumulates (guided by the first-hit AOVs, at most 15 % of the render's "
                    "time; the film is not touched); off: the raw mean")
        ->capture_default_str();
    cmd->add_flag("--split", o->split, "Start in the A/B split view (B: --compare)");
    cmd->add_option("--window", o->window, "The window's first size, WxH (default: the render's size and the panel's)");
    cmd->add_option("--display", o->display,
                    "What resizing the window changes: render (the render's size follows the area, up to --max-render-pixels) "
                    "or scale (the render keeps --size and is drawn scaled)")
        ->capture_default_str();
    cmd->add_option("--max-render-pixels", o->max_render_pixels, "Under --display render: the render's largest size; larger areas scale it up")
        ->capture_default_str();
    cmd->add_option("--open", o->open_sections, "Panel sections open from the start, besides Material and Checks (e.g. Lobe; all)")->delimiter(',');
    cmd->add_option("--resize", o->resizes, "Headless: WxH@FRAME, the window resized at a frame as a window manager does (repeatable)");
    cmd->add_flag("--stats", o->stats, "Print interface frame times, samples/s and change-to-frame latency on exit");
    cmd->add_flag("--print-layout", o->print_layout, "Print each new layout of the window, and where the open panel sections are on exit");
    cmd->add_option("--turntable", o->turntable.frames,
                    "N: no window; render one turn in N frames (--turn, --spp) to -o, a video (.mp4, made with FFmpeg) or frames (frame_%04d.png or .exr)");
    cmd->add_option("--turn", o->turntable.turn, "With --turntable: model (it turns under fixed lighting) or environment (the map turns)")
        ->capture_default_str();
    cmd->add_option("--spp", o->turntable.spp, "With --turntable: samples per pixel of each frame")->capture_default_str();
    cmd->add_option("--fps", o->turntable.fps, "With --turntable: frames per second of the video")->capture_default_str();
    cmd->add_option("-o,--output", o->turntable.output, "With --turntable: the video (.mp4) or the frames' pattern (frame_%04d.png or .exr)");
    cmd->add_flag("--quiet", o->turntable.quiet, "With --turntable: no line per frame");
    cmd->add_option("--max-spp", o->max_spp, "Stop accumulating at this many samples per pixel")->capture_default_str();
    cmd->add_option("--chunk-ms", o->chunk_ms, "Render time per chunk between published images, ms")->capture_default_str();
    cmd->add_option("--tonemap", o->tone_map, "Display tone map: aces, reinhard or clamp")->capture_default_str();
    cmd->add_option("--exposure", o->exposure, "Display exposure in stops")->capture_default_str();
    cmd->callback([o] { run_view(*o); });
}

}  // namespace lab::cli
