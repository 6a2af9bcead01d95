#include "cli/render_job.hpp"

#include <cmath>
#include <cstdio>
#include <functional>

#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "render/aov_layers.hpp"
#include "render/display_denoise.hpp"
#include "render/film_file.hpp"
#include "render/host_renderer.hpp"
#include "render/interrupt.hpp"
#include "render/vcm.hpp"
#include "render/opencl_renderer.hpp"
#include "render/scene_environment.hpp"
#include "scene/look_dev_references.hpp"
#include "scene/load_scene.hpp"
#include "scene/scene_time.hpp"
#include "scene/test_model.hpp"

namespace lab::cli {

void add_render_options(CLI::App& cmd, RenderJobOptions* o) {
    cmd.add_option("--env", o->env, "Environment: an equirectangular .exr/.hdr or constant:R,G,B (default: the scene's)");
    cmd.add_option("--env-rotation", o->env_rotation, "Environment rotation about +y, degrees")->capture_default_str();
    cmd.add_option("--env-exposure", o->env_exposure, "Environment intensity in stops")->capture_default_str();
    cmd.add_option("--background-opacity", o->background_opacity,
                   "How much of the environment camera rays see, in [0, 1] (0: the lights kept, the background hidden; the EXR's alpha "
                   "channel A says where it is); the lighting is unchanged (default: the scene's, else 1)");
    cmd.add_option("--background-blur", o->background_blur,
                   "Blur of the background camera rays see, degrees in [0, 90] (a spherical Gaussian's sigma; 0: sharp); the lighting is "
                   "unchanged (default: the scene's, else 0)");
    cmd.add_option("--scene-time", o->scene_time,
                   "The scene time in seconds: where the scene's camera and environment keyframes are, and the frame an emitter's image sequence or video shows (docs/scenes.md, Time)")
        ->capture_default_str();
    cmd.add_option("--size", o->size, "Image size WxH")->capture_default_str();
    cmd.add_option("--light-selection", o->light_selection, "How a light is chosen for next-event estimation: power or uniform")
        ->capture_default_str();
    cmd.add_option("--normals", o->normals, "Surface normals: tetrahedral, central or analytic")->capture_default_str();
    cmd.add_option("--object-bounds", o->object_bounds,
                   "Box tests that skip objects far from the point being marched: on or off (same image; off to compare speed)")
        ->capture_default_str();
    cmd.add_option("--geometry", o->geometry,
                   "auto: plain primitives and emitters intersected exactly, the rest sphere-traced; march: sphere-trace everything (to compare)")
        ->capture_default_str();
    cmd.add_option("--max-depth", o->max_depth, "Scattering events per path, for every integrator (bdpt and lt: paths of at most max-depth + 2 vertices, at most 62 events)")->capture_default_str();
    cmd.add_option("--light-paths", o->light_paths, "bdpt-cache: light subpaths per sample, per pixel of the image, in (0, 16]")
        ->capture_default_str();
    cmd.add_option("--connections", o->connections, "bdpt-cache: light-cache vertices each camera vertex is joined to, in [1, 64]")
        ->capture_default_str();
    cmd.add_option("--merge-radius", o->merge_radius,
                   "vcm: the first sample's merge radius r_0 in scene units, > 0 (it shrinks as r_0 (i + 1)^-0.125 with the sample index "
                   "i); without it 1 % of the scene's bounding radius")
        ->each([o](const std::string&) { o->merge_radius_given = true; });
    cmd.add_option("--connection-roulette", o->connection_roulette,
                   "bdpt, lt, bdpt-cache: a connection of MIS weight w below this traces its shadow ray with probability w / this, and "
                   "counts 1 / that probability (0: always)")
        ->capture_default_str();
    cmd.add_option("--max-steps", o->max_steps, "Sphere-tracing steps per ray before it counts as lost")->capture_default_str();
    cmd.add_option("--over-relaxation", o->over_relaxation, "Sphere-tracing over-relaxation in [1, 2] (1: plain; a scene that is not a distance bound uses 1)")->capture_default_str();
    cmd.add_option("--seed", o->seed, "Seed of the random numbers (same seed, same image)")->capture_default_str();
    cmd.add_option("--references", o->references,
                   "Look-dev references in the view's lower corners: none, all, or a list of chrome (a chrome ball), grey (an 18 % grey "
                   "ball), chart (a ColorChecker)")
        ->capture_default_str();
    cmd.add_flag("--shadow-catcher", o->shadow_catcher,
                 "A ground under the objects that shows the background with their shadows on it (and takes the place of the test "
                 "model's ground): differential rendering, the path tracer only");
    cmd.add_option("--device", o->device,
                   "OpenCL device: P:D, gpu, cpu or part of its name (dtoadq devices lists them); host: the C++ build on the CPU's threads");
}

void add_preview_options(CLI::App& cmd, RenderJobOptions* o) {
    cmd.add_option("--scene", o->scene, "Scene file (docs/scenes.md); default: the built-in test model");
    cmd.add_option("--material", o->material, "Material preset for the scene's \"sample\" slot");
    cmd.add_option("--ground", o->ground, "Ground plane of the test model: on or off")->capture_default_str();
    cmd.add_option("--ibl-sampling", o->light_sampling, "Light sampling: brdf, env (next-event estimation) or mis")->capture_default_str();
    o->light_sampling_option = "--ibl-sampling";
}

bool parse_on_off(const std::string& text, const std::string& option) {
    if (text == "on") return true;
    if (text == "off") return false;
    throw InputError(option, "", "expected on or off, got \"" + text + "\"");
}

namespace {

void require_within(float value, const std::string& option, float lo, float hi) {
    if (!(value >= lo && value <= hi))
        throw InputError(option, "", "value " + std::to_string(value) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

// The environment of `source` loaded with `options` by `load`, or the cache's copy of it turned and scaled.
ibl::Environment cached_environment(EnvironmentCache* cache, const std::string& source, const ibl::EnvironmentOptions& options,
                                    const std::function<ibl::Environment()>& load) {
    if (cache && cache->environment && cache->environment->source() == source) {
        ibl::Environment environment = *cache->environment;
        environment.set_transform(options.rotation_degrees, options.exposure_stops);
        return environment;
    }
    ibl::Environment environment = load();
    if (cache) cache->environment = environment;
    return environment;
}

std::optional<ibl::Environment> load_job_environment(const RenderJobOptions& o, const scene::Scene& scene, std::string* name) {
    ibl::EnvironmentOptions env_options;
    env_options.rotation_degrees = o.env_rotation;
    env_options.exposure_stops = o.env_exposure;
    EnvironmentCache* cache = o.environment_cache.get();
    if (!o.env.empty()) {
        *name = o.env;
        return cached_environment(cache, o.env, env_options, [&] { return ibl::load_environment(o.env, env_options); });
    }
    if (scene.environment) {  // its rotation and exposure, the options' on top
        const ibl::EnvironmentOptions options = render::scene_environment_options(scene, env_options, name);
        return cached_environment(cache, *name, options, [&] { return *render::load_scene_environment(scene, env_options); });
    }
    if (o.default_env.empty()) {
        *name = "none";
        return std::nullopt;
    }
    *name = o.default_env;
    return cached_environment(cache, o.default_env, env_options, [&] { return ibl::load_environment(o.default_env, env_options); });
}

}  // namespace

render::RenderSettings checked_render_settings(const RenderJobOptions& o, render::LightSelection* selection) {
    render::RenderSettings settings;
    render::parse_image_size(o.size, "--size", &settings.width, &settings.height);
    settings.integrator = render::parse_integrator(o.integrator);
    settings.light_sampling = render::parse_light_sampling(o.light_sampling, o.light_sampling_option);
    settings.normals = render::parse_normal_method(o.normals);
    settings.max_depth = o.max_depth;
    settings.bdpt.mis_heuristic = render::parse_mis_heuristic(o.mis_heuristic);
    settings.bdpt.light_paths = o.light_paths;
    settings.bdpt.connections = o.connections;
    settings.bdpt.connection_roulette = o.connection_roulette;
    settings.bdpt.merge_radius = o.merge_radius;
    if (o.merge_radius_given) render::check_merge_radius(o.merge_radius);  // 0 means the scene's share only when not given
    settings.max_steps = o.max_steps;
    settings.over_relaxation = o.over_relaxation;
    render::check_render_settings(settings);
    *selection = render::parse_light_selection(o.light_selection);
    require_within(o.env_rotation, "--env-rotation", -36000.0f, 36000.0f);
    require_within(o.env_exposure, "--env-exposure", -64.0f, 64.0f);
    if (!(std::fabs(o.scene_time) <= 1e9)) throw InputError("--scene-time", "", "must be a number of seconds in [-1e9, 1e9]");
    parse_on_off(o.ground, "--ground");
    scene::parse_look_dev_references(o.references, "--references");
    settings.object_bounds = parse_on_off(o.object_bounds, "--object-bounds");
    if (o.geometry != "auto" && o.geometry != "march") throw InputError("--geometry", "", "expected auto or march, got \"" + o.geometry + "\"");
    settings.march_everything = o.geometry == "march";
    settings.seed = o.seed;
    if (o.background_opacity) settings.background_opacity = *o.background_opacity;
    if (o.background_blur) settings.background_blur_degrees = *o.background_blur;
    render::check_render_settings(settings);
    return settings;
}

RenderJob prepare_render_job(const RenderJobOptions& o) {
    render::LightSelection selection;
    render::RenderSettings settings = checked_render_settings(o, &selection);  // before anything is loaded

    // scene::apply_options rejects, naming the scene file, a slot or object the scene does not declare
    scene::CompileOptions compile;
    std::optional<brdf::Preset> sample;
    if (!o.material.empty()) {
        sample = brdf::load_preset(o.material);
        compile.material_overrides[scene::kSampleMaterialSlot] = sample->material;
    }
    if (!parse_on_off(o.ground, "--ground")) compile.disabled_objects.push_back(scene::kGroundObject);
    compile.march_everything = settings.march_everything;  // the scene as the renderer has it (the viewer's probe reads it)
    scene::Scene scene =
        scene::apply_options(scene::scene_at_time(o.scene.empty() ? scene::load_test_model() : scene::load_scene(o.scene), o.scene_time), compile);
    scene::Scene base_scene = scene;
    scene::LookDevReferences references = scene::parse_look_dev_references(o.references, "--references");
    references.shadow_catcher = references.shadow_catcher || o.shadow_catcher;  // the catcher takes the ground's place
    scene = scene::with_look_dev_references(scene, references, float(settings.width) / float(settings.height));

    std::string env_name;
    std::optional<ibl::Environment> environment = load_job_environment(o, scene, &env_name);
    if (scene.environment && o.env.empty()) {  // the scene's backdrop, unless the command line gives its own
        if (!o.background_opacity) settings.background_opacity = scene.environment->background_opacity;
        if (!o.background_blur) settings.background_blur_degrees = scene.environment->background_blur_degrees;
    }
    RenderJob job;
    job.scene_name = o.scene.empty() ? std::string("test model") : o.scene;
    job.material_name = sample ? sample->name : std::string("the scene's materials");
    job.environment_name = env_name;
    job.env_rotation = o.env_rotation;
    job.env_exposure = o.env_exposure;
    job.scene_time = o.scene_time;
    job.ground = parse_on_off(o.ground, "--ground");
    job.references = scene::look_dev_references_text(references);
    job.base_scene = std::move(base_scene);
    job.input.scene = std::move(scene);
    job.input.environment = std::move(environment);
    job.input.settings = settings;
    job.input.light_selection = selection;
    job.input.scene_time = o.scene_time;  // the time an emitter's image is read at
    char line[768];
    std::snprintf(line, sizeof line, "%s on %s under %s, %dx%d, %s with %s light sampling", job.material_name.c_str(),
                  job.scene_name.c_str(), env_name.c_str(), settings.width, settings.height, render::integrator_name(settings.integrator),
                  render::light_sampling_name(settings.light_sampling));
    job.description = line;
    return job;
}

std::unique_ptr<render::Renderer> make_renderer(const RenderJob& job, const std::string& device, std::optional<opencl::Runtime>* runtime) {
    if (device == "host") return std::make_unique<render::HostRenderer>(job.input);
    if (!*runtime) runtime->emplace(device);
    return std::make_unique<render::OpenClRenderer>(**runtime, job.input);
}

film::ImageMetadata job_metadata(const RenderJob& job, const render::Renderer& renderer, const render::RenderStatistics& stats) {
    film::ImageMetadata m = render::render_metadata(renderer, stats);
    m.set("material", job.material_name);
    m.set("scene", job.scene_name);
    m.set("environment", job.environment_name);
    m.set("env_rotation", job.env_rotation);
    m.set("env_exposure", job.env_exposure);
    m.set("ground", job.ground ? "on" : "off");
    m.set("references", job.references);
    char seconds[40];
    std::snprintf(seconds, sizeof seconds, "%.17g", job.scene_time);  // every digit: a resume or merge at another time is refused
    m.set("scene_time", seconds);
    return m;
}

void add_render_run_options(CLI::App& cmd, const std::shared_ptr<RenderRunOptions>& run) {
    cmd.add_option("--spp", run->spp, "Samples per pixel (with --time: at most this many)")->capture_default_str()
        ->each([run](const std::string&) { run->spp_given = true; });
    cmd.add_option("--time", run->time_seconds, "Render until this many seconds have passed, instead of a sample count");
    cmd.add_option("-o,--output", run->output, "Output .exr (linear, with a tone-mapped .png beside it) or .png")->capture_default_str();
    cmd.add_option("--tonemap", run->tone_map, "Tone map of the PNG: aces, reinhard or clamp")->capture_default_str();
    cmd.add_option("--exposure", run->exposure, "Exposure of the PNG in stops")->capture_default_str();
    cmd.add_flag("--quiet", run->quiet, "No progress bar or statistics");
    cmd.add_flag("--verbose", run->verbose, "Also print which objects are intersected exactly and which are sphere-traced");
    cmd.add_option("--samples", run->samples,
                   "A:B renders exactly the sample indices A to B-1 of every pixel: a part of a render that dtoadq merge combines");
    cmd.add_option("--aov", run->aov,
                   "AOVs as extra EXR layers, a comma-separated list of albedo, normal, depth, slot (first hit: albedo.R/G/B, normal.X/Y/Z, "
                   "depth.Z, IndexMA.X), variance, samples (of each pixel's mean: variance.R/G/B, samples.X)");
    cmd.add_option("--denoise", run->denoise,
                   "on: the image denoised for looking at (guided by the first-hit AOVs), the raw one kept as the EXR layer noisy.R/G/B")
        ->capture_default_str();
    cmd.add_option("--resume", run->resume, "An EXR this command wrote: continue it (to --spp samples per pixel in all, or for --time more)");
}

namespace {

// How many samples this run adds, and from where: --samples A:B, --resume (up to --spp), or --spp/--time.
render::RenderLimits run_limits(const RenderRunOptions& run, const std::optional<render::SampleRanges>& range,
                                const std::optional<render::FilmFile>& resumed) {
    render::RenderLimits limits;
    limits.samples = run.spp;
    limits.samples_given = run.spp_given;
    limits.seconds = run.time_seconds;
    limits.quiet = run.quiet;
    if (range) {
        limits.samples = int(range->count());
        limits.samples_given = true;
    }
    if (resumed) {
        int held = int(resumed->ranges.count());
        if (run.skip_finished && held >= run.spp) {
            limits.samples = 0;  // a finished frame
            return limits;
        }
        if (!run.time_seconds && held >= run.spp)
            throw InputError("--spp", "", std::to_string(run.spp) + " samples per pixel in all, but " + resumed->path + " already holds " +
                                              std::to_string(held) + ": ask for more to resume");
        limits.samples = run.spp - held;
        if (run.time_seconds > 0.0 && !run.spp_given) limits.samples_given = false;
    }
    return limits;
}

}  // namespace

bool run_render_job(const RenderJobOptions& options, const RenderRunOptions& run, const film::ImageMetadata& extra,
                    std::optional<opencl::Runtime>* shared_runtime) {
    // Everything that can be wrong with the input is found before the first sample.
    render::check_render_output(run.output);
    const render::AovSelection aov_selection = render::parse_aov_selection(run.aov, run.output);
    const bool denoise = parse_on_off(run.denoise, "--denoise");
    film::ToneMap tone_map = film::parse_tone_map(run.tone_map);
    if (!(run.time_seconds >= 0.0) || run.time_seconds > 1e6) throw InputError("--time", "", "must be in [0, 1e6] seconds");
    if (run.spp < 1 || run.spp > 1 << 24) throw InputError("--spp", "", "must be in [1, 16777216]");
    if (!(run.exposure >= -64.0f && run.exposure <= 64.0f)) throw InputError("--exposure", "", "must be a number of stops in [-64, 64]");
    std::optional<render::SampleRanges> range;
    if (!run.samples.empty()) {
        range = render::SampleRanges::parse_range(run.samples, "--samples");
        if (run.spp_given || run.time_seconds > 0.0) throw InputError("--samples", "", "gives the sample count itself: leave out --spp and --time");
        if (!run.resume.empty()) throw InputError("--samples", "", "cannot be used with --resume (a resumed render continues where it stopped)");
    }
    std::optional<render::FilmFile> resumed;
    if (!run.resume.empty()) resumed = render::read_film_file(run.resume);
    render::RenderLimits limits = run_limits(run, range, resumed);
    RenderJob job = prepare_render_job(options);
    std::optional<opencl::Runtime> own_runtime;
    std::unique_ptr<render::Renderer> renderer = make_renderer(job, options.device, shared_runtime ? shared_runtime : &own_runtime);
    auto metadata_now = [&] {
        film::ImageMetadata m = job_metadata(job, *renderer, renderer->statistics());
        for (const auto& [key, value] : extra.values) m.values[key] = value;
        m.set("tonemap", run.tone_map);
        m.set("exposure", run.exposure);
        return m;
    };
    if (range) renderer->set_first_sample(int(range->ranges().front().first));
    if (resumed) {
        render::check_same_render("this render", metadata_now(), renderer->settings().width, renderer->settings().height, *resumed);
        renderer->restore_film(resumed->film, resumed->ranges);
        if (limits.samples == 0) return false;  // finished (skip_finished), and a part of this render
    }
    if (!run.quiet)
        std::printf("%s on %s: kernel built in %.2f s\n", job.description.c_str(), renderer->device_description().c_str(),
                    renderer->build_seconds());
    std::fflush(stdout);
    for (const std::string& w : renderer->compiled_scene().warnings) std::fprintf(stderr, "dtoadq: note: %s\n", w.c_str());
    if (run.verbose)
        for (const std::string& line : renderer->compiled_scene().geometry_paths) std::printf("geometry: %s\n", line.c_str());
    std::fflush(stdout);

    // Held past the render, across the writing: a Ctrl-C while the images are written ends the job as
    // interrupted once they are complete, and a second one stops at once with its message, instead of
    // SIGINT's default action (short launches make a Ctrl-C right after the first one land here).
    render::InterruptScope interrupt_scope;
    render::ProgressiveOutcome outcome = render::render_progressively(*renderer, limits);
    render::RenderStatistics stats = renderer->statistics();
    if (!outcome.failure.empty() && stats.samples_per_pixel == 0) render::fail_after_writing(outcome, 0, "");
    if (stats.samples_per_pixel == 0 && (outcome.interrupted || render::interrupt_requested())) {
        // a file without samples could be neither resumed nor merged (render/film_file.hpp)
        std::fprintf(stderr, "dtoadq: interrupted before the first sample; nothing was written\n");
        throw CLI::RuntimeError(render::kInterruptedExitStatus);
    }
    film::ImageMetadata metadata = metadata_now();
    metadata.set("denoise", denoise ? "on" : "off");
    const render::FilmReadback film = renderer->film();
    const film::ImageRgb raw = renderer->image();
    std::optional<render::FirstHitAovs> first_hits;
    // a backdrop that is not opaque gets an alpha channel, which the first hits' coverage gives
    const float opacity = renderer->settings().background_opacity;
    const bool alpha = opacity < 1.0f && render::is_exr_path(run.output);
    if (aov_selection.first_hit() || denoise || alpha) first_hits = renderer->first_hit_aovs();
    std::vector<film::ImageChannel> layers;
    if (alpha) layers.push_back(render::background_alpha_channel(*first_hits, opacity));
    const std::vector<film::ImageChannel> aovs = render::aov_channels(first_hits ? &*first_hits : nullptr, film, stats.samples_per_pixel,
                                                                      renderer->settings().width, renderer->settings().height, aov_selection);
    layers.insert(layers.end(), aovs.begin(), aovs.end());
    film::ImageRgb shown = raw;
    if (denoise) {
        shown = render::denoised(raw, render::denoise_guide(*first_hits, renderer->variance()), *renderer->display_filter(), {});
        const std::vector<film::ImageChannel> noisy = render::noisy_channels(raw);
        layers.insert(layers.end(), noisy.begin(), noisy.end());
    }
    render::write_render_images(run.output, shown, tone_map, run.exposure, metadata, &film, layers);
    std::printf("wrote %s%s\n", run.output.c_str(), render::is_exr_path(run.output) ? (" and " + render::png_beside(run.output)).c_str() : "");
    if (!outcome.failure.empty()) render::fail_after_writing(outcome, stats.samples_per_pixel, run.output);
    render::print_render_statistics(stats, run.quiet);
    if (outcome.interrupted || render::interrupt_requested()) {
        std::fprintf(stderr, "dtoadq: interrupted after %d samples per pixel; the image so far was written\n", stats.samples_per_pixel);
        throw CLI::RuntimeError(render::kInterruptedExitStatus);
    }
    return true;
}

}  // namespace lab::cli
