// The renderer interface every integrator implements, on OpenCL (render/opencl_renderer) or on the
// host (render/host_renderer): one compiled scene, its lights and camera, an environment, and a
// film that samples are added to progressively.
//
// Edits that keep the scene's kernel -- a material whose BRDF features the kernel already has,
// the camera, the environment's rotation and exposure, the image size -- are uploads and restart
// the accumulation; a material that needs another feature rebuilds the kernel (from the warm
// PoCL cache when that kernel was built before).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "film/denoise.hpp"
#include "film/image.hpp"
#include "ibl/environment.hpp"
#include "kernels/host.hpp"
#include "render/display_filter.hpp"
#include "render/emitter_images.hpp"
#include "render/film_readback.hpp"
#include "render/film_resolve.hpp"
#include "render/light_set.hpp"
#include "render/render_settings.hpp"
#include "render/sample_ranges.hpp"
#include "scene/compile.hpp"
#include "scene/scene.hpp"

namespace lab::render {

// What a renderer is made from.
struct RenderInput {
    scene::Scene scene;                          // with its options applied (scene::apply_options)
    std::optional<ibl::Environment> environment; // none: no environment light, escaping rays see black
    RenderSettings settings;
    LightSelection light_selection = LightSelection::power;
    double scene_time = 0.0;  // seconds: the time `scene` was taken at (scene::scene_at_time), which an emitter's image is read at
};

// First-hit AOVs (kernels/first_hit.h), each pixel's mean over the film's samples: albedo
// (directional, estimated by FIRST_HIT_ALBEDO_SAMPLES BSDF samples per camera ray), world-space shading normal (the mean
// of unit normals, not renormalised, so an edge pixel shows its mix), camera-ray distance. A ray
// that escapes adds zeros, so a pixel partly on the background holds the covered fraction's share.
// Coverage is the share of the pixel's camera rays that hit a surface: the EXR's alpha with the
// backdrop's opacity (background_alpha). The material slot is not a mean: the slot the pixel's
// first sample sees (-1: none), as Cycles writes its material index from sample 0.
struct FirstHitAovs {
    film::ImageRgb albedo, normal;
    std::vector<float> depth;     // one per pixel
    std::vector<float> coverage;  // one per pixel, in [0, 1]
    std::vector<int> slot;        // one per pixel
};

struct RenderStatistics {
    int samples_per_pixel = 0;
    double render_seconds = 0.0;  // in add_samples(): launches and waiting for them
    uint64_t paths = 0, rays = 0;
    uint64_t lost_rays = 0;          // marches that ran out of steps
    uint64_t nonfinite_samples = 0;  // paths whose radiance was NaN or infinite: left out and counted
    double paths_per_second() const { return render_seconds > 0.0 ? double(paths) / render_seconds : 0.0; }
    double rays_per_second() const { return render_seconds > 0.0 ? double(rays) / render_seconds : 0.0; }
};

// Pixels [first, first + count) in row order (pixel k is (k % width, k / width)): what one launch
// covers. A range starts at a multiple of Renderer::kLaunchGranularity and spans a multiple of it
// unless it ends the image, so an OpenCL launch of whole work-groups covers it exactly.
struct PixelRange {
    int first = 0, count = 0;
};

class Renderer {
public:
    virtual ~Renderer() = default;
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    virtual std::string device_description() const = 0;
    const RenderSettings& settings() const { return input_.settings; }
    const scene::CompiledScene& compiled_scene() const { return compiled_; }
    double build_seconds() const { return build_seconds_; }
    LightSelection light_selection() const { return input_.light_selection; }

    // Adds samples per pixel, in launches of samples_per_launch(), until `max_samples` were added or
    // `budget_seconds` have passed; returns how many were added (at least one launch when
    // max_samples > 0). A launch is not cut short, so a call overruns its budget by at most one
    // launch: callers that need a frame-time budget keep launches small (set_samples_per_launch).
    //
    // With set_launch_pixels(n), a pass of samples_per_launch() samples over the image is split into
    // launches of about n pixels each (rounded up to kLaunchGranularity), so that a caller waits at
    // most one such launch. A call may then end in the middle of a pass; the next call continues
    // it (with the pass's sample count). Only complete passes count as added, in sample_ranges()
    // and in statistics().samples_per_pixel; image() resolves the pass in progress per pixel (the
    // pixels it has reached hold its samples, the others not yet). Any integrator: every pixel's
    // work-item is keyed by its pixel and sample index, whatever launch it runs in, so the split
    // changes no pixel's samples.
    int add_samples(int max_samples, double budget_seconds = std::numeric_limits<double>::infinity());
    int samples_per_launch() const { return samples_per_launch_; }
    void set_samples_per_launch(int n) { samples_per_launch_ = n < 1 ? 1 : n; }
    static constexpr int kLaunchGranularity = 64;  // the largest OpenCL work-group the renderers use
    // Pixels per launch at most; 0 (the default): a launch covers the whole image.
    void set_launch_pixels(int pixels) { launch_pixels_ = pixels < 0 ? 0 : pixels; }
    int launch_pixels() const { return launch_pixels_; }
    // Pixels of the pass in progress done so far (the first ones in row order); 0: none in progress.
    int pass_pixels() const { return pass_pixels_; }

