#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "brdf/brdf.hpp"
#include "brdf/host/features.hpp"
#include "common/input_error.hpp"
#include "common/seconds_since.hpp"
#include "ibl/background_blur.hpp"
#include "render/camera_setup.hpp"
#include "render/film_resolve.hpp"
#include "render/integrator.hpp"
#include "render/vcm.hpp"

namespace lab::render {

namespace {

using Clock = std::chrono::steady_clock;

// NORMAL_TETRAHEDRAL, NORMAL_CENTRAL, NORMAL_ANALYTIC of sdf/normals.h (which only a translation unit
// with a scene can include).
int normal_code(NormalMethod m) { return m == NormalMethod::tetrahedral ? 0 : (m == NormalMethod::central ? 1 : 2); }

int light_sampling_code(LightSampling s) {
    switch (s) {
        case LightSampling::bsdf: return LIGHT_SAMPLING_BSDF;
        case LightSampling::lights: return LIGHT_SAMPLING_LIGHTS;
        case LightSampling::mis: break;
    }
    return LIGHT_SAMPLING_MIS;
}

// An emitter's material scatters when any of its lobes has weight; an emitter without a material
// is black (every weight 0, docs/scenes.md) and ends the path that reaches it.
bool scatters(const brdf::Material& m) {
    return m.weight_diffuse > 0.0f || m.weight_glossy > 0.0f || m.weight_specular > 0.0f || m.weight_transmission > 0.0f;
}

// The integrators' kernels (kernels/path_tracer.h; BDPT's through brdf/bsdf_transport.h) call the
// BSDF's entry points for clamped materials (bsdf_*_clamped): every renderer's materials are
// clamped here, once, when it takes them, not at every vertex. Materials read from files were
// range-checked already, so this changes none of theirs; it keeps the kernels defined for any
// struct handed to the renderer.
void clamp_materials(std::vector<brdf::Material>& materials) {
    for (brdf::Material& m : materials) m = brdf::material_clamped(&m);
}

}  // namespace

std::vector<brdf::float4> emission_table(const scene::CompiledScene& scene) {
    std::vector<brdf::float4> table;
    for (size_t k = 0; k < scene.materials.size(); ++k) {
        scene::Vec3 e = k < scene.emission.size() ? scene.emission[k] : scene::Vec3(0.0f);
        float kind = EMISSION_NONE;
        if (e.x > 0.0f || e.y > 0.0f || e.z > 0.0f) kind = scatters(scene.materials[k]) ? EMISSION_SCATTERS : EMISSION_ABSORBS;
        else if (k < scene.shadow_catcher.size() && scene.shadow_catcher[k]) kind = EMISSION_CATCHER;
        else if (brdf::material_emits(&scene.materials[k])) kind = EMISSION_SURFACE;  // its radiance is the material's (brdf/emission.h)
        table.push_back(brdf::float4(e.x, e.y, e.z, kind));
    }
    return table;
}

Renderer::Renderer(RenderInput input) : input_(std::move(input)) {
    check_render_settings(input_.settings);
    input_.scene.march_everything = input_.settings.march_everything;  // the host build evaluates input_.scene
    compiled_ = scene::compile_scene(input_.scene, compile_options());
    if (compiled_.materials.empty()) throw std::invalid_argument("Renderer: a scene has at least one material slot");
    clamp_materials(compiled_.materials);
    // Everything about the scene is checked before the (slow) build.
    camera_ = make_camera(compiled_.camera, input_.settings.width, input_.settings.height, compiled_.file);
    // Over-relaxation's step back is safe only where the field bounds the distance (sdf/march.h).
    if (!compiled_.is_distance_bound && input_.settings.over_relaxation > 1.0f) {
        input_.settings.over_relaxation = 1.0f;
        compiled_.warnings.push_back(compiled_.file + ": the field is not a distance bound, so sphere tracing is not over-relaxed (1)");
    }
    emission_ = emission_table(compiled_);
    emitter_images_ = load_emitter_images(compiled_, input_.scene_time);
    rebuild_lights();
    rebuild_background();
    check_emissive_materials();
    for (size_t k = 0; k < compiled_.shadow_catcher.size(); ++k)
        if (compiled_.shadow_catcher[k] && input_.settings.integrator != Integrator::pt)
            throw InputError(compiled_.file, "--integrator",
                             std::string("the shadow catcher (material \"") + compiled_.material_names[k] + "\") is rendered by the path tracer only: use --integrator pt");
}

// A material's emission is found only by paths that hit it (kernels/render_scene.h): bdpt's s = 0,
// which a scene lit by such materials alone is enough for, and never the light tracer's t = 1.
void Renderer::check_emissive_materials() const {
    bool any = false;
    for (size_t k = 0; k < emission_.size(); ++k) {
        if (emission_[k].w != EMISSION_SURFACE) continue;
        any = true;
        if (!integrator_descriptor(input_.settings.integrator).sees_emissive_materials())
            throw InputError(compiled_.file, "materials." + compiled_.material_names[k],
                             std::string("emission_luminance: ") + integrator_descriptor(input_.settings.integrator).noun +
                                 " cannot see a material's emission (no light subpath starts on it): use --integrator bdpt or pt");
    }
    check_integrator_lights(input_.settings.integrator, compiled_.file, any || !lights_.lights.empty(), input_.environment.has_value());
}

void Renderer::initialize() {
    build_kernel();
    upload_scene();
    clear_film();
}

void Renderer::rebuild_lights() {
    lights_ = build_light_set(compiled_, input_.environment ? &*input_.environment : nullptr, input_.light_selection,
                              emitter_image_means(emitter_images_));
    rebind_buffers();
}

void Renderer::rebind_buffers() {
    const ibl::Environment& env = bound_environment();
    const bool had_extras = !texels_with_extras_.empty();  // else the bound buffers are the environment's, unchanged
    texels_with_extras_.clear();
    alias_with_images_.clear();
    bool images = false;
    for (const std::optional<EmitterImage>& image : emitter_images_) images = images || image.has_value();
    if (background_face_size_ > 0 || images) {
        texels_with_extras_ = env.texels();
        texels_with_extras_.insert(texels_with_extras_.end(), blurred_texels_.begin(), blurred_texels_.end());
    }
    if (images) {
        alias_with_images_ = env.alias();
        bind_emitter_images(emitter_images_, &lights_, &texels_with_extras_, &alias_with_images_);
    }
    if (had_extras || !texels_with_extras_.empty()) ++texels_version_;
}

scene::CompileOptions Renderer::compile_options() const {
    scene::CompileOptions options;  // the scene's own options were applied to input_.scene already
    options.object_bounds = input_.settings.object_bounds;
    options.march_everything = input_.settings.march_everything;
    return options;
}

kernel::RenderKernelSettings Renderer::kernel_settings(int first_sample, int count) const {
    const RenderSettings& s = input_.settings;
    kernel::RenderKernelSettings launch_settings{};
    launch_settings.first_sample = first_sample;
    launch_settings.sample_count = count;
    launch_settings.max_depth = s.max_depth;
    launch_settings.roulette_depth = s.roulette_depth;
    launch_settings.light_sampling = light_sampling_code(s.light_sampling);
    launch_settings.normal_method = normal_code(s.normals);
    launch_settings.normal_step = s.normal_step;
    launch_settings.seed_lo = unsigned(s.seed & 0xffffffffu);
    launch_settings.seed_hi = unsigned(s.seed >> 32);
    launch_settings.max_steps = s.max_steps;
    launch_settings.max_distance = s.max_distance;
    launch_settings.over_relaxation = s.over_relaxation;
    launch_settings.lipschitz = std::max(compiled_.lipschitz, 1.0f);
    launch_settings.light_count = int(lights_.lights.size());
    launch_settings.background_opacity = s.background_opacity;
    launch_settings.background_face_size = background_face_size_;
    launch_settings.background_texels = background_face_size_ > 0 ? int(bound_environment().texels().size()) : 0;
    launch_settings.bdpt.max_vertices = bdpt_max_vertices(s);
    const StrategyDebugSettings& debug = s.strategy_debug;
    launch_settings.bdpt.strategies = debug.strategies != 0 ? debug.strategies : integrator_descriptor(s.integrator).strategies;
    launch_settings.bdpt.mis_heuristic = s.bdpt.mis_heuristic == MisHeuristic::power ? MIS_POWER : MIS_BALANCE;
    launch_settings.bdpt.single_strategy = debug.strategy_s >= 0 ? kernel::bdpt_strategy_code(debug.strategy_s, debug.strategy_t) : -1;
    launch_settings.bdpt.unweighted = debug.strategy_unweighted ? 1 : 0;
    launch_settings.bdpt.scene_center[0] = compiled_.bounds_center.x;
    launch_settings.bdpt.scene_center[1] = compiled_.bounds_center.y;
    launch_settings.bdpt.scene_center[2] = compiled_.bounds_center.z;
    launch_settings.bdpt.scene_radius = std::max(compiled_.bounds_radius, 1e-3f);
    // one sample of each strategy per camera subpath; the light-vertex cache's renderers set its
    // own counts (set_light_cache_weights) from their pilot pool
    launch_settings.bdpt.light_tracing_samples = 1.0f;
    launch_settings.bdpt.connection_samples = 1.0f;
    launch_settings.bdpt.connection_roulette = s.bdpt.connection_roulette;
    // vcm: r_0; each sample's own radius is set per sample index (render/vcm.hpp), 0 merges nothing
    launch_settings.bdpt.merge_radius0 = integrator_descriptor(s.integrator).merges ? vcm_base_radius(s, launch_settings.bdpt.scene_radius) : 0.0f;
    launch_settings.bdpt.merge_radius = 0.0f;
    launch_settings.bdpt.merge_samples = 0.0f;
    for (int i = 0; i < 3; ++i) {
        launch_settings.surface_lo[i] = compiled_.surface_lo[i];
        launch_settings.surface_hi[i] = compiled_.surface_hi[i];
    }
    return launch_settings;
}

const ibl::Environment& Renderer::bound_environment() const {
    if (input_.environment) return *input_.environment;
    static const ibl::Environment black = [] {
        ibl::EnvironmentOptions options;
        options.face_size = 1;
        return ibl::Environment::constant(brdf::float3(0.0f), "none", options);
    }();
    return black;
}

kernel::RenderScene Renderer::host_render_scene() const {
    const ibl::Environment& env = bound_environment();
    return kernel::render_scene_make(compiled_.materials.data(), brdf::bsdf_tables(), emission_.data(), lights_.lights.data(),
                                     lights_.selection_cdf.data(), lights_.light_of_slot.data(), env.map(), bound_texels().data(),
                                     bound_alias().data());
}

const std::vector<brdf::float4>& Renderer::bound_texels() const {
    return has_extras() ? texels_with_extras_ : bound_environment().texels();
}

const std::vector<kernel::AliasEntry>& Renderer::bound_alias() const {
    return alias_with_images_.empty() ? bound_environment().alias() : alias_with_images_;
}

void Renderer::rebuild_background() {
    const float blur = input_.settings.background_blur_degrees;
    blurred_texels_.clear();
    background_face_size_ = 0;
    if (blur > 0.0f && input_.environment) {
        const ibl::Environment& env = *input_.environment;
        ibl::BlurredCubemap blurred = ibl::blur_cubemap(env.texels(), env.face_size(), blur);
        blurred_texels_ = std::move(blurred.texels);
        background_face_size_ = blurred.face_size;
    }
    rebind_buffers();
}

int Renderer::add_samples(int max_samples, double budget_seconds) {
    Clock::time_point start = Clock::now();
    int added = 0;
    if (max_samples > 0 && int64_t(next_sample_) + max_samples > SampleRanges::kMaxEnd)
        throw std::invalid_argument("Renderer::add_samples: sample indices past " + std::to_string(SampleRanges::kMaxEnd));
    const int pixels = input_.settings.width * input_.settings.height;
    const bool per_pass_squares = integrator_descriptor(input_.settings.integrator).splats();
    while (added < max_samples) {
        if (pass_pixels_ == 0) pass_samples_ = std::min(max_samples - added, samples_per_launch_);
        if (per_pass_squares && pass_pixels_ == 0 && !pass_start_valid_) {
            pass_start_ = read_film();
            pass_start_valid_ = true;
        }
        int count = pixels - pass_pixels_;
        if (launch_pixels_ > 0) {
            const int tile = (launch_pixels_ + kLaunchGranularity - 1) / kLaunchGranularity * kLaunchGranularity;
            count = std::min(count, tile);
        }
        launch(kernel_settings(next_sample_, pass_samples_), PixelRange{pass_pixels_, count});
        pass_pixels_ += count;
        if (pass_pixels_ == pixels) {  // the pass is complete
            if (per_pass_squares) {
                FilmReadback now = read_film();
                add_pass_squares(pass_start_, &now, pass_samples_);
                write_film(now);
                pass_start_ = std::move(now);
            }
            next_sample_ += pass_samples_;
            added += pass_samples_;
            pass_pixels_ = 0;
        }
        if (seconds_since(start) >= budget_seconds) break;
    }
    render_seconds_ += seconds_since(start);
    return added;
}

void Renderer::reset() {
    clear_film();
    pass_pixels_ = 0;
    pass_start_valid_ = false;
    restored_ = SampleRanges();
    run_first_ = next_sample_ = first_sample_;
    render_seconds_ = 0.0;
}

void Renderer::set_first_sample(int first) {
    if (first < 0) throw std::invalid_argument("Renderer::set_first_sample: a sample index is >= 0");
    first_sample_ = first;
    reset();
}

FilmReadback Renderer::film() const {
    if (pass_pixels_ > 0) throw std::logic_error("Renderer::film: a pass is in progress (add_samples ended inside a pass)");
    return read_film();
}

SampleRanges Renderer::sample_ranges() const { return restored_.joined(SampleRanges(run_first_, next_sample_)); }

void Renderer::restore_film(const FilmReadback& film, const SampleRanges& ranges) {
    size_t pixels = size_t(input_.settings.width) * size_t(input_.settings.height);
    if (film.accumulation.size() != 4 * pixels || film.squares.size() != 4 * pixels || film.splat.size() != 3 * pixels)
        throw std::invalid_argument("Renderer::restore_film: the film's buffers do not match the image size");
    if (ranges.end() > SampleRanges::kMaxEnd) throw std::invalid_argument("Renderer::restore_film: sample indices out of range");
    write_film(film);
    pass_pixels_ = 0;
    pass_start_valid_ = false;
    restored_ = ranges;
    run_first_ = next_sample_ = int(ranges.end());
    render_seconds_ = 0.0;
}

void Renderer::resize(int width, int height) {
    RenderSettings s = input_.settings;
    s.width = width;
    s.height = height;
    check_render_settings(s);
    kernel::Camera camera = make_camera(compiled_.camera, width, height, compiled_.file);
    input_.settings = s;
    camera_ = camera;
    reset();
}

bool Renderer::set_materials(const std::vector<brdf::Material>& materials) {
    if (materials.size() != compiled_.materials.size())
        throw std::invalid_argument("Renderer::set_materials: one material per slot (" + std::to_string(compiled_.materials.size()) + ")");
    bool rebuild = brdf::used_features(materials) != brdf::used_features(compiled_.materials);
    for (size_t k = 0; k < materials.size(); ++k) input_.scene.materials[k].material = materials[k];
    if (rebuild) {
        compiled_ = scene::compile_scene(input_.scene, compile_options());
        build_kernel();
    } else {
        compiled_.materials = materials;
    }
    clamp_materials(compiled_.materials);
    emission_ = emission_table(compiled_);
    check_emissive_materials();
    upload_scene();
    reset();
    return rebuild;
}

void Renderer::set_camera(const scene::Camera& camera) {
    kernel::Camera c = make_camera(camera, input_.settings.width, input_.settings.height, compiled_.file);
    compiled_.camera = camera;
    input_.scene.camera = camera;
    camera_ = c;
    reset();
}

void Renderer::set_environment_transform(float rotation_degrees, float exposure_stops) {
    if (!input_.environment) return;
    input_.environment->set_transform(rotation_degrees, exposure_stops);
    rebuild_lights();
    upload_scene();
    reset();
}

void Renderer::set_background(float opacity, float blur_degrees) {
    RenderSettings s = input_.settings;
    s.background_opacity = opacity;
    s.background_blur_degrees = blur_degrees;
    check_render_settings(s);
    const bool blur_changed = blur_degrees != input_.settings.background_blur_degrees;
    input_.settings = s;
    if (blur_changed) {
        rebuild_background();
        upload_scene();
    }
    reset();
}

std::unique_ptr<DisplayFilter> Renderer::display_filter() const { return host_display_filter(); }

PartialPass Renderer::partial_pass() const { return PartialPass{pass_pixels_, pass_pixels_ > 0 ? pass_samples_ : 0}; }

film::ImageRgb Renderer::image() const {
    return resolve_film(read_film(), film_samples(), input_.settings.width, input_.settings.height,
                        partial_pass());
}

film::ImageRgb Renderer::variance() const {
    // Squared per pass: during a pass, the complete passes' (the pass's squares come at its end).
    if (pass_pixels_ > 0 && pass_start_valid_)
        return resolve_variance(pass_start_, film_samples(), input_.settings.width, input_.settings.height);
    return resolve_variance(read_film(), film_samples(), input_.settings.width, input_.settings.height,
                            partial_pass());
}

std::vector<float> Renderer::sample_counts() const {
    return finite_sample_counts(read_film(), film_samples(), input_.settings.width, input_.settings.height,
                                partial_pass());
}

RenderStatistics Renderer::statistics() const {
    FilmReadback film = read_film();
    RenderStatistics s;
    s.samples_per_pixel = film_samples();
    s.render_seconds = render_seconds_;
    // this run's paths: render_seconds counts this run's time only
    s.paths = uint64_t(run_samples()) * uint64_t(input_.settings.width) * uint64_t(input_.settings.height);
    if (pass_pixels_ > 0) s.paths += uint64_t(pass_pixels_) * uint64_t(pass_samples_);  // the pass in progress, so far
    read_ray_counts(&s.rays, &s.lost_rays);
    for (size_t p = 3; p < film.accumulation.size(); p += 4) s.nonfinite_samples += uint64_t(film.accumulation[p]);
    return s;
}

}  // namespace lab::render
