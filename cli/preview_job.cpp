#include "cli/preview_job.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>

#include "brdf/host/preset.hpp"
#include "cli/interrupt.hpp"
#include "common/input_error.hpp"
#include "film/image_output.hpp"
#include "film/progress_bar.hpp"
#include "ibl/preview_scene.hpp"

namespace lab::cli {

namespace fs = std::filesystem;

void add_preview_job_options(CLI::App& cmd, PreviewJobOptions* o) {
    cmd.add_option("--scene", o->scene, "Scene file (docs/scenes.md); default: the built-in test model");
    cmd.add_option("--material", o->material, "Material preset for the scene's \"sample\" slot");
    cmd.add_option("--env", o->env, "Environment: an equirectangular .exr/.hdr or constant:R,G,B (default: the scene's, else constant:1,1,1)");
    cmd.add_option("--env-rotation", o->env_rotation, "Environment rotation about +y, degrees")->capture_default_str();
    cmd.add_option("--env-exposure", o->env_exposure, "Environment intensity in stops")->capture_default_str();
    cmd.add_option("--size", o->size, "Image size WxH")->capture_default_str();
    cmd.add_option("--ground", o->ground, "Ground plane of the test model: on or off")->capture_default_str();
    cmd.add_option("--ibl-sampling", o->sampling, "Environment sampling: brdf, env or mis")->capture_default_str();
    cmd.add_option("--normals", o->normals, "Surface normals: tetrahedral, central or analytic")->capture_default_str();
    cmd.add_option("--max-depth", o->max_depth, "Scattering events per path")->capture_default_str();
    cmd.add_option("--max-steps", o->max_steps, "Sphere-tracing steps per ray before it counts as lost")->capture_default_str();
    cmd.add_option("--over-relaxation", o->over_relaxation, "Sphere-tracing over-relaxation in [1, 2] (1: plain)")->capture_default_str();
    cmd.add_option("--seed", o->seed, "Seed of the random numbers (same seed, same image)")->capture_default_str();
    cmd.add_option("--device", o->device, "OpenCL device: P:D, gpu, cpu or part of its name (dtoadq devices lists them)");
}

void parse_image_size(const std::string& text, const std::string& option, int* width, int* height) {
    static const std::regex pattern(R"((\d{1,6})x(\d{1,6}))");
    std::smatch m;
    if (!std::regex_match(text, m, pattern)) throw InputError(option, "", "expected WIDTHxHEIGHT, e.g. 512x512, got \"" + text + "\"");
    *width = std::stoi(m[1].str());
    *height = std::stoi(m[2].str());
    if (*width < 1 || *height < 1 || *width > ibl::kMaxImageSide || *height > ibl::kMaxImageSide)
        throw InputError(option, "", text + " is outside 1 .. " + std::to_string(ibl::kMaxImageSide) + " pixels a side");
}

namespace {

bool parse_on_off(const std::string& text, const std::string& option) {
    if (text == "on") return true;
    if (text == "off") return false;
    throw InputError(option, "", "expected on or off, got \"" + text + "\"");
}

void require_finite(float value, const std::string& option, float lo, float hi) {
    if (!(value >= lo && value <= hi))
        throw InputError(option, "", "value " + std::to_string(value) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

ibl::Environment load_job_environment(const PreviewJobOptions& o, const scene::Scene& scene, std::string* name) {
    ibl::EnvironmentOptions env_options;
    env_options.rotation_degrees = o.env_rotation;
    env_options.exposure_stops = o.env_exposure;
    if (!o.env.empty()) {
        *name = o.env;
        return ibl::load_environment(o.env, env_options);
    }
    if (scene.environment) {  // the scene's own: its rotation and exposure, then the options' on top
        const scene::EnvironmentSpec& spec = *scene.environment;
        env_options.rotation_degrees += spec.rotation_degrees;
        env_options.exposure_stops += spec.exposure;
        env_options.origin = scene.file + ": environment";
        if (!spec.file.empty()) {
            *name = spec.file;
            return ibl::load_environment(spec.file, env_options);
        }
        *name = "constant:" + std::to_string(spec.constant.x) + "," + std::to_string(spec.constant.y) + "," + std::to_string(spec.constant.z);
        return ibl::Environment::constant(spec.constant, *name, env_options);
    }
    *name = "constant:1,1,1";
    return ibl::load_environment(*name, env_options);
}

}  // namespace

PreviewJob prepare_preview_job(const PreviewJobOptions& o) {
    ibl::PreviewSettings settings;
    parse_image_size(o.size, "--size", &settings.width, &settings.height);
    settings.sampling = ibl::parse_ibl_sampling(o.sampling);
    settings.normals = ibl::parse_normal_method(o.normals);
    settings.max_depth = o.max_depth;
    settings.max_steps = o.max_steps;
    settings.over_relaxation = o.over_relaxation;
    ibl::check_preview_settings(settings);  // before anything is loaded
    require_finite(o.env_rotation, "--env-rotation", -36000.0f, 36000.0f);
    require_finite(o.env_exposure, "--env-exposure", -64.0f, 64.0f);
    settings.seed = o.seed;

    ibl::PreviewSceneOptions scene_options;
    scene_options.ground = parse_on_off(o.ground, "--ground");
    if (!o.material.empty()) scene_options.sample_material = brdf::load_preset(o.material);
    scene::Scene scene = ibl::load_preview_scene(o.scene);
    ibl::PreviewScene compiled = ibl::compile_preview_scene(scene, scene_options);

    std::string env_name;
    ibl::Environment environment = load_job_environment(o, scene, &env_name);
    PreviewJob job{std::move(compiled), std::move(environment), settings, {}, {}, {}, {}, {}};
    job.scene_name = o.scene.empty() ? std::string("test model") : o.scene;
    job.material_name = scene_options.sample_material ? scene_options.sample_material->name : std::string("the scene's materials");
    job.environment_name = env_name;
    char line[512];
    std::snprintf(line, sizeof line, "%s on %s under %s, %dx%d, %s sampling", job.material_name.c_str(), job.scene_name.c_str(),
                  env_name.c_str(), settings.width, settings.height, ibl::ibl_sampling_name(settings.sampling));
    job.description = line;
    for (const std::string& w : job.scene.warnings) job.warnings.push_back(w);
    return job;
}

film::ImageMetadata preview_metadata(const PreviewJob& job, const ibl::PreviewStatistics& stats, const std::string& device) {
    film::ImageMetadata m;
    m.set("spp", stats.samples_per_pixel);
    m.set("seconds", stats.render_seconds);
    m.set("material", job.material_name);
    m.set("scene", job.scene_name);
    m.set("environment", job.environment_name);
    m.set("ibl_sampling", ibl::ibl_sampling_name(job.settings.sampling));
    m.set("max_depth", job.settings.max_depth);
    m.set("normals", ibl::normal_method_name(job.settings.normals));
    m.set("seed", std::to_string(job.settings.seed));
    m.set("device", device);
    m.set("nonfinite_samples", std::to_string(stats.nonfinite_samples));
    m.set("lost_rays", std::to_string(stats.lost_rays));
    return m;
}

bool is_exr_path(const std::string& path) {
    std::string extension = fs::path(path).extension().string();
    return extension == ".exr" || extension == ".EXR";
}

std::string png_beside(const std::string& exr_path) { return fs::path(exr_path).replace_extension(".png").string(); }

void write_preview_images(const std::string& output, const film::ImageRgb& image, film::ToneMap tone_map, float exposure_stops,
                          const film::ImageMetadata& metadata) {
    try {
        if (is_exr_path(output)) {
            film::write_exr(output, image, metadata);
            film::write_png(png_beside(output), image, tone_map, exposure_stops, metadata);
        } else {
            film::write_png(output, image, tone_map, exposure_stops, metadata);
        }
    } catch (const InputError& e) {
        fs::path rescue = fs::temp_directory_path() / ("dtoadq-preview-" + std::to_string(::getpid()) + ".exr");
        film::write_exr(rescue.string(), image, metadata);
        throw InputError(output, "", std::string("cannot write (") + e.what() + "); the render was saved to " + rescue.string());
    }
}

bool render_progressively(ibl::PreviewRenderer& renderer, const RenderLimits& limits) {
    bool timed = limits.seconds > 0.0;
    int target = timed && !limits.samples_given ? (1 << 24) : limits.samples;
    film::ProgressOptions progress_options;
    progress_options.quiet = limits.quiet;
    const ibl::PreviewSettings& settings = renderer.settings();
    film::ProgressBar progress(timed ? film::ProgressMode::Time : film::ProgressMode::Samples, timed ? limits.seconds : double(target),
                               double(settings.width) * settings.height, progress_options);
    InterruptScope interrupt_scope;
    int done = 0;
    while (done < target && !interrupt_requested()) {
        if (timed && progress.elapsed_seconds() >= limits.seconds) break;
        int n = std::min(renderer.samples_per_launch(), target - done);
        auto start = std::chrono::steady_clock::now();
        renderer.add_samples(n);
        double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        done += n;
        progress.update(done);
        // Launches grow while they take under an eighth of a second: fewer launches, a live bar.
        if (seconds < 0.125) renderer.set_samples_per_launch(renderer.samples_per_launch() * 2);
        if (timed) {  // do not start a launch that would end well past the time
            double per_sample = seconds / n, left = limits.seconds - progress.elapsed_seconds();
            int fit = int(left / per_sample);
            if (fit < renderer.samples_per_launch()) renderer.set_samples_per_launch(std::max(1, fit));
        }
    }
    progress.finish();
    return interrupt_requested();
}

void print_preview_statistics(const ibl::PreviewStatistics& s, bool quiet) {
    if (!quiet)
        std::printf("%d spp in %.2f s: %.3g paths/s, %.3g rays/s (%.2f rays per path)\n", s.samples_per_pixel, s.render_seconds,
                    s.paths_per_second(), s.rays_per_second(), s.paths ? double(s.rays) / double(s.paths) : 0.0);
    if (s.nonfinite_samples)
        std::fprintf(stderr, "dtoadq: warning: %llu non-finite samples (NaN or infinite) were left out of the image\n",
                     (unsigned long long)s.nonfinite_samples);
    if (s.lost_rays && !quiet)  // grazing rays; counted as escaping (or shadowed, for shadow rays)
        std::printf("%llu of %llu rays ran out of sphere-tracing steps (%.3g%%)\n", (unsigned long long)s.lost_rays,
                    (unsigned long long)s.rays, 100.0 * double(s.lost_rays) / double(s.rays));
}

}  // namespace lab::cli