    // Drops every sample so far.
    void reset();
    // Renders from sample index `first` on (--samples A:B renders indices A to B-1); resets.
    void set_first_sample(int first);
    // Samples per pixel of the complete passes on the film (statistics() without reading the film back).
    int samples_per_pixel() const { return film_samples(); }
    // The sample indices the film holds.
    SampleRanges sample_ranges() const;
    // The film's buffers as they are now (render/film_file.hpp writes them beside the image). Not
    // during a pass in progress (std::logic_error): its samples are on part of the film only, which
    // sample_ranges() cannot say.
    FilmReadback film() const;
    // Continues a render from its film (--resume): the film's buffers, of this renderer's size, and
    // the sample indices they hold; the next sample is the one after the last of them. Own-pixel
    // accumulation continues in sample order, so the result is bit-identical to one run.
    void restore_film(const FilmReadback& film, const SampleRanges& ranges);
    // A new image size (check_render_settings' limits); resets.
    void resize(int width, int height);
    // New materials for the scene's slots (one per slot, in slot order); resets. Rebuilds the
    // kernel when their BRDF features differ from the kernel's; returns whether it did.
    bool set_materials(const std::vector<brdf::Material>& materials);
    // A new camera; resets. Throws lab::InputError as make_camera does.
    void set_camera(const scene::Camera& camera);
    // The environment turned and scaled anew (absolute values, as ibl::EnvironmentOptions); resets.
    // The light selection follows the environment's new power.
    void set_environment_transform(float rotation_degrees, float exposure_stops);
    // What camera rays that escape see of the environment (kernels/background.h): its opacity in
    // [0, 1] and its blur in degrees (0: sharp; else ibl::blur_cubemap, built here when the angle
    // changes); the lighting stays the environment's. Resets. Throws lab::InputError as
    // check_render_settings does.
    void set_background(float opacity, float blur_degrees);

    // The mean so far (all zeros before the first sample): each pixel's own finite samples, plus
    // what was splatted onto it, over the samples per pixel. A pixel none of whose samples was
    // finite is NaN, so it shows (magenta in a PNG).
    film::ImageRgb image() const;
    // Per pixel, as image() counts them (a pass in progress on the pixels it reached): the variance
    // of its mean (resolve_variance) and how many finite samples the mean is over.
    film::ImageRgb variance() const;
    std::vector<float> sample_counts() const;
    RenderStatistics statistics() const;
    // The first-hit AOVs over the film's sample indices (sample_ranges()): the first hit is the
    // same for every integrator. Here on the host's threads with the kernels' C++ build
    // (render/first_hit_aovs.cpp); OpenClRenderer runs the same code as a kernel of its own. Not
    // during a pass in progress (std::logic_error).
    FirstHitAovs first_hit_aovs() const;
    // The same over other sample indices (the viewer's views take a few, not every sample so far);
    // any time, since it reads nothing of the film.
    FirstHitAovs first_hit_aovs(const SampleRanges& ranges) const;
    // The same, given up (nullopt) as soon as `cancelled` says so: it is asked between pieces of
    // about kFirstHitPiece pixels (a thread that renders and must answer a change soon waits at
    // most one piece); empty: never asked, and the image is one launch.
    virtual std::optional<FirstHitAovs> first_hit_aovs(const SampleRanges& ranges, const std::function<bool()>& cancelled) const;
    static constexpr int kFirstHitPiece = 4096;
    // The display denoiser's passes (film/denoise.hpp) on the device this renderer runs on, apart
    // from it (render/display_filter.hpp): on the host here; OpenClRenderer's in a context of its
    // own, so a thread may filter while this one renders.
    virtual std::unique_ptr<DisplayFilter> display_filter() const;
    // What a launch of `count` samples from `first_sample` is given; public for host-side tools that
    // trace the same rays (the viewer's pixel inspector).
    kernel::RenderKernelSettings kernel_settings(int first_sample, int count) const;

protected:
    explicit Renderer(RenderInput input);
    // Derived constructors call this last: builds the kernel, uploads the scene, allocates the film.
    void initialize();

