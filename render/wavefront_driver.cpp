#include "render/wavefront_driver.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "render/host_renderer.hpp"
#include "render/opencl_launch.hpp"
#include "kernels/host/scene_kernel_source.hpp"

namespace lab::render {

namespace {

// Paths the wavefront keeps in flight unless OpenClTuning::wavefront_paths says otherwise: a
// step and a march of a launch cost some fifty microseconds of launching and waiting whatever their
// size, and at 128 x 128 one sample of a simple scene takes only a few milliseconds.
constexpr int kWavefrontPaths = 1 << 16;

// A packet work-item marches MARCH_RAYS_PER_ITEM rays, one granule of the paths.
static_assert(MARCH_RAYS_PER_ITEM == Renderer::kLaunchGranularity, "a packet work-item marches one granule");
constexpr size_t kPacketLocal = 1;

}  // namespace

int wavefront_slots(const RenderSettings& s) {
    const int64_t pixels = int64_t(s.width) * s.height;
    const int64_t paths = s.opencl.wavefront_paths > 0 ? s.opencl.wavefront_paths : kWavefrontPaths;
    return int(std::max<int64_t>(1, paths / pixels));
}

void WavefrontDriver::build(const opencl::Program& program, const scene::CompiledScene& compiled, const std::string& options) {
    step_kernel_ = program.kernel("render_pt_step");
    camera_kernel_ = program.kernel("render_pt_camera");
    resolve_kernel_ = program.kernel("render_pt_resolve");
    opencl::AssembledSource packets = kernels::assemble_scene_kernel("kernels/march_packets.cl", compiled);
    std::string packet_options = options + " -DSDF_LANES=8";
    if (!packet_program_ || packets.text != packet_source_ || packet_options != packet_options_) {
        packet_program_.emplace(runtime_.build(packets, packet_options));
        march_rays_ = packet_program_->kernel("march_rays");
        march_camera_rays_ = packet_program_->kernel("march_camera_rays");
        packet_source_ = std::move(packets.text);
        packet_options_ = std::move(packet_options);
    }
}

void WavefrontDriver::allocate(int slots, size_t pixels) {
    if (slots == slots_ && size_t(stride_) >= size_t(slots) * pixels) return;
    slots_ = slots;
    const size_t paths = size_t(slots) * pixels;
    stride_ = int((paths + 7) / 8 * 8);
    const size_t n = size_t(stride_);
    states_ = runtime_.buffer(n * path_state_bytes(), CL_MEM_READ_WRITE);
    // the padding past the image holds no ray (kernels/ray_march.h), so that its lanes idle
    std::vector<float> no_rays(n * RAY_FIELDS, NO_RAY);
    path_rays_ = runtime_.buffer(no_rays.size() * sizeof(float), CL_MEM_READ_WRITE);
    shadow_rays_ = runtime_.buffer(no_rays.size() * sizeof(float), CL_MEM_READ_WRITE);
    runtime_.write(path_rays_, no_rays.data(), no_rays.size() * sizeof(float));
    runtime_.write(shadow_rays_, no_rays.data(), no_rays.size() * sizeof(float));
    ray_marches_ = runtime_.buffer(n * sizeof(kernel::RayMarch), CL_MEM_READ_WRITE);
    shadow_marches_ = runtime_.buffer(n * sizeof(kernel::RayMarch), CL_MEM_READ_WRITE);
    camera_rngs_ = runtime_.buffer(n * 4 * sizeof(cl_uint), CL_MEM_READ_WRITE);
    unfinished_ = runtime_.buffer(2 * sizeof(cl_uint), CL_MEM_READ_WRITE);
    path_radiance_ = runtime_.buffer(n * 4 * sizeof(float), CL_MEM_READ_WRITE);
    path_ray_counts_ = runtime_.buffer(n * sizeof(cl_uint), CL_MEM_READ_WRITE);
    path_lost_counts_ = runtime_.buffer(n * sizeof(cl_uint), CL_MEM_READ_WRITE);
}

void WavefrontDriver::launch(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, PixelRange pixels) {
    const bool whole = pixels.first == 0 && pixels.count == target.image_pixels;
    kernel::RenderKernelSettings batch = settings;
    for (int i = 0; i < settings.sample_count; i += batch.sample_count) {
        batch.first_sample = settings.first_sample + i;
        batch.sample_count = whole ? std::min(slots_, settings.sample_count - i) : 1;
        launch_samples(target, batch, pixels);
    }
}

WavefrontDriver::Ranges WavefrontDriver::ranges_of(int slots, int image_pixels, PixelRange pixels) {
    Ranges r;
    r.slots = slots;
    r.path_count = slots * image_pixels;
    r.paths = slots == 1 ? pixels : PixelRange{0, r.path_count};
    r.granules = (r.path_count + MARCH_RAYS_PER_ITEM - 1) / MARCH_RAYS_PER_ITEM;
    r.packets = PixelRange{r.paths.first / MARCH_RAYS_PER_ITEM, (r.paths.count + MARCH_RAYS_PER_ITEM - 1) / MARCH_RAYS_PER_ITEM};
    r.shadow_packets = PixelRange{r.granules + r.packets.first, r.packets.count};
    return r;
}

// kernels/path_tracer_wavefront.h's loop: the camera rays, then steps and the packets of their rays
// and shadow rays until no path has anything left to march; then, with several samples in flight,
// the resolve that adds them to the film in sample order.
void WavefrontDriver::launch_samples(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, PixelRange pixels) {
    const Ranges r = ranges_of(settings.sample_count, target.image_pixels, pixels);
    launch_camera_rays(target, settings, r);
    launch_steps(target, settings, r);
    if (r.slots > 1) launch_resolve(target, r.slots);
}

// the step kernels' arguments (kernels/path_tracer.cl, WAVEFRONT_KERNEL_ARGUMENTS); returns the
// index of the next argument (render_pt_step's `first`)
cl_uint WavefrontDriver::bind_step(const WavefrontTarget& target, const opencl::KernelHandle& step, const kernel::RenderKernelSettings& settings,
                                int slots) const {
    cl_uint a = target.bind_render_arguments(step, settings);
    opencl::set_kernel_arg(step, a++, stride_);
    for (const opencl::BufferHandle* b : {&states_, &path_rays_, &shadow_rays_, &ray_marches_, &shadow_marches_, &unfinished_})
        opencl::set_kernel_arg(step, a++, *b);
    opencl::set_kernel_arg(step, a++, slots);
    for (const opencl::BufferHandle* b : {&path_radiance_, &path_ray_counts_, &path_lost_counts_, &camera_rngs_})
        opencl::set_kernel_arg(step, a++, *b);
    return a;
}

// march_rays' work-items `packets` of the rays' granules, then the shadow rays'.
void WavefrontDriver::launch_packets(const kernel::RenderKernelSettings& settings, const Ranges& r, PixelRange packets) const {
    opencl::set_kernel_args(march_rays_, settings, r.path_count, stride_, path_rays_, ray_marches_, shadow_rays_, shadow_marches_);
    launch_range(runtime_, march_rays_, packets, kPacketLocal, 2 * size_t(r.granules));
}

void WavefrontDriver::ended(WavefrontLaunch kind, Clock::time_point start, bool wait) {
    if (observer_ == nullptr) return;
    if (wait) runtime_.finish();
    observer_->launch_ended(kind, start);
}

// Iteration 0, the camera rays: a pinhole's are begun on the packets' lanes and marched in one
// launch (march_camera_rays); a thin lens's by the camera step, one path per work-item, then
// marched. Every path has one, so the host need not ask.
void WavefrontDriver::launch_camera_rays(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, const Ranges& r) {
    const Clock::time_point camera_start = Clock::now();
    if (target.camera->lens_radius > 0.0f) {
        bind_step(target, camera_kernel_, settings, r.slots);
        launch_range(runtime_, camera_kernel_, r.paths, target.local_size, size_t(r.path_count));
        ended(WavefrontLaunch::camera_step, camera_start);
        const Clock::time_point march_start = Clock::now();
        launch_packets(settings, r, r.packets);
        ended(WavefrontLaunch::camera_march, march_start);
    } else {
        opencl::set_kernel_args(march_camera_rays_, settings, *target.camera, r.path_count, stride_, path_rays_, camera_rngs_, ray_marches_);
        launch_range(runtime_, march_camera_rays_, r.packets, kPacketLocal, size_t(r.granules));
        ended(WavefrontLaunch::camera_march, camera_start);
    }
}

// Per step the host waits once, for the step's two flags (a ray left, a shadow ray left), and
// launches one march of what is left.
void WavefrontDriver::launch_steps(const WavefrontTarget& target, const kernel::RenderKernelSettings& settings, const Ranges& r) {
    for (int iteration = 1;; ++iteration) {
        const Clock::time_point step_start = Clock::now();
        // max_depth scattering events, and the last shadow ray one step later
        if (iteration > settings.max_depth + 3) throw std::logic_error("path tracer wavefront: paths still unfinished after max_depth + 3 steps");
        runtime_.zero(unfinished_, 2 * sizeof(cl_uint));
        const cl_uint first_argument = bind_step(target, step_kernel_, settings, r.slots);
        opencl::set_kernel_arg(step_kernel_, first_argument, cl_int(iteration == 1));
        launch_range(runtime_, step_kernel_, r.paths, target.local_size, size_t(r.path_count));
        cl_uint unfinished[2] = {0, 0};
        runtime_.read(unfinished_, unfinished, sizeof(unfinished));  // blocking: the step is done
        const bool last = unfinished[0] == 0 && unfinished[1] == 0;
        ended(last ? WavefrontLaunch::last_step : WavefrontLaunch::scatter_step, step_start, false);
        if (last) break;
        const Clock::time_point march_start = Clock::now();
        if (unfinished[0] != 0 && unfinished[1] != 0 && r.packets.count == r.granules)
            launch_packets(settings, r, PixelRange{0, 2 * r.granules});  // both, in one launch
        else {
            if (unfinished[0] != 0) launch_packets(settings, r, r.packets);
            if (unfinished[1] != 0) launch_packets(settings, r, r.shadow_packets);
        }
        ended(WavefrontLaunch::march, march_start);
    }
}

void WavefrontDriver::launch_resolve(const WavefrontTarget& target, int slots) {
    const Clock::time_point resolve_start = Clock::now();
    const int image = target.image_pixels;
    opencl::set_kernel_args(resolve_kernel_, image, slots, *target.accumulation, *target.squares, *target.rays, *target.lost, path_radiance_, path_ray_counts_,
                            path_lost_counts_);
    runtime_.launch_1d(resolve_kernel_, size_t(image), target.local_size);
    ended(WavefrontLaunch::resolve, resolve_start);
}

}  // namespace lab::render
