// A renderer on an OpenCL device: the integrator's kernel (kernels/<integrator>.cl) assembled
// around the scene's generated source, built once per set of BRDF features (PoCL caches builds),
// the scene and the film in device buffers.
#pragma once

#include "opencl/runtime.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// Where the wavefront's time goes, launch by launch (`dtoadq bench breakdown`): each kind's seconds,
// with the host waiting for every launch to end, and its number of launches.
struct WavefrontLaunchTimes {
    struct Kind {
        double seconds = 0.0;
        int launches = 0;
    };
    Kind camera_steps;    // a thin lens's camera rays, one path per work-item, left in the buffers
    Kind camera_marches;  // the camera rays' packets (a pinhole's rays begun in them)
    Kind scatter_steps;   // a step that leaves rays to march (the paths begun, surfaces scattered, light samples drawn)
    Kind marches;         // the packets of the rays and shadow rays those steps leave
    Kind last_steps;      // the step that leaves nothing to march (the last shadow rays resolved, escapes looked up)
    Kind resolves;        // several samples in flight: their paths added to the film
    double total() const {
        return camera_steps.seconds + camera_marches.seconds + scatter_steps.seconds + marches.seconds + last_steps.seconds + resolves.seconds;
    }
};

class OpenClRenderer final : public Renderer {
public:
    // Builds the kernel (opencl::KernelBuildError with the mapped log on failure) and uploads the
    // scene. Throws lab::InputError for bad settings or camera before anything is built.
    OpenClRenderer(const opencl::Runtime& runtime, RenderInput input);

    std::string device_description() const override;

    // The path tracer's wavefront (kernels/path_tracer_wavefront.h), when RenderSettings::packets
    // and the device is a CPU: its marches run eight rays per work-item on the vector lanes.
    bool wavefront() const;
    // Samples of every pixel the wavefront keeps in flight (RenderSettings::wavefront_paths); 1
    // without the wavefront.
    int samples_in_flight() const;

    // With `on`, the wavefront's launches are timed from now (the host waits for each: a little
    // slower than an untimed render), into wavefront_launch_times(), which restarts at 0.
    void time_wavefront_launches(bool on);
    const WavefrontLaunchTimes& wavefront_launch_times() const { return launch_times_; }

    // The options the integrator's program was last built with: among them the scene's kinds of
    // light (-DSCENE_LIGHT_TYPES, kernels/lights/light_selection.h).
    const std::string& build_options() const { return build_options_; }

private:
    void build_kernel() override;
    void upload_scene() override;
    void clear_film() override;
    void launch(const kernel::RenderKernelSettings& k, PixelRange pixels) override;
    FilmReadback read_film() const override;
    void write_film(const FilmReadback& film) override;
    void read_ray_counts(uint64_t* rays, uint64_t* lost) const override;

    const opencl::Runtime& runtime_;
    std::optional<opencl::Program> program_;
    std::string build_options_;
    opencl::KernelHandle kernel_;
    // The wavefront's camera and step kernels, packet kernel (kernels/march_packets.cl), resolve
    // kernel and per-path buffers:
    // k.sample_count samples in flight, one path per pixel and sample (the whole image when more
    // than one).
    void launch_wavefront_samples(const kernel::RenderKernelSettings& k, PixelRange pixels);
    cl_uint bind_render_arguments(const opencl::KernelHandle& kernel, const kernel::RenderKernelSettings& k) const;
    void launch_range(const opencl::KernelHandle& kernel, PixelRange range, size_t local, size_t total) const;
    std::optional<opencl::Program> packet_program_;
    std::string packet_source_, packet_options_;  // what packet_program_ was built from
    opencl::KernelHandle first_step_kernel_, step_kernel_, camera_kernel_, resolve_kernel_, march_rays_, march_camera_rays_;
    opencl::BufferHandle states_, path_rays_, shadow_rays_, ray_marches_, shadow_marches_, unfinished_;
    opencl::BufferHandle camera_rngs_;  // per path: the generator its camera ray left for its first step
    opencl::BufferHandle path_radiance_, path_ray_counts_, path_lost_counts_;  // per path, several samples in flight
    bool time_launches_ = false;
    WavefrontLaunchTimes launch_times_;
    int wavefront_slots_ = 0;  // samples in flight the buffers hold
    int stride_ = 0;           // entries of each ray array: the paths rounded up to a whole packet
    size_t local_size_ = 64;
    opencl::BufferHandle texels_, alias_, materials_, emission_buffer_, lights_buffer_, light_cdf_, light_of_slot_;
    opencl::BufferHandle measured_;  // brdf::measured_table_data(), or one float for a scene without measured materials
    size_t measured_floats_ = 0;
    opencl::BufferHandle accumulation_, splat_, rays_, lost_;
    size_t film_pixels_ = 0;  // the size the film buffers were made for
    const brdf::float4* uploaded_texels_ = nullptr;  // the environment texels texels_ holds
};

}  // namespace lab::render