    // The scene's kernel source (scene/generated.h) changed, or there is none yet.
    virtual void build_kernel() = 0;
    // Materials, emission, lights and the environment's buffers changed.
    virtual void upload_scene() = 0;
    // A zeroed film (and ray counters) of the current size.
    virtual void clear_film() = 0;
    // Adds launch_settings.sample_count samples to every pixel of the range, the first keyed by its first_sample; blocks.
    virtual void launch(const kernel::RenderKernelSettings& launch_settings, PixelRange pixels) = 0;
    virtual FilmReadback read_film() const = 0;
    // Replaces the film's buffers (restore_film has checked their sizes).
    virtual void write_film(const FilmReadback& film) = 0;
    virtual void read_ray_counts(uint64_t* rays, uint64_t* lost) const = 0;

    scene::CompileOptions compile_options() const;
    // The environment the kernels bind: the input's, or a black one when there is none (the kernels
    // take its map and buffers either way; without an environment light nothing reads them).
    const ibl::Environment& bound_environment() const;
    // The AOVs from each pixel's sums over `samples` samples: albedo in xyz, coverage in w; normal in xyz, depth in w.
    FirstHitAovs first_hit_means(const std::vector<brdf::float4>& albedo_sums, const std::vector<brdf::float4>& normal_depth_sums,
                                 std::vector<int> slots, int64_t samples) const;
    // The scene as the kernels' host build reads it (kernels/render_scene.h), over this renderer's buffers.
    kernel::RenderScene host_render_scene() const;
    // The texels the kernels bind: the environment's, followed by the blurred backdrop's when there
    // is a blur (kernels/background.h), and the images emitters show (render/emitter_images.hpp);
    // texels_version() changes whenever they do. bound_alias(): the environment's alias tables, and
    // the images' after them.
    const std::vector<brdf::float4>& bound_texels() const;
    const std::vector<kernel::AliasEntry>& bound_alias() const;
    uint64_t texels_version() const { return texels_version_; }

    RenderInput input_;
    scene::CompiledScene compiled_;
    kernel::Camera camera_{};
    LightSet lights_;
    std::vector<brdf::float4> emission_;  // per slot: radiance, and EMISSION_* (kernels/render_scene.h)
    double build_seconds_ = 0.0;

private:
    void rebuild_lights();
    // Throws lab::InputError when the integrator cannot render the scene's lights and emissive
    // materials (check_integrator_lights; the light tracer never sees a material's emission).
    void check_emissive_materials() const;
    // The blurred backdrop for input_.settings.background_blur_degrees (none at 0 or without an environment).
    void rebuild_background();
    // The buffers bound_texels() and bound_alias() return, and the image emitters' lights' offsets
    // into them (bind_emitter_images), after the lights or the backdrop changed.
    void rebind_buffers();

    std::vector<std::optional<EmitterImage>> emitter_images_;  // per emitter of the scene
    std::vector<brdf::float4> blurred_texels_;           // the blurred backdrop's (none: empty)
    std::vector<brdf::float4> texels_with_extras_;       // the environment's texels, the blurred map's, the images'
    std::vector<kernel::AliasEntry> alias_with_images_;  // the environment's tables, then the images'
    bool has_extras() const { return background_face_size_ > 0 || !alias_with_images_.empty(); }
    int background_face_size_ = 0;                       // the blurred map's face; 0: none
    uint64_t texels_version_ = 0;

    // The pass in progress, as the film's resolves take it.
    PartialPass partial_pass() const;

    int first_sample_ = 0;    // where a reset film starts
    SampleRanges restored_;   // the samples restore_film put on the film
    int run_first_ = 0;       // the first sample of this run (after the restored ones)
    int next_sample_ = 0;     // the index of the next sample to add
    // Samples per pixel added since the last reset or restore, and on the film in all.
    int run_samples() const { return next_sample_ - run_first_; }
    int film_samples() const { return int(restored_.count()) + run_samples(); }
    int samples_per_launch_ = 1;
    int launch_pixels_ = 0;  // 0: whole image
    // An integrator that splats squares its film per pass (add_pass_squares): the film as the pass
    // in progress found it, read at its start (or, after a complete pass, kept from its end).
    FilmReadback pass_start_;
    bool pass_start_valid_ = false;
    int pass_pixels_ = 0;    // the pass in progress has reached pixels [0, pass_pixels_)
    int pass_samples_ = 0;   // and adds samples next_sample_ .. next_sample_ + pass_samples_ - 1 to them
    double render_seconds_ = 0.0;
};

// The emission table of kernels/render_scene.h: per slot, its radiance and whether it emits,
// and whether an emitter's material scatters too.
std::vector<brdf::float4> emission_table(const scene::CompiledScene& scene);

}  // namespace lab::render
