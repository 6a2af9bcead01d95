// What `preview`, `render`, `report` and the benches share: the options that choose the scene,
// material, environment, integrator and sampling, turned into a ready job (render::RenderInput);
// the renderer it runs on (an OpenCL device, or `--device host` for the C++ build); and the whole
// progressive run from the first sample to the written images.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "film/image_metadata.hpp"
#include "opencl/runtime.hpp"
#include "render/progressive.hpp"
#include "render/renderer.hpp"

namespace lab::cli {

// An environment loaded once for many jobs (a sequence's frames): a job whose environment comes from
// the same file or constant takes a copy turned and scaled to its own rotation and exposure
// (ibl::Environment::set_transform, which makes exactly what a fresh load would).
struct EnvironmentCache {
    std::optional<ibl::Environment> environment;
};

struct RenderJobOptions {
    std::string scene;     // empty: the built-in test model
    std::string material;  // preset for the "sample" slot; empty: the scene's own
    std::string env;       // file or constant:R,G,B; empty: the scene's (else see default_env)
    std::string default_env;  // when neither --env nor the scene gives one; empty: no environment
    double scene_time = 0.0;  // seconds: the scene's keyframes at this time (scene/scene_time.hpp)
    std::shared_ptr<EnvironmentCache> environment_cache;  // none: every job loads its environment
    float env_rotation = 0.0f;
    float env_exposure = 0.0f;
    // What camera rays see of the environment (render::RenderSettings); unset: the scene's, else 1 and 0
    std::optional<float> background_opacity;
    std::optional<float> background_blur;
    std::string size = "512x512";
    std::string ground = "on";
    std::string references = "none";  // look-dev references (scene/look_dev_references.hpp)
    bool shadow_catcher = false;       // a shadow-catching ground in the ground's place (scene/shadow_catcher.hpp): the reference word "catcher"
    std::string integrator = "pt";
    std::string light_sampling = "mis";
    std::string light_sampling_option = "--light-sampling";  // the flag that gave it, for errors
    std::string light_selection = "power";
    std::string normals = "tetrahedral";
    std::string object_bounds = "on";
    std::string geometry = "auto";
    int max_depth = 16;
    std::string mis_heuristic = "balance";  // bdpt, lt
    float light_paths = render::BdptSettings{}.light_paths;  // bdpt-cache
    int connections = render::BdptSettings{}.connections;    // bdpt-cache
    float connection_roulette = render::BdptSettings{}.connection_roulette;  // bdpt, lt, bdpt-cache
    float merge_radius = render::BdptSettings{}.merge_radius;  // vcm: 0 the scene's share; given, it must be > 0
    bool merge_radius_given = false;
    int max_steps = 1024;
    float over_relaxation = render::RenderSettings{}.over_relaxation;
    unsigned long long seed = 0;
    std::string device;
};

// The options of every render: environment, size, normals, depth, march, light selection, seed, device.
void add_render_options(CLI::App& cmd, RenderJobOptions* options);
// The preview's: --scene, --material, --ground and --ibl-sampling (brdf, env or mis).
void add_preview_options(CLI::App& cmd, RenderJobOptions* options);

struct RenderJob {
    render::RenderInput input;
    std::string scene_name, material_name, environment_name;
    float env_rotation = 0.0f, env_exposure = 0.0f;  // the options' (a scene's own are in its file)
    double scene_time = 0.0;
    bool ground = true;
    std::string references = "none";  // the references' words, the shadow catcher's ("catcher") among them
    scene::Scene base_scene;  // input.scene without the look-dev references (the viewer adds and removes them)
    std::string description;  // one line: material, scene, environment, size, integrator, sampling
};

// "on" or "off" as a bool; anything else is lab::InputError naming the option.
bool parse_on_off(const std::string& text, const std::string& option);

// The render settings and light selection the options give, checked before anything is loaded
// (sizes, words, ranges); throws lab::InputError naming the option.
render::RenderSettings checked_render_settings(const RenderJobOptions& options, render::LightSelection* selection);

// Loads and checks everything (scene, preset, environment, sizes, words); throws lab::InputError.
RenderJob prepare_render_job(const RenderJobOptions& options);

// The renderer the job runs on: the C++ build for `--device host`, else the OpenCL device the
// selector names (the runtime is made here on the first call and kept in `runtime`; later calls
// with the same `runtime` render on it, so that a program built for one renderer serves the next,
// opencl::Runtime::build).
std::unique_ptr<render::Renderer> make_renderer(const RenderJob& job, const std::string& device,
                                                std::optional<opencl::Runtime>* runtime);

// The render's metadata (render::render_metadata) with the job's scene, material and environment.
film::ImageMetadata job_metadata(const RenderJob& job, const render::Renderer& renderer, const render::RenderStatistics& stats);

// Where a progressive run stops and what it writes.
struct RenderRunOptions {
    int spp = 64;
    bool spp_given = false;
    double time_seconds = 0.0;
    std::string output;
    std::string tone_map = "aces";
    float exposure = 0.0f;
    bool quiet = false;
    bool verbose = false;  // also print which objects are intersected exactly
    std::string samples;  // --samples A:B: exactly the sample indices A to B-1 (a part of a render to merge)
    std::string resume;   // --resume FILE.exr: continue that render (its film) up to --spp in all, or for --time more
    std::string aov;      // --aov albedo,normal,depth: first-hit AOVs as EXR layers (render/aov_layers.hpp)
    std::string denoise = "off";  // --denoise on: the image denoised, the raw one kept as noisy.R/G/B (render/display_denoise.hpp)
    // A frame of a sequence (cli/render_sequence.hpp): a --resume file that holds --spp samples
    // already is a finished frame, and the job renders nothing instead of refusing.
    bool skip_finished = false;
};
void add_render_run_options(CLI::App& cmd, const std::shared_ptr<RenderRunOptions>& run);

// The whole command: checks the output and the limits, prepares the job, renders progressively
// (Ctrl-C writes the image so far), writes the EXR with metadata and the film (render/film_file.hpp)
// and the PNG, prints statistics. `extra` is added to the metadata. With --samples it renders one
// sample range; with --resume it first checks that the file is a part of this same render. With
// `runtime` (a sequence's frames) the renderer runs on that OpenCL runtime, made on the first call,
// so that its program is built once. Returns false when it rendered nothing: a finished frame
// (skip_finished).
bool run_render_job(const RenderJobOptions& options, const RenderRunOptions& run, const film::ImageMetadata& extra = {},
                    std::optional<opencl::Runtime>* runtime = nullptr);

}  // namespace lab::cli
