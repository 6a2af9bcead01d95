// The path tracer's wavefront on an OpenCL CPU device (kernels/path_tracer_wavefront.h): its step,
// camera and resolve kernels, the packet kernels that march eight rays per work-item on the vector
// lanes (kernels/march_packets.cl), the per-path buffers between the launches, and the host's loop
// of steps and marches. OpenClRenderer owns one when the integrator has a wavefront
// (IntegratorDescriptor::wavefront) and the device is a CPU.
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "opencl/runtime.hpp"
#include "render/renderer.hpp"

namespace lab::render {

// Samples of every pixel the wavefront keeps in flight: about OpenClTuning::wavefront_paths paths
// (or the default), at least one sample.
int wavefront_slots(const RenderSettings& settings);

// The kinds of launch the wavefront makes.
enum class WavefrontLaunch {
    camera_step,   // a thin lens's camera rays, one path per work-item, left in the buffers
    camera_march,  // the camera rays' packets (a pinhole's rays begun in them)
    scatter_step,  // a step that leaves rays to march (the paths begun, surfaces scattered, light samples drawn)
    march,         // the packets of the rays and shadow rays those steps leave
    last_step,     // the step that leaves nothing to march (the last shadow rays resolved, escapes looked up)
    resolve,       // several samples in flight: their paths added to the film
};

// Told of every launch once it has ended, the host waiting for each (a little slower than an
// unobserved render): the measurement of `dtoadq bench breakdown` (bench/wavefront_launch_timer.hpp).
class WavefrontLaunchObserver {
public:
    virtual ~WavefrontLaunchObserver() = default;
    virtual void launch_ended(WavefrontLaunch kind, std::chrono::steady_clock::time_point start) = 0;
};

// What the renderer that owns the scene and the film gives a launch.
struct WavefrontTarget {
    const kernel::Camera* camera;
    // Binds arguments 0 .. 15, which every render kernel takes (kernels/path_tracer.cl); returns the next index.
    std::function<cl_uint(const opencl::KernelHandle&, const kernel::RenderKernelSettings&)> bind_render_arguments;
    const opencl::BufferHandle* accumulation;
    const opencl::BufferHandle* squares;
    const opencl::BufferHandle* rays;
    const opencl::BufferHandle* lost;
    size_t local_size;  // the work-group size of the path kernels
    int image_pixels;
};

class WavefrontDriver {
public:
    explicit WavefrontDriver(const opencl::Runtime& runtime) : runtime_(runtime) {}

    // The step, camera and resolve kernels of the path tracer's `program`, and the packet kernels,
    // built from the scene's geometry with `options`: the marches see only the geometry
    // (scene/generated.h), so a change of materials, which rebuilds the step kernel, keeps them.
    void build(const opencl::Program& program, const scene::CompiledScene& compiled, const std::string& options);
    // Buffers for `slots` samples of `pixels` pixels in flight; kept while they hold that many.
    void allocate(int slots, size_t pixels);
    // Adds settings.sample_count samples to the pixels: up to slots() at a time, and only one for a part
    // of the image (the buffers hold that many paths of every pixel).
    void launch(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, PixelRange pixels);

    // Tells `observer` of every launch from now on; nullptr: of none.
    void observe_launches(WavefrontLaunchObserver* observer) { observer_ = observer; }

private:
    // Where a launch's paths and packets lie in the buffers.
    struct Ranges {
        int slots, path_count;
        PixelRange paths;           // path slot * image + pixel: with one sample, the range's pixels; with several, all of them
        int granules;               // of MARCH_RAYS_PER_ITEM paths: the buffers' packets of rays
        PixelRange packets;         // march_rays' work-items of the launch's rays
        PixelRange shadow_packets;  // and of its shadow rays, after every ray's
    };
    static Ranges ranges_of(int slots, int image_pixels, PixelRange pixels);

    void launch_samples(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, PixelRange pixels);
    cl_uint bind_step(const WavefrontTarget& target, const opencl::KernelHandle& step, const kernel::RenderKernelSettings& settings, int slots) const;
    void launch_camera_rays(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, const Ranges& r);
    void launch_steps(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, const Ranges& r);
    void launch_resolve(const WavefrontTarget& target, int slots);
    void launch_packets(const kernel::RenderKernelSettings& settings, const Ranges& r, PixelRange packets) const;
    // With an observer: waits for the launches so far (unless the host has), and tells it.
    using Clock = std::chrono::steady_clock;
    void ended(WavefrontLaunch kind, Clock::time_point start, bool wait = true);

    const opencl::Runtime& runtime_;
    opencl::KernelHandle step_kernel_, camera_kernel_, resolve_kernel_, march_rays_, march_camera_rays_;
    std::optional<opencl::Program> packet_program_;
    std::string packet_source_, packet_options_;  // what packet_program_ was built from
    opencl::BufferHandle states_, path_rays_, shadow_rays_, ray_marches_, shadow_marches_, unfinished_;
    opencl::BufferHandle camera_rngs_;  // per path: the generator its camera ray left for its first step
    opencl::BufferHandle path_radiance_, path_ray_counts_, path_lost_counts_;  // per path, several samples in flight
    int slots_ = 0;   // samples in flight the buffers hold
    int stride_ = 0;  // entries of each ray array: the paths rounded up to a whole packet
    WavefrontLaunchObserver* observer_ = nullptr;
};

}  // namespace lab::render
